#include "xml/writer_extras.hpp"

#include <cassert>

namespace esi::xml_writer {

namespace {

// Deeper verbatim trees are cut here rather than risking the stack; the reader already stops
// copying at ReadOptions::max_verbatim_depth (256), so only hand-built models can reach this.
constexpr std::size_t max_verbatim_depth = 1024;

bool only_whitespace(std::string_view text) {
    for (const char c : text)
        if (c != ' ' && c != '\t' && c != '\n' && c != '\r') return false;
    return true;
}

void write_verbatim_at(XmlEmitter& out, const XmlElement& element, std::size_t depth) {
    // A name that is not an XML name (only possible in hand-built models) cannot be written
    // without breaking the file; such elements are left out.
    if (!is_xml_name(element.name)) return;
    out.begin(element.name);
    for (const auto& a : element.attributes)
        if (is_xml_name(a.name)) out.attribute(a.name, a.value);
    if (element.children.empty() || depth >= max_verbatim_depth) {
        out.text(element.text);
    } else {
        // Whitespace between child elements is layout; any other text is mixed content and is
        // kept (before the children: the reader does not record where it stood among them).
        if (!only_whitespace(element.text)) out.text(element.text);
        for (const auto& child : element.children) write_verbatim_at(out, child, depth + 1);
    }
    out.end();
}

}  // namespace

void write_verbatim(XmlEmitter& out, const XmlElement& element) { write_verbatim_at(out, element, 0); }

void write_extra_attributes(XmlEmitter& out, const Extras& extras) {
    for (const auto& a : extras.attributes)
        if (is_xml_name(a.name)) out.attribute(a.name, a.value);
}

ChildPlacer::ChildPlacer(XmlEmitter& out, const Extras& extras, ChildOrder order)
    : out_(out), extras_(extras), order_(order) {
    const auto& elements = extras_.elements;
    if (elements.empty()) return;
    for (std::size_t i = 0; i < elements.size(); ++i) {
        const std::string& after = elements[i].after;
        if (i > 0 && !after.empty() && after == elements[i - 1].name) {
            runs_.back().last = i + 1;  // directly follows the previous unknown element
            continue;
        }
        Run run;
        run.first = i;
        run.last = i + 1;
        run.anchor = after;
        run.anchor_rank = after.empty() ? -1 : rank_of(after);
        run.own_rank = rank_of(elements[i].name);
        runs_.push_back(run);
    }
    // First children the schema does not place: they stay first.
    for (auto& run : runs_)
        if (run.anchor.empty() && run.own_rank < 0) write_run(run);
}

int ChildPlacer::rank_of(std::string_view name) const {
    for (std::size_t i = 0; i < order_.size(); ++i)
        if (order_[i] == name) return static_cast<int>(i);
    return -1;
}

void ChildPlacer::write_run(Run& run) {
    for (std::size_t i = run.first; i < run.last; ++i) write_verbatim(out_, extras_.elements[i]);
    run.written = true;
}

void ChildPlacer::switch_to(std::string_view name) {
    if (!current_.empty())
        for (auto& run : runs_)
            if (!run.written && run.anchor == current_) write_run(run);
    const int rank = rank_of(name);
    assert(rank >= 0 && "typed child not in the element's schema order");
    assert(rank >= current_rank_ && "typed children must be written in schema order");
    for (auto& run : runs_) {
        if (run.written) continue;
        bool due = false;
        if (run.anchor.empty()) due = run.own_rank <= rank;
        else if (run.anchor_rank >= 0) due = run.anchor_rank < rank;  // its anchor was not written
        else due = run.own_rank >= 0 && run.own_rank < rank;
        if (due) write_run(run);
    }
    current_ = name;
    current_rank_ = rank;
}

void ChildPlacer::finish() {
    if (runs_.empty()) return;
    if (!current_.empty())
        for (auto& run : runs_)
            if (!run.written && run.anchor == current_) write_run(run);
    for (auto& run : runs_)
        if (!run.written) write_run(run);
}

}  // namespace esi::xml_writer
