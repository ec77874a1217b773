#pragma once
// C identifiers from EtherCAT names ("Modes of operation" -> modes_of_operation). Generated code
// names objects, sub-entries and process-image members after what the ESI calls them, so the
// identifiers must be valid in C99 and C++17, unique within their scope and the same on every run.

#include <string>
#include <string_view>
#include <unordered_set>

namespace esi::codegen {

// Lower-case snake_case: letters and digits kept (German umlauts and ß transliterated), every
// other run of characters becomes one '_', no leading/trailing '_'. A result that is empty
// becomes `fallback`; one that starts with a digit gets an "n_" prefix; a C/C++ keyword gets a
// trailing '_'. The result never starts with '_' nor contains "__" (both reserved in C).
[[nodiscard]] std::string c_identifier(std::string_view name, std::string_view fallback = "unnamed");

// The same, in upper case (for macros).
[[nodiscard]] std::string c_macro_name(std::string_view name, std::string_view fallback = "UNNAMED");

[[nodiscard]] bool is_c_or_cpp_keyword(std::string_view word);

// Hands out identifiers unique within one scope (the objects of a device, the sub-entries of
// an object, the members of a process image). Callers visit names in a fixed order, so the
// result is deterministic.
class IdentifierScope {
public:
    // `wanted` if still free; else `wanted` + "_" + `disambiguator` (e.g. the object index) if
    // that is free; else the first free `wanted_2`, `wanted_3`, ...
    [[nodiscard]] std::string claim(const std::string& wanted, std::string_view disambiguator = {});
    [[nodiscard]] bool taken(const std::string& name) const { return used_.count(name) != 0; }
    // Marks a name as used without handing it out (names the templates use themselves).
    void reserve(const std::string& name) { used_.insert(name); }

private:
    std::unordered_set<std::string> used_;
};

// Text for a C/C++ string literal, quotes included: '\\', '"' and '?' (trigraphs) escaped,
// everything outside printable ASCII as a three-digit octal escape (never ambiguous with a
// following digit, unlike \x).
[[nodiscard]] std::string c_string_literal(std::string_view text);

// Text safe inside a /* */ comment: one line, no "*/", no trigraph-forming "??".
[[nodiscard]] std::string c_comment_text(std::string_view text);

}  // namespace esi::codegen
