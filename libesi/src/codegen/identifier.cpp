#include "esi/codegen/identifier.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <iterator>

namespace esi::codegen {

namespace {

// C99 and C++17 keywords plus the alternative operator spellings and the C99 macros that act
// like keywords (bool, true, false): none of them can name a variable in both languages.
constexpr std::string_view keywords[] = {
    "alignas", "alignof", "and", "and_eq", "asm", "auto", "bitand", "bitor", "bool", "break", "case", "catch",
    "char", "char16_t", "char32_t", "char8_t", "class", "compl", "concept", "const", "const_cast", "consteval",
    "constexpr", "constinit", "continue", "co_await", "co_return", "co_yield", "decltype", "default", "delete",
    "do", "double", "dynamic_cast", "else", "enum", "explicit", "export", "extern", "false", "float", "for",
    "friend", "goto", "if", "inline", "int", "long", "mutable", "namespace", "new", "noexcept", "not",
    "not_eq", "nullptr", "operator", "or", "or_eq", "private", "protected", "public", "register",
    "reinterpret_cast", "requires", "restrict", "return", "short", "signed", "sizeof", "static",
    "static_assert", "static_cast", "struct", "switch", "template", "this", "thread_local", "throw", "true",
    "try", "typedef", "typeid", "typename", "union", "unsigned", "using", "virtual", "void", "volatile",
    "wchar_t", "while", "xor", "xor_eq",
    // Not keywords, but macros or functions of the C library a variable must not shadow.
    "main", "errno", "assert", "offsetof", "stdin", "stdout", "stderr",
};

// UTF-8 letters common in German vendor texts, transliterated the way a German reader would.
struct Transliteration {
    std::string_view utf8;
    std::string_view ascii;
};
constexpr std::array<Transliteration, 7> transliterations = {{
    {"\xC3\xA4", "ae"}, {"\xC3\xB6", "oe"}, {"\xC3\xBC", "ue"}, {"\xC3\x84", "ae"},
    {"\xC3\x96", "oe"}, {"\xC3\x9C", "ue"}, {"\xC3\x9F", "ss"},
}};

std::string snake(std::string_view name) {
    std::string out;
    out.reserve(name.size());
    bool pending_separator = false;
    for (std::size_t i = 0; i < name.size();) {
        const auto c = static_cast<unsigned char>(name[i]);
        std::string_view piece;
        std::size_t advance = 1;
        char single = 0;
        if (std::isalnum(c) && c < 0x80) {
            single = static_cast<char>(std::tolower(c));
        } else {
            for (const auto& t : transliterations)
                if (name.substr(i, t.utf8.size()) == t.utf8) {
                    piece = t.ascii;
                    advance = t.utf8.size();
                    break;
                }
        }
        if (single != 0 || !piece.empty()) {
            if (pending_separator && !out.empty()) out += '_';
            pending_separator = false;
            if (single != 0) out += single;
            else out += piece;
        } else {
            pending_separator = true;
        }
        i += advance;
    }
    return out;
}

}  // namespace

bool is_c_or_cpp_keyword(std::string_view word) {
    return std::find(std::begin(keywords), std::end(keywords), word) != std::end(keywords);
}

std::string c_identifier(std::string_view name, std::string_view fallback) {
    std::string id = snake(name);
    if (id.empty()) id = snake(fallback);
    if (id.empty()) id = "unnamed";
    if (std::isdigit(static_cast<unsigned char>(id.front()))) id = "n_" + id;
    if (is_c_or_cpp_keyword(id)) id += '_';
    return id;
}

std::string c_macro_name(std::string_view name, std::string_view fallback) {
    std::string id = c_identifier(name, fallback);
    if (id.back() == '_') id.pop_back();  // keywords do not matter in upper case
    std::transform(id.begin(), id.end(), id.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    return id;
}

std::string IdentifierScope::claim(const std::string& wanted, std::string_view disambiguator) {
    if (used_.insert(wanted).second) return wanted;
    if (!disambiguator.empty()) {
        std::string candidate = wanted + "_" + std::string(disambiguator);
        if (used_.insert(candidate).second) return candidate;
    }
    for (unsigned n = 2;; ++n) {
        std::string candidate = wanted + "_" + std::to_string(n);
        if (used_.insert(candidate).second) return candidate;
    }
}

std::string c_string_literal(std::string_view text) {
    std::string out;
    out.reserve(text.size() + 2);
    out += '"';
    for (const char ch : text) {
        const auto c = static_cast<unsigned char>(ch);
        if (c == '\\' || c == '"' || c == '?') {
            out += '\\';
            out += ch;
        } else if (c >= 0x20 && c < 0x7F) {
            out += ch;
        } else {
            out += '\\';
            out += static_cast<char>('0' + ((c >> 6) & 7));
            out += static_cast<char>('0' + ((c >> 3) & 7));
            out += static_cast<char>('0' + (c & 7));
        }
    }
    out += '"';
    return out;
}

std::string c_comment_text(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (const char ch : text) {
        const char c = (ch == '\n' || ch == '\r' || ch == '\t') ? ' ' : ch;
        // "*/" would end the comment, "??" could start a trigraph, "/*" nests badly with -Wcomment.
        if (!out.empty() && ((out.back() == '*' && c == '/') || (out.back() == '?' && c == '?') ||
                             (out.back() == '/' && c == '*')))
            out += ' ';
        out += c;
    }
    return out;
}

}  // namespace esi::codegen
