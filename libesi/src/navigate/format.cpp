#include "navigate/format.hpp"

#include "esi/number.hpp"

namespace esi::navigate {

std::string format_index(std::uint32_t index, bool yaml) {
    std::string hex = format_hex(index, 4);  // "#x1600"
    if (yaml) hex.replace(0, 2, "0x");
    return hex;
}

std::string format_subindex(std::uint32_t subindex, bool yaml) {
    std::string hex = format_hex(subindex, 2);
    if (yaml) return std::to_string(subindex);
    return hex.substr(2);
}

std::string format_coe_code(std::uint16_t code) {
    std::string hex = format_hex(code, 4);
    return hex.replace(0, 2, "0x");
}

std::string bits_text(std::string_view bit_size) {
    if (bit_size.empty()) return {};
    return std::string(bit_size) + (bit_size == "1" ? " bit" : " bits");
}

std::string code(std::string_view text) {
    if (text.empty()) return {};
    // A backtick inside the value needs a longer fence (CommonMark code spans).
    const bool has_tick = text.find('`') != std::string_view::npos;
    const std::string fence = has_tick ? "`` " : "`";
    const std::string close = has_tick ? " ``" : "`";
    return fence + std::string(text) + close;
}

std::string scope_title(const Scope& scope) {
    std::string title = scope.module ? "module " : "device ";
    title += scope.type.empty() ? scope.name : scope.type;
    return title;
}

}  // namespace esi::navigate
