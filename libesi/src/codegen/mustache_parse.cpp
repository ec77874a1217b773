// Parsing a Mustache template into esi-gen's instruction list (see mustache.hpp for what is
// supported and how it relates to the spec and to kainjow).
//
// Tags are read the way kainjow reads them: the text between the delimiters is trimmed, its first
// character gives the kind (# ^ / ! & > =, else a variable) and the rest, trimmed again, is the
// name; with the default delimiters "{{{" opens an unescaped variable closed by "}}}".
//
// Standalone lines are removed from the text before it is parsed, line by line, exactly as
// esi-gen did before kainjow saw a template (mustache.hpp); error positions are mapped back to
// the text as written.

#include <algorithm>
#include <cctype>
#include <utility>

#include "esi/codegen/mustache.hpp"

namespace esi::codegen::mustache {

namespace {

bool is_space(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }
bool is_blank(char c) { return c == ' ' || c == '\t'; }

std::string_view trim(std::string_view s) {
    while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
    while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
    return s;
}

SourcePos position_of(std::string_view text, std::size_t offset) {
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

std::string describe(SourcePos pos) { return std::to_string(pos.line) + ":" + std::to_string(pos.column); }

// The Mustache spec removes a line that holds nothing but a section, inverted-section, end or
// comment tag; kainjow does so only for sections that render, so a false section would leave an
// empty line behind. Joining such lines to the next one before parsing gives the spec's output.
// Templates that set delimiters are left as written.
using Segments = std::vector<std::pair<std::size_t, std::size_t>>;  // (offset in text, offset in the original)

struct StrippedTemplate {
    std::string text;
    Segments segments;  // empty: the text is the original
};

std::size_t original_offset(const Segments& segments, std::size_t offset) {
    std::size_t original = offset;
    for (const auto& [at, from] : segments)
        if (at <= offset) original = from + (offset - at);
    return original;
}

bool is_standalone_tag(std::string_view line) {
    if (line.size() < 5 || line.substr(0, 2) != "{{" || line.substr(line.size() - 2) != "}}") return false;
    const char sigil = line[2];
    if (sigil != '#' && sigil != '^' && sigil != '/' && sigil != '!') return false;
    return line.find("{{", 2) == std::string_view::npos && line.find("}}") == line.size() - 2;
}

StrippedTemplate strip_standalone_lines(std::string_view text) {
    StrippedTemplate out;
    if (text.find("{{=") != std::string_view::npos) {
        out.text.assign(text);
        return out;
    }
    out.text.reserve(text.size());
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        const bool has_newline = end != std::string_view::npos;
        if (!has_newline) end = text.size();
        const std::string_view line = text.substr(start, end - start);
        std::string_view trimmed = line;
        while (!trimmed.empty() && is_blank(trimmed.front())) trimmed.remove_prefix(1);
        while (!trimmed.empty() && (is_blank(trimmed.back()) || trimmed.back() == '\r')) trimmed.remove_suffix(1);
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

enum class TagKind { variable, unescaped, section, inverted, end, comment, set_delimiter, partial, inheritance };

}  // namespace

// Builds the instruction list while the text is scanned once.
class Parser {
public:
    Parser(std::string_view original, StrippedTemplate&& stripped) : original_(original), segments_(std::move(stripped.segments)) {
        tmpl_.text_ = std::move(stripped.text);
    }

    ParseResult run();

private:
    using Op = Template::Op;
    using Code = Template::Code;

    struct OpenSection {
        std::size_t op;
        std::string_view name;
        std::size_t offset;  // of its tag, for messages
    };

    [[nodiscard]] std::string_view text() const { return tmpl_.text_; }
    void fail(std::string message, std::size_t offset) {
        if (!result_error_.empty()) return;
        result_error_ = std::move(message);
        error_offset_ = offset;
    }
    // Plain text between tags: text runs and line breaks ("\r\n", "\n" and, as kainjow, a lone "\r").
    void add_text(std::size_t from, std::size_t to);
    void push_text(Code code, std::size_t from, std::size_t to) {
        tmpl_.ops_.push_back({code, false, static_cast<std::uint32_t>(from), static_cast<std::uint32_t>(to - from)});
    }
    std::uint32_t add_name(std::string_view name);
    [[nodiscard]] bool set_delimiters(std::string_view content);
    // Where an offset in the parsed text is in the template as written.
    [[nodiscard]] SourcePos position(std::size_t offset) const { return position_of(original_, original_offset(segments_, offset)); }

    Template tmpl_;
    std::string open_ = "{{";
    std::string close_ = "}}";
    std::vector<OpenSection> sections_;
    std::string_view original_;
    Segments segments_;
    std::string result_error_;
    std::size_t error_offset_ = 0;
};

void Parser::add_text(std::size_t from, std::size_t to) {
    const std::string_view t = text();
    std::size_t run = from;
    for (std::size_t k = from; k < to;) {
        const char c = t[k];
        if (c == '\n' || c == '\r') {
            if (run < k) push_text(Code::text, run, k);
            const bool crlf = c == '\r' && k + 1 < to && t[k + 1] == '\n';
            const std::size_t end = k + (crlf ? 2 : 1);
            push_text(Code::newline, k, end);
            k = end;
            run = k;
            continue;
        }
        ++k;
    }
    if (run < to) push_text(Code::text, run, to);
}

std::uint32_t Parser::add_name(std::string_view name) {
    Template::Name entry;
    entry.first_part = static_cast<std::uint32_t>(tmpl_.parts_.size());
    const auto offset_of = [&](std::string_view part) { return static_cast<std::uint32_t>(part.data() - tmpl_.text_.data()); };
    if (name == ".") {
        entry.implicit = true;
    } else if (name.find('.') == std::string_view::npos) {
        tmpl_.parts_.push_back({offset_of(name), static_cast<std::uint32_t>(name.size())});
    } else {
        // Split at every '.', as kainjow does (std::getline: no empty part after a trailing '.').
        std::size_t start = 0;
        while (start < name.size()) {
            const std::size_t dot = std::min(name.find('.', start), name.size());
            const std::string_view part = name.substr(start, dot - start);
            tmpl_.parts_.push_back({offset_of(part), static_cast<std::uint32_t>(part.size())});
            start = dot + 1;
        }
    }
    entry.part_count = static_cast<std::uint32_t>(tmpl_.parts_.size()) - entry.first_part;
    tmpl_.names_.push_back(entry);
    return static_cast<std::uint32_t>(tmpl_.names_.size() - 1);
}

bool Parser::set_delimiters(std::string_view content) {
    // "{{=<% %>=}}": two delimiters separated by spaces, neither holding whitespace or '='
    // (the spec's rule; kainjow's parser accepts the same).
    if (content.size() < 5 || content.back() != '=') return false;
    const std::string_view inner = trim(content.substr(1, content.size() - 2));
    const std::size_t space = inner.find(' ');
    if (space == std::string_view::npos) return false;
    const std::size_t second = inner.find_first_not_of(' ', space + 1);
    if (second == std::string_view::npos) return false;
    const std::string_view open = inner.substr(0, space);
    const std::string_view close = inner.substr(second);
    const auto valid = [](std::string_view d) {
        return !d.empty() && std::none_of(d.begin(), d.end(), [](char c) { return c == '=' || is_space(c); });
    };
    if (!valid(open) || !valid(close)) return false;
    open_.assign(open);
    close_.assign(close);
    return true;
}

ParseResult Parser::run() {
    const std::string_view t = text();
    std::size_t pos = 0;
    while (pos < t.size() && result_error_.empty()) {
        const std::size_t open_at = t.find(open_, pos);
        if (open_at == std::string_view::npos) {
            add_text(pos, t.size());
            break;
        }
        add_text(pos, open_at);

        std::size_t content_from = open_at + open_.size();
        const bool braces = open_ == "{{" && close_ == "}}";
        const bool triple = braces && content_from < t.size() && t[content_from] == '{';
        const std::string_view close = triple ? std::string_view("}}}") : std::string_view(close_);
        if (triple) ++content_from;
        const std::size_t close_at = t.find(close, content_from);
        if (close_at == std::string_view::npos) {
            fail("Unclosed tag", open_at);
            break;
        }
        const std::string_view content = trim(t.substr(content_from, close_at - content_from));
        const std::size_t after = close_at + close.size();

        TagKind kind = TagKind::variable;
        std::string_view name = content;
        if (!content.empty() && content.front() == '=') {
            kind = TagKind::set_delimiter;
        } else if (triple) {
            kind = TagKind::unescaped;
        } else if (!content.empty()) {
            switch (content.front()) {
                case '#': kind = TagKind::section; break;
                case '^': kind = TagKind::inverted; break;
                case '/': kind = TagKind::end; break;
                case '!': kind = TagKind::comment; break;
                case '&': kind = TagKind::unescaped; break;
                case '>': kind = TagKind::partial; break;
                case '<':
                case '$': kind = TagKind::inheritance; break;
                default: break;
            }
            if (kind != TagKind::variable) name = trim(content.substr(1));
        }

        if (kind == TagKind::partial) {
            fail("partials are not supported ({{> " + std::string(name) + "}}): esi-gen renders each template on its own", open_at);
            break;
        }
        if (kind == TagKind::inheritance) {
            fail("template inheritance is not supported (" + std::string(content.substr(0, 1)) + " " + std::string(name) + ")", open_at);
            break;
        }
        if (kind == TagKind::variable || kind == TagKind::unescaped) {
            tmpl_.ops_.push_back({Code::variable, kind == TagKind::variable, add_name(name), 0});
            pos = after;
            continue;
        }

        switch (kind) {
            case TagKind::section:
            case TagKind::inverted:
                if (sections_.size() >= max_section_depth) {
                    fail("sections nested deeper than " + std::to_string(max_section_depth), open_at);
                    break;
                }
                sections_.push_back({tmpl_.ops_.size(), name, open_at});
                tmpl_.ops_.push_back({kind == TagKind::section ? Code::section : Code::inverted, false, add_name(name), 0});
                break;
            case TagKind::end:
                if (sections_.empty()) {
                    fail("Unopened section \"" + std::string(name) + "\"", open_at);
                    break;
                }
                if (sections_.back().name != name) {
                    fail("Unclosed section \"" + std::string(sections_.back().name) + "\" (closed by {{/" + std::string(name) + "}} at " +
                             describe(position(open_at)) + ")",
                         sections_.back().offset);
                    break;
                }
                tmpl_.ops_[sections_.back().op].b = static_cast<std::uint32_t>(tmpl_.ops_.size());
                sections_.pop_back();
                break;
            case TagKind::set_delimiter:
                if (!set_delimiters(content)) fail("Invalid set delimiter tag", open_at);
                break;
            default: break;  // comment
        }
        pos = after;
    }
    if (result_error_.empty() && !sections_.empty())
        fail("Unclosed section \"" + std::string(sections_.front().name) + "\"", sections_.front().offset);

    ParseResult result;
    if (!result_error_.empty()) {
        result.error = std::move(result_error_);
        result.pos = position(error_offset_);
        return result;
    }
    if (tmpl_.text_.size() > UINT32_MAX || tmpl_.ops_.size() > UINT32_MAX) {
        result.error = "template too large";
        result.pos = {1, 1};
        return result;
    }
    result.parsed = std::move(tmpl_);
    return result;
}

ParseResult parse(std::string_view text) {
    if (text.size() > UINT32_MAX) return {std::nullopt, "template too large", {1, 1}};
    Parser parser(text, strip_standalone_lines(text));
    return parser.run();
}

}  // namespace esi::codegen::mustache
