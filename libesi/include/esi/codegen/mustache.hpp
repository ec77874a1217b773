#pragma once
// The Mustache engine of libesi's templates: a template is parsed once into a flat list of
// instructions and rendered straight over the view tree into one output buffer. esi-gen renders
// code with it (Escape::none), esi-doc renders HTML pages (Escape::html).
//
// Supported: text, variables ({{name}}, {{{name}}}, {{& name}}; HTML-escaped or not, see
// Escape), sections and inverted sections over lists, objects and values, comments, set
// delimiters ({{=<% %>=}}), dotted names and the implicit iterator {{.}}. Partials ({{> name}})
// and template inheritance ({{< name}}, {{$ name}}) are parse errors with the tag's line:col;
// lambdas cannot occur (the view is data).
//
// The output is the one esi-gen gave when it rendered with the kainjow mustache library, after
// removing standalone lines itself (tests/codegen/mustache_differential_test.cpp keeps both in
// step, with kainjow as the oracle). That includes kainjow's choices where the spec leaves room
// or differs:
//   - a name is looked up in each context from the innermost outwards; a dotted name a.b.c is
//     resolved as a whole in each context in turn (the spec stops at the first context that has
//     `a`);
//   - falsey are false, null and empty lists; "" and 0 are truthy; numbers render in decimal,
//     booleans, null, lists and objects render as nothing;
//   - an output line that holds only blanks and was touched by a section that rendered is
//     dropped with its line break (kainjow's line buffer).
// Standalone lines are removed from the template text before it is parsed, line by line, as
// esi-gen did before kainjow saw a template: a line that holds, besides blanks (and CRs at its
// end), exactly one tag {{#...}}, {{^...}}, {{/...}} or {{!...}} (sigil right after "{{", no other
// "{{" or "}}" on the line) loses its blanks and line break, whether the section renders or not
// (the spec's rule, which kainjow applies only to sections that render). The rule looks at lines
// only, so it also joins such a line inside a comment that spans lines. Templates that contain
// "{{=" (set delimiters) are parsed as written, with kainjow's rule only, as before.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "esi/codegen/view_tree.hpp"
#include "esi/source_pos.hpp"

namespace esi::codegen::mustache {

enum class Escape {
    none,  // code generation: {{name}} is inserted as it is
    html,  // the spec's default: & < > " ' as entities in {{name}}, not in {{{name}}}/{{& name}}
};

class Template {
public:
    // Appends the rendering over `context` to `out`.
    void render(const ViewValue& context, std::string& out, Escape escape = Escape::none) const;

    [[nodiscard]] std::size_t instruction_count() const { return ops_.size(); }

private:
    friend class Parser;
    friend class Renderer;

    enum class Code : std::uint8_t { text, newline, variable, section, inverted };
    struct Op {
        Code code = Code::text;
        bool escaped = false;    // variable: {{name}} (escaped in Escape::html) rather than {{{name}}}
        std::uint32_t a = 0;     // text/newline: offset in text_; variable/section/inverted: name index
        std::uint32_t b = 0;     // text/newline: length; section/inverted: index of the op after its end
    };
    struct Name {
        std::uint32_t first_part = 0;  // into parts_
        std::uint32_t part_count = 0;
        bool implicit = false;         // {{.}}
    };
    struct Part {
        std::uint32_t offset = 0;  // into text_
        std::uint32_t length = 0;
    };

    std::string text_;
    std::vector<Op> ops_;
    std::vector<Name> names_;
    std::vector<Part> parts_;
};

struct ParseResult {
    std::optional<Template> parsed;  // absent on error
    std::string error;               // e.g. `Unclosed section "objects"`
    SourcePos pos;                   // where in the template text (1-based line and column)
};

// Sections may nest this deep; deeper templates are refused (rendering recurses per level).
inline constexpr std::size_t max_section_depth = 256;

[[nodiscard]] ParseResult parse(std::string_view text);

}  // namespace esi::codegen::mustache
