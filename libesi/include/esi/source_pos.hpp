#pragma once
// Where a model element came from. The file path lives once on the document (or the
// diagnostic); elements only carry line and column, both 1-based, 0 meaning unknown.

#include <compare>
#include <cstdint>

namespace esi {

struct SourcePos {
    std::uint32_t line = 0;
    std::uint32_t column = 0;

    [[nodiscard]] constexpr bool known() const { return line != 0; }
    friend constexpr auto operator<=>(const SourcePos&, const SourcePos&) = default;
};

}  // namespace esi
