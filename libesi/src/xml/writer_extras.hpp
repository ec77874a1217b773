#pragma once
// Putting back what the reader kept verbatim (Extras): unknown attributes after the typed ones,
// unknown elements among the typed children where they were in the source.
//
// The reader records, for each unknown element, the name of its preceding sibling (`after`).
// Consecutive unknown elements form a run (each one's `after` is the previous one's name); a run
// is anchored at the `after` of its first element. While an element's typed children are written
// in schema order, ChildPlacer is told which child group comes next (`at`) and writes each run
// right after the group it is anchored at. A run whose anchor is not written (the model no longer
// has that element) goes where the schema puts that anchor; when the schema does not know the
// anchor either, where it puts the run's own first element; failing both, at the end. A run
// without anchor (it was the first child) goes first, or to its schema place if it has one.

#include <span>
#include <string_view>
#include <vector>

#include "esi/model/common.hpp"
#include "xml/writer_emitter.hpp"

namespace esi::xml_writer {

// The children of one element in ETG.2000 schema order (typed and untyped names alike).
using ChildOrder = std::span<const std::string_view>;

// Writes an element kept verbatim, with its attributes, text and children, as it was read.
void write_verbatim(XmlEmitter& out, const XmlElement& element);

// Writes the unknown attributes of an element (call after its typed attributes).
void write_extra_attributes(XmlEmitter& out, const Extras& extras);

class ChildPlacer {
public:
    // `extras` and `order` must outlive the placer. Writes the runs that go first.
    ChildPlacer(XmlEmitter& out, const Extras& extras, ChildOrder order);
    ChildPlacer(const ChildPlacer&) = delete;
    ChildPlacer& operator=(const ChildPlacer&) = delete;

    // The next typed child belongs to group `name` (a name in `order`). Call before writing each
    // typed child; repeated calls with the same name are free.
    void at(std::string_view name) {
        if (runs_.empty() || name == current_) return;
        switch_to(name);
    }
    // Writes what is left; call before ending the element.
    void finish();

private:
    struct Run {
        std::size_t first = 0;  // indices into extras.elements
        std::size_t last = 0;   // one past the end
        std::string_view anchor;
        int anchor_rank = -1;  // position of the anchor in `order`, -1 when not in it
        int own_rank = -1;     // position of the first element's name in `order`
        bool written = false;
    };

    void switch_to(std::string_view name);
    void write_run(Run& run);
    [[nodiscard]] int rank_of(std::string_view name) const;

    XmlEmitter& out_;
    const Extras& extras_;
    ChildOrder order_;
    std::vector<Run> runs_;
    std::string_view current_;
    int current_rank_ = -1;
};

}  // namespace esi::xml_writer
