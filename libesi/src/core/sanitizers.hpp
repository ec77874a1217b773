#pragma once
// Whether this translation unit is compiled with a sanitizer, as 0 or 1 for #if: GCC defines
// __SANITIZE_ADDRESS__, clang answers __has_feature.
//   ESI_ADDRESS_SANITIZER  AddressSanitizer
//   ESI_SANITIZER          AddressSanitizer, MemorySanitizer or ThreadSanitizer: what must see
//                          every allocation (the tools' own heaps and mappings step aside)

#if defined(__SANITIZE_ADDRESS__)
#define ESI_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define ESI_ADDRESS_SANITIZER 1
#endif
#endif
#ifndef ESI_ADDRESS_SANITIZER
#define ESI_ADDRESS_SANITIZER 0
#endif

#if ESI_ADDRESS_SANITIZER
#define ESI_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(memory_sanitizer) || __has_feature(thread_sanitizer)
#define ESI_SANITIZER 1
#endif
#endif
#ifndef ESI_SANITIZER
#define ESI_SANITIZER 0
#endif
