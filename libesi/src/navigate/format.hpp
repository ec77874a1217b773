#pragma once
// How hovers, completions and the outline spell indices and names: as the document does (ESI
// "#x1600", YAML "0x1600").

#include <cstdint>
#include <string>
#include <string_view>

#include "navigate/index.hpp"

namespace esi::navigate {

[[nodiscard]] std::string format_index(std::uint32_t index, bool yaml);
[[nodiscard]] std::string format_subindex(std::uint32_t subindex, bool yaml);
[[nodiscard]] std::string format_coe_code(std::uint16_t code);
// "1 bit", "16 bits"; empty stays empty.
[[nodiscard]] std::string bits_text(std::string_view bit_size);
// `text` as Markdown inline code; empty stays empty.
[[nodiscard]] std::string code(std::string_view text);
// "device EL1008" / "module …": how a hover names the scope.
[[nodiscard]] std::string scope_title(const Scope& scope);

}  // namespace esi::navigate
