#pragma once
// Counts in messages and pages: "1 byte", "2 bytes", "0 bytes". Every text that puts a number
// before a noun goes through here (or a view field made by it), so that no template says
// "1 bytes"; tests/unit/wording_test.cpp scans the message templates for the pattern.

#include <cstdint>
#include <string>
#include <string_view>

namespace esi {

// "<n> <singular>" for n == 1, else "<n> <plural>"; `plural` defaults to singular + "s".
[[nodiscard]] std::string counted(std::uint64_t n, std::string_view singular, std::string_view plural = {});

}  // namespace esi
