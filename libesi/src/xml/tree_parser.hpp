#pragma once
// One pass over an XML document's text that checks it for XML 1.0 well-formedness and builds the
// element tree the ESI reader reads (xml/element_tree.hpp), with the line:column of every element
// and the line index of the text as by-products. It replaced a pugixml parse of a copy of the
// text, a second pass of the well-formedness check and a third for the line index: the bytes are
// now read once (docs/performance.md, issue 25).
//
// The grammar of the rare constructs (the prolog and DOCTYPE, comments, processing instructions,
// CDATA sections, references, names beyond ASCII) is the well-formedness scanner's
// (xml/well_formed_scanner.hpp), on whose productions this parser builds; elements, attributes and
// character data, which are nearly all of a file, are parsed here.
//
// The reader streams the document: the root's start tag first, then the children of an element a
// start tag at a time (stream_children), each child built as a whole subtree when it is read
// (expand) and dropped from the tree once the reader has it in the model. A fault stops the
// parse; everything after it is left unread and the reader discards what it read.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "esi/encoding.hpp"
#include "esi/source_text.hpp"
#include "esi/xml/well_formed.hpp"
#include "xml/element_tree.hpp"
#include "xml/well_formed_scanner.hpp"

namespace esi::xml_tree {

// Told about start tags, in document order, while the element's ancestors are in the tree (the
// checks of XInclude elements and of namespace prefixes).
class StartTagObserver {
public:
    virtual ~StartTagObserver() = default;
    virtual void start_tag(Element element) = 0;
};

// Told about every namespace declaration (an attribute named xmlns or xmlns:prefix) with its
// value, while the start tag holding it is read: before the observers of start tags are told
// about that tag.
class NamespaceObserver {
public:
    virtual ~NamespaceObserver() = default;
    virtual void declared(std::string_view uri) = 0;
};

// Whether an attribute of that name declares a namespace: xmlns or xmlns:prefix.
[[nodiscard]] inline bool is_namespace_declaration(std::string_view attribute_name) {
    return attribute_name.starts_with("xmlns") && (attribute_name.size() == 5 || attribute_name[5] == ':');
}

// The base-from-member idiom: the Checker the Scanner refers to exists before the Scanner.
struct CheckerHolder {
    CheckerHolder(std::string_view text, SourceEncoding encoding) : checker(text, encoding) {}
    xml_well_formed::Checker checker;
};

class TreeParser : private CheckerHolder, private xml_well_formed::Scanner {
public:
    // `text` is valid UTF-8 without NUL bytes, followed by a NUL byte, and must outlive the parser
    // and the tree.
    TreeParser(std::string_view text, SourceEncoding encoding, Tree& tree);

    // The prolog and the root element's start tag; none after a fault.
    Element root();

    // Reads the next child element's start tag of `parent` (whose start tag is read and whose
    // content is not) and returns it, its content not yet read; none at the parent's end tag
    // (which is then read) and after a fault. Character data, comments and processing
    // instructions on the way are checked and dropped. The child is not linked into the parent's
    // list of children: it is the reader's to expand, stream or ignore, and drop afterwards.
    Element next_child(Element parent);

    // Reads the rest of `element` (from after its start tag, or wherever a stream of its children
    // stopped) to its end tag, building its subtree. Nothing to do for a complete element.
    bool expand(Element element);

    // Each child element of `parent` in turn: f(child, name, name of the previous child element).
    // What f leaves unread of the child is read (and checked) after it, and the child's subtree
    // is dropped from the tree before the next one.
    template <class F>
    bool stream_children(Element parent, F&& f) {
        std::string_view previous;
        for (;;) {
            const Tree::Mark mark = tree_.mark();
            const Element child = next_child(parent);
            if (!child) return !faulted();
            const std::string_view name = child.name();  // a view into the text: it outlives the subtree
            f(child, name, previous);
            if (!expand(child)) return false;
            previous = name;
            tree_.truncate(mark);
            if (releasable_) releasable_->release_text(released_, offset());
            released_ = offset();
        }
    }

    // The text read so far may let its memory go (SourceText::release_text) behind each child
    // read by stream_children: nothing of it is in the tree any more.
    void release_behind(const SourceText* source) { releasable_ = source; }
    [[nodiscard]] std::size_t offset() const { return static_cast<std::size_t>(p_ - begin_); }

    // After the root element: reads its rest if the reader left any, then what follows it to the
    // end of the text (comments, processing instructions and white space only).
    bool finish();

    [[nodiscard]] bool faulted() const { return checker.faulted(); }
    [[nodiscard]] const std::optional<WellFormednessFault>& fault() const { return checker.fault(); }

    // The DOCTYPE, where there is one: its offset and whether it declares entities.
    struct Doctype {
        std::size_t offset = 0;
        bool declares_entities = false;
    };
    [[nodiscard]] std::optional<Doctype> doctype_declaration() const;

    // `every` is told about every start tag after the root's, `prefixed` about those whose element
    // or attribute names have a prefix (a ':'): those are few, and the parser finds them at no
    // cost to the others (their names end the inner loop's name scan).
    void observe(StartTagObserver* every, StartTagObserver* prefixed) {
        observer_ = every;
        prefix_observer_ = prefixed;
    }
    void observe_namespaces(NamespaceObserver* observer) { namespace_observer_ = observer; }
    [[nodiscard]] StartTagObserver* prefix_observer() const { return prefix_observer_; }
    // Whether the last start tag read had a prefixed name.
    [[nodiscard]] bool last_tag_prefixed() const { return tag_prefixed_; }
    // The position of a byte of the start tag just read (for the observers' diagnostics).
    SourcePos position_of(const char* p);

