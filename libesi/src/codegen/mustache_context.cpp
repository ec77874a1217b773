#include "codegen/mustache_context.hpp"

#include <kainjow/mustache.hpp>

#include <algorithm>
#include <cctype>
#include <utility>
#include <vector>

namespace esi::codegen {

namespace mu = kainjow::mustache;

namespace {

mu::data convert(const Json& value) {
    switch (value.type()) {
        case Json::value_t::object: {
            mu::data out(mu::data::type::object);
            for (const auto& [key, child] : value.items()) out[key] = convert(child);
            return out;
        }
        case Json::value_t::array: {
            mu::data out(mu::data::type::list);
            // kainjow offers only const access to a list and copies on push_back, and its move
            // constructor is not noexcept, so a growing vector would deep-copy every item on each
            // reallocation. The list owns its items (writing through the reference is sound):
            // reserve once, append cheap placeholders and move each converted item into place.
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

SourcePos position_in(std::size_t offset, const std::string& text) {
    offset = std::min(offset, text.size());
    SourcePos pos{1, 1};
    for (std::size_t k = 0; k < offset; ++k) {
        if (text[k] == '\n') {
            ++pos.line;
            pos.column = 1;
        } else {
            ++pos.column;
        }
    }
    return pos;
}

bool is_standalone_tag(std::string_view line) {
    if (line.size() < 5 || line.substr(0, 2) != "{{" || line.substr(line.size() - 2) != "}}") return false;
    const char sigil = line[2];
    if (sigil != '#' && sigil != '^' && sigil != '/' && sigil != '!') return false;
    return line.find("{{", 2) == std::string_view::npos && line.find("}}") == line.size() - 2;
}

// The mustache spec removes a line that holds nothing but a section, inverted-section, end or
// comment tag. kainjow does so only for sections that render, so a false section would leave an
// empty line behind; joining such lines to the next one before parsing gives the spec's output.
struct StrippedTemplate {
    std::string text;
    std::vector<std::pair<std::size_t, std::size_t>> segments;  // (offset in text, offset in the original)

    [[nodiscard]] std::size_t original_offset(std::size_t offset) const {
        std::size_t original = offset;
        for (const auto& [at, from] : segments)
            if (at <= offset) original = from + (offset - at);
        return original;
    }
};

StrippedTemplate strip_standalone_lines(const std::string& text) {
    StrippedTemplate out;
    if (text.find("{{=") != std::string::npos) {  // custom delimiters: leave as written
        out.text = text;
        return out;
    }
    out.text.reserve(text.size());
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
            out.segments.emplace_back(out.text.size(), static_cast<std::size_t>(trimmed.data() - text.data()));
            out.text += trimmed;
        } else {
            out.segments.emplace_back(out.text.size(), start);
            out.text += line;
            if (has_newline) out.text += '\n';
        }
        start = end + 1;
    }
    return out;
}

SourcePos position_of(const std::string& message, const StrippedTemplate& stripped, const std::string& text) {
    const std::size_t at = message.rfind(" at ");
    if (at == std::string::npos) return {};
    std::size_t offset = 0;
    for (std::size_t k = at + 4; k < message.size() && std::isdigit(static_cast<unsigned char>(message[k])); ++k)
        offset = offset * 10 + static_cast<std::size_t>(message[k] - '0');
    return position_in(stripped.original_offset(offset), text);
}

}  // namespace

struct MustacheContext::Impl {
    mu::data data;
};

MustacheContext::MustacheContext(const Json& view) : impl_(std::make_unique<Impl>(Impl{convert(view)})) {}
MustacheContext::~MustacheContext() = default;

Rendered MustacheContext::render(const std::string& template_text) const {
    Rendered out;
    // Templates may come from users: nothing they contain may escape as an exception.
    try {
        return render_checked(template_text);
    } catch (const std::exception& e) {
        out.error = std::string("template could not be rendered: ") + e.what();
    }
    return out;
}

Rendered MustacheContext::render_checked(const std::string& template_text) const {
    Rendered out;
    const StrippedTemplate stripped = strip_standalone_lines(template_text);
    mu::mustache tmpl(stripped.text);
    tmpl.set_custom_escape([](const std::string& s) { return s; });
    if (!tmpl.is_valid()) {
        out.error = tmpl.error_message();
        out.pos = position_of(out.error, stripped, template_text);
        return out;
    }
    out.text = tmpl.render(impl_->data);
    if (!tmpl.is_valid()) {
        out.error = tmpl.error_message();
        return out;
    }
    out.ok = true;
    return out;
}

}  // namespace esi::codegen
