// Rendering a parsed template over the view tree (semantics in mustache.hpp).
//
// Speed matters here (issue 3 section 5: 5,000 objects, every output, under 200 ms): the output
// goes into one string, text runs are copied straight from the template, and a name is found
// with one comparison in the common case: each name part remembers the member position where it
// was found last, and the items of a list are built alike, so the next item has it at the same
// position.

#include <charconv>

#include <nlohmann/json.hpp>

#include "esi/codegen/mustache.hpp"

namespace esi::codegen::mustache {

namespace {

// As kainjow: false, null (kainjow saw it as false) and empty lists; "" and 0 are truthy.
bool is_falsey(const ViewValue& value) {
    return value.kind == ViewValue::Kind::null || (value.kind == ViewValue::Kind::boolean && !value.boolean) ||
           (value.kind == ViewValue::Kind::list && value.size == 0);
}

}  // namespace

class Renderer {
public:
    Renderer(const Template& tmpl, std::string& out, Escape escape)
        : tmpl_(tmpl), out_(out), escape_(escape), line_start_(out.size()) {
        parts_.reserve(tmpl.parts_.size());
        for (const auto& p : tmpl.parts_) parts_.emplace_back(tmpl.text_.data() + p.offset, p.length);
        hints_.assign(tmpl.parts_.size(), 0);
        stack_.reserve(16);
    }

    void render(const ViewValue& context) {
        stack_.push_back(&context);
        run(0, static_cast<std::uint32_t>(tmpl_.ops_.size()));
        // The last line has no line break; kainjow's line buffer still drops it when blank.
        if (section_touched_line_ && line_is_blank()) out_.resize(line_start_);
    }

private:
    using Code = Template::Code;

    void run(std::uint32_t begin, std::uint32_t end);
    void section(const Template::Op& op, std::uint32_t body);
    void inverted(const Template::Op& op, std::uint32_t body);
    void line_break(const Template::Op& op);
    void write(const ViewValue& value, bool escaped);
    void write_text(std::string_view text, bool escaped);
    [[nodiscard]] bool line_is_blank() const;
    [[nodiscard]] const ViewValue* lookup(std::uint32_t name_index);
    [[nodiscard]] const ViewValue* member(const ViewValue& object, std::uint32_t part);

    const Template& tmpl_;
    std::string& out_;
    Escape escape_;
    std::vector<std::string_view> parts_;
    std::vector<std::uint32_t> hints_;  // per name part: member position where it was last found
    std::vector<const ViewValue*> stack_;
    std::size_t line_start_;            // where the current output line starts in out_
    bool section_touched_line_ = false;  // a section rendered on the current output line
};

void Template::render(const ViewValue& context, std::string& out, Escape escape) const {
    Renderer renderer(*this, out, escape);
    renderer.render(context);
}

void Renderer::run(std::uint32_t begin, std::uint32_t end) {
    const auto& ops = tmpl_.ops_;
    const char* text = tmpl_.text_.data();
    for (std::uint32_t pc = begin; pc < end;) {
        const Template::Op& op = ops[pc];
        switch (op.code) {
            case Code::text:
                out_.append(text + op.a, op.b);
                ++pc;
                break;
            case Code::newline:
                line_break(op);
                ++pc;
                break;
            case Code::variable:
                if (const ViewValue* value = lookup(op.a)) write(*value, op.escaped);
                ++pc;
                break;
            case Code::section:
                section(op, pc + 1);
                pc = op.b;
                break;
            case Code::inverted:
                inverted(op, pc + 1);
                pc = op.b;
                break;
        }
    }
}

void Renderer::section(const Template::Op& op, std::uint32_t body) {
    const ViewValue* value = lookup(op.a);
    if (!value || is_falsey(*value)) return;
    if (value->kind == ViewValue::Kind::list) {
        for (const ViewValue* item = value->begin_items(); item != value->end_items(); ++item) {
            section_touched_line_ = true;
            stack_.push_back(item);
            run(body, op.b);
            stack_.pop_back();
            section_touched_line_ = true;
        }
        return;
    }
    section_touched_line_ = true;
    stack_.push_back(value);
    run(body, op.b);
    stack_.pop_back();
    section_touched_line_ = true;
}

void Renderer::inverted(const Template::Op& op, std::uint32_t body) {
    const ViewValue* value = lookup(op.a);
    if (value && !is_falsey(*value)) return;
    section_touched_line_ = true;
    // kainjow makes the false value or empty list the context ({{.}} inside renders nothing).
    if (value) stack_.push_back(value);
    run(body, op.b);
    if (value) stack_.pop_back();
    section_touched_line_ = true;
}

bool Renderer::line_is_blank() const {
    for (std::size_t k = line_start_; k < out_.size(); ++k)
        if (out_[k] != ' ' && out_[k] != '\t') return false;
    return true;
}

void Renderer::line_break(const Template::Op& op) {
    if (section_touched_line_ && line_is_blank()) out_.resize(line_start_);
    else out_.append(tmpl_.text_.data() + op.a, op.b);
    line_start_ = out_.size();
    section_touched_line_ = false;
}

const ViewValue* Renderer::member(const ViewValue& object, std::uint32_t part) {
    if (object.kind != ViewValue::Kind::object) return nullptr;
    const std::string_view key = parts_[part];
    const ViewMember* members = object.members;
    const std::uint32_t hint = hints_[part];
    if (hint < object.size && members[hint].key == key) return &members[hint].value;
    for (std::uint32_t k = 0; k < object.size; ++k) {
        if (members[k].key == key) {
            hints_[part] = k;
            return &members[k].value;
        }
    }
    return nullptr;
}

const ViewValue* Renderer::lookup(std::uint32_t name_index) {
    const Template::Name& name = tmpl_.names_[name_index];
    if (name.implicit) return stack_.back();
    for (auto frame = stack_.rbegin(); frame != stack_.rend(); ++frame) {
        const ViewValue* value = *frame;
        for (std::uint32_t k = 0; k < name.part_count && value; ++k) value = member(*value, name.first_part + k);
        if (value) return value;
    }
    return nullptr;
}

void Renderer::write_text(std::string_view text, bool escaped) {
    if (!escaped || escape_ == Escape::none) {
        out_.append(text);
        return;
    }
    for (const char c : text) {
        switch (c) {
            case '&': out_.append("&amp;"); break;
            case '<': out_.append("&lt;"); break;
            case '>': out_.append("&gt;"); break;
            case '"': out_.append("&quot;"); break;
            case '\'': out_.append("&apos;"); break;
            default: out_.push_back(c);
        }
    }
}

void Renderer::write(const ViewValue& value, bool escaped) {
    char buffer[32];
    switch (value.kind) {
        case ViewValue::Kind::string: write_text(value.text(), escaped); break;
        case ViewValue::Kind::integer: {
            const auto r = std::to_chars(buffer, buffer + sizeof buffer, value.integer);
            out_.append(buffer, r.ptr);
            break;
        }
        case ViewValue::Kind::unsigned_integer: {
            const auto r = std::to_chars(buffer, buffer + sizeof buffer, value.unsigned_integer);
            out_.append(buffer, r.ptr);
            break;
        }
        case ViewValue::Kind::real:
            // As the JSON view prints it (kainjow saw the view's JSON text of the number).
            write_text(nlohmann::ordered_json(value.real).dump(), escaped);
            break;
        default: break;  // booleans, null, lists and objects render as nothing
    }
}

}  // namespace esi::codegen::mustache