    // After finish(): the comments of the text, for SourceText.
    std::vector<TextSpan> take_comments() { return std::move(checker.comments); }
    // After finish(): the line starts of the whole text (0, then the offset after every '\n'), for
    // SourceText.
    LineStartList take_line_starts();

private:
    // An element being built by expand(), and its last child so far.
    struct Open {
        std::uint32_t index;
        std::uint32_t last_child;
    };

    // ---- lines: every byte the parse steps over is looked at for line feeds once, by the scan
    // that steps over it; the rare constructs the scanner parses are counted afterwards.

    // Line starts found so far: 0, then the offset after every '\n'. A block of 16 bytes holds at
    // most 16 line feeds, so room is made once per block and each start is one store. The starts
    // are kept in the list SourceText adopts, sized ahead (without zeroing it: the part beyond
    // the last line is never touched, so it is not trimmed either) and cut to length at the end.
    class LineStarts {
    public:
        explicit LineStarts(std::size_t expected) : starts_(std::max<std::size_t>(expected, 64)) { starts_[0] = 0; }
        void make_room(std::size_t n) {
            if (starts_.size() - count_ < n) starts_.resize(2 * starts_.size() + n);
        }
        void add(std::uint32_t offset) { starts_[count_++] = offset; }
        [[nodiscard]] std::uint32_t count() const { return count_; }
        [[nodiscard]] std::uint32_t operator[](std::size_t i) const { return starts_[i]; }
        LineStartList take() {
            starts_.resize(count_);
            return std::move(starts_);
        }

    private:
        LineStartList starts_;
        std::uint32_t count_ = 1;
    };

    // The line feeds marked in `mask` of the 16 bytes at `block`.
    [[gnu::always_inline]] void newlines_in_block(const char* block, unsigned mask) {
        line_starts_.make_room(16);
        const auto base = static_cast<std::uint32_t>(block - begin_ + 1);
        unsigned last = 0;
        for (; mask != 0; mask &= mask - 1) {
            last = static_cast<unsigned>(__builtin_ctz(mask));
            line_starts_.add(base + last);
        }
        line_start_ = block + last + 1;
    }
    void newline_at(const char* line_feed) {
        line_starts_.make_room(1);
        line_starts_.add(static_cast<std::uint32_t>(line_feed - begin_ + 1));
        line_start_ = line_feed + 1;
    }
    void count_lines(const char* from, const char* to);
    const char* skip_space(const char* p);
    SourcePos position_at(const char* p);
    // A scanner production from p_, with the line feeds it stepped over counted.
    template <class Step>
    bool scanned(Step step) {
        const char* from = p_;
        const bool ok = (this->*step)();
        count_lines(from, p_);
        return ok;
    }

    std::uint32_t start_tag(std::uint32_t parent, bool& empty);
    bool attributes(std::uint32_t element, std::string_view element_name, bool& empty);
    bool attribute(std::uint32_t element, std::string_view element_name);
    bool attribute_value(std::string_view attribute_name, std::string_view& value);
    bool end_tag(std::uint32_t element);
    // Character data from `start` (p_ is past its leading white space, at a byte that is not '<')
    // up to the next '<' or the end. With `owner` it is kept: as the owner's own text or as a
    // pcdata child after `last_child`. `decoded`: what lies before p_ needs decoding already.
    bool character_data(const char* start, std::uint32_t owner, std::uint32_t* last_child, bool decoded = false);
    void keep_text(const char* start, const char* stop, bool decoded, std::uint32_t owner, std::uint32_t* last_child);
    // A run of character data up to the next '<' (run_to_markup).
    struct Run {
        const char* stop = nullptr;    // the '<'; or where to go on byte by byte when not `plain`
        bool plain = true;             // nothing in it needs a closer look, and the '<' was found
        bool white = true;             // white space only (so far, when not plain)
        bool carriage_return = false;  // holds a '\r', to be read as a line feed
    };
    Run run_to_markup(const char* p);
    bool short_run(const char*& p, const char*& text, std::uint32_t owner, std::uint32_t* last_child);
    bool leaf(const char*& p, std::uint32_t element, std::string_view name);
    // The attributes of a start tag as most are written: see plain_attributes() in the .cpp.
    static constexpr unsigned max_plain_attributes = 8;
    struct PlainAttributes {
        Attribute items[max_plain_attributes];
        unsigned count = 0;
        const char* after = nullptr;  // the byte after the tag's '>'
        bool empty = false;           // "/>"
    };
    bool plain_attributes(const char* q, PlainAttributes& out) const;
    // Markup other than a tag at p_: comments, processing instructions, CDATA sections (kept under
    // `owner` when there is one), and what is misplaced.
    bool other_markup(std::uint32_t owner, std::uint32_t* last_child);
    void append_child(std::uint32_t parent, std::uint32_t* last_child, std::uint32_t child);
    bool unclosed(std::uint32_t element);
    void tell_observers(std::uint32_t element, bool slow);
    bool report(const char* at, std::string message);

    Tree& tree_;
    LineStarts line_starts_;
    const char* line_start_;  // of the line of p_
    // The last position computed, to count columns on from it along one (long) line.
    std::uint32_t memo_line_ = 0;
    const char* memo_ = nullptr;
    std::uint32_t memo_column_ = 0;
    std::vector<Open> building_;  // the elements expand() has open, innermost last
    StartTagObserver* observer_ = nullptr;
    StartTagObserver* prefix_observer_ = nullptr;
    NamespaceObserver* namespace_observer_ = nullptr;
    const SourceText* releasable_ = nullptr;
    std::size_t released_ = 0;
    bool tag_prefixed_ = false;  // the start tag being read has a prefixed element or attribute name
    std::uint32_t root_ = 0;
};

}  // namespace esi::xml_tree
