#pragma once
// The test oracle of esi-gen's Mustache engine: how esi-gen rendered templates before it had its
// own engine, with the kainjow mustache library (Debian libkainjow-mustache-dev). The view's JSON
// becomes kainjow data (numbers as their decimal text, null as false), lines that hold nothing
// but a section, inverted-section, end or comment tag are removed before kainjow parses the
// template (the spec's standalone rule, which kainjow applies only to sections that render), and
// {{name}} is not HTML-escaped unless asked.
//
// The differential tests render the same template over the same view with both and compare the
// bytes. The stripping here knows the default delimiters only, as the old renderer did.

#include <kainjow/mustache.hpp>

#include <string>
#include <string_view>
#include <utility>

#include <nlohmann/json.hpp>

namespace esi::test::codegen {

namespace kainjow_oracle_detail {

namespace mu = kainjow::mustache;
using Json = nlohmann::ordered_json;

inline mu::data convert(const Json& value) {
    switch (value.type()) {
        case Json::value_t::object: {
            mu::data out(mu::data::type::object);
            for (const auto& [key, child] : value.items()) out[key] = convert(child);
            return out;
        }
        case Json::value_t::array: {
            mu::data out(mu::data::type::list);
            // kainjow offers only const access to a list and copies on push_back: reserve, append
            // placeholders and move each converted item into place (the list owns its items).
            auto& items = const_cast<mu::list&>(out.list_value());
            items.reserve(value.size());
            for (const auto& child : value) {
                out.push_back(mu::data(false));
                items.back() = convert(child);
            }
            return out;
        }
        case Json::value_t::string: return mu::data(value.get_ref<const std::string&>());
        case Json::value_t::boolean: return mu::data(value.get<bool>());
        case Json::value_t::number_integer: return mu::data(std::to_string(value.get<std::int64_t>()));
        case Json::value_t::number_unsigned: return mu::data(std::to_string(value.get<std::uint64_t>()));
        case Json::value_t::number_float: return mu::data(value.dump());
        default: return mu::data(false);
    }
}

inline bool is_standalone_tag(std::string_view line) {
    if (line.size() < 5 || line.substr(0, 2) != "{{" || line.substr(line.size() - 2) != "}}") return false;
    const char sigil = line[2];
    if (sigil != '#' && sigil != '^' && sigil != '/' && sigil != '!') return false;
    return line.find("{{", 2) == std::string_view::npos && line.find("}}") == line.size() - 2;
}

inline std::string strip_standalone_lines(const std::string& text) {
    if (text.find("{{=") != std::string::npos) return text;  // custom delimiters: left as written
    std::string out;
    out.reserve(text.size());
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        const bool has_newline = end != std::string::npos;
        if (!has_newline) end = text.size();
        const std::string_view line(text.data() + start, end - start);
        std::string_view trimmed = line;
        while (!trimmed.empty() && (trimmed.front() == ' ' || trimmed.front() == '\t')) trimmed.remove_prefix(1);
        while (!trimmed.empty() && (trimmed.back() == ' ' || trimmed.back() == '\t' || trimmed.back() == '\r')) trimmed.remove_suffix(1);
        if (is_standalone_tag(trimmed)) {
            out += trimmed;
        } else {
            out += line;
            if (has_newline) out += '\n';
        }
        start = end + 1;
    }
    return out;
}

}  // namespace kainjow_oracle_detail

struct OracleResult {
    bool ok = false;
    std::string text;
    std::string error;
};

// Renders `template_text` over `view` the way esi-gen did with kainjow.
inline OracleResult kainjow_render(const std::string& template_text, const nlohmann::ordered_json& view, bool html_escape = false) {
    namespace d = kainjow_oracle_detail;
    OracleResult out;
    try {
        d::mu::mustache tmpl(d::strip_standalone_lines(template_text));
        if (!html_escape) tmpl.set_custom_escape([](const std::string& s) { return s; });
        if (!tmpl.is_valid()) {
            out.error = tmpl.error_message();
            return out;
        }
        const d::mu::data data = d::convert(view);
        out.text = tmpl.render(data);
        if (!tmpl.is_valid()) {
            out.error = tmpl.error_message();
            return out;
        }
        out.ok = true;
    } catch (const std::exception& e) {
        out.error = e.what();
    }
    return out;
}

}  // namespace esi::test::codegen
