#pragma once
// What the navigation tests share: positions of a needle in a text, found by byte offset.

#include <gtest/gtest.h>

#include <cstddef>
#include <string>
#include <string_view>

#include "esi/navigate/navigate.hpp"

namespace esi::navigate::test {

// Byte offset of the nth (0-based) occurrence of `needle`; fails the test when absent.
inline std::size_t offset_of(std::string_view text, std::string_view needle, int nth = 0) {
    std::size_t at = text.find(needle);
    for (int i = 0; i < nth && at != std::string_view::npos; ++i) at = text.find(needle, at + 1);
    EXPECT_NE(at, std::string_view::npos) << "no occurrence " << nth << " of " << needle;
    return at == std::string_view::npos ? 0 : at;
}

// LSP position of the nth occurrence of `needle`, plus `skip` bytes into it.
inline Position at(std::string_view text, std::string_view needle, int nth = 0, std::size_t skip = 0) {
    return LineMap(text).position_of(offset_of(text, needle, nth) + skip);
}

// The range of the nth occurrence of `needle` itself.
inline Range range_of(std::string_view text, std::string_view needle, int nth = 0) {
    const std::size_t begin = offset_of(text, needle, nth);
    return LineMap(text).range_of(begin, begin + needle.size());
}

// The range of `token` inside the nth occurrence of `context` (which holds it).
inline Range token_range(std::string_view text, std::string_view context, std::string_view token, int nth = 0) {
    const std::size_t begin = offset_of(text, context, nth) + context.find(token);
    return LineMap(text).range_of(begin, begin + token.size());
}

}  // namespace esi::navigate::test
