#pragma once
// Mailbox error details (ETG.1000.6 Table 30): the answer of type 0 to a request the mailbox
// cannot serve.

#include <cstdint>

namespace esi::sim::mailbox_error {

inline constexpr std::uint16_t syntax = 0x0001;
inline constexpr std::uint16_t unsupported_protocol = 0x0002;
inline constexpr std::uint16_t invalid_channel = 0x0003;
inline constexpr std::uint16_t service_not_supported = 0x0004;
inline constexpr std::uint16_t invalid_header = 0x0005;
inline constexpr std::uint16_t size_too_short = 0x0006;
inline constexpr std::uint16_t no_more_memory = 0x0007;
inline constexpr std::uint16_t invalid_size = 0x0008;

}  // namespace esi::sim::mailbox_error
