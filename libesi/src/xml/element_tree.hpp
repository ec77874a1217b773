#pragma once
// The element tree the ESI reader reads: what xml/tree_parser.hpp built in its one pass over the
// text, kept in flat arrays. Names, and every value that needed no decoding, are views into the
// text itself (so a value's offset in the file is where it points); values that did (a reference,
// a carriage return, a tab in an attribute) are decoded into the tree's own store. Each element
// carries the line:column of its '<', computed during the pass.
//
// The tree mirrors what pugixml builds with the reader's former options (parse_default |
// parse_embed_pcdata), which tests/unit/element_tree_test.cpp checks against pugixml itself:
// comments and processing instructions are not kept; character data that is only white space is
// dropped; the first other character data of an element with no child yet is the element's own
// value, later runs are pcdata children; CDATA sections are cdata children; "\r\n" and "\r" read
// as "\n"; an attribute value reads tabs and line breaks as spaces; the five predefined entities
// and character references are replaced, other references stay as written.
//
// Elements are streamed a subtree at a time (TreeParser::stream_children): a mark taken before a
// child is read lets the tree drop the child again once the reader has it in the model, so that a
// catalogue of a thousand devices never has more than one device's elements in memory.

#include <cstdint>
#include <cstring>
#include <algorithm>
#include <deque>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "esi/large_buffer.hpp"
#include "esi/source_pos.hpp"

namespace esi::xml_tree {

enum class NodeKind : std::uint8_t { element, pcdata, cdata };

struct Attribute {
    std::string_view name;
    std::string_view value;
};
// A document's attributes, in one array (a big file's is a large buffer, esi/large_buffer.hpp).
using AttributeList = std::vector<Attribute, LargeBufferAllocator<Attribute>>;

struct Node {
    std::string_view name;   // elements only
    std::string_view value;  // an element's own text (see above); the text of pcdata and cdata
    std::uint32_t parent = 0;  // 0: none (index 0 is no node)
    std::uint32_t first_child = 0;
    std::uint32_t next_sibling = 0;
    std::uint32_t first_attribute = 0;
    std::uint32_t attribute_count = 0;
    std::uint32_t offset = 0;  // of the '<' of an element, or of the first byte of character data
    SourcePos pos;             // of the '<'
    NodeKind kind = NodeKind::element;
    bool has_value = false;  // an element's own text was set (pugixml's "value is not null")
    bool complete = false;   // read up to its end tag
};

class Tree;

// A handle to an element (or a character-data node) of a Tree; false when it names none. Valid
// until the tree is truncated before it.
class Element {
public:
    Element() = default;
    Element(const Tree* tree, std::uint32_t index) : tree_(tree), index_(index) {}

    explicit operator bool() const { return index_ != 0; }
    [[nodiscard]] std::uint32_t index() const { return index_; }
    friend bool operator==(const Element& a, const Element& b) { return a.index_ == b.index_ && a.tree_ == b.tree_; }

    [[nodiscard]] const Node& node() const;
    [[nodiscard]] NodeKind kind() const { return node().kind; }
    [[nodiscard]] std::string_view name() const { return node().name; }
    [[nodiscard]] std::string_view value() const { return node().value; }
    [[nodiscard]] SourcePos pos() const { return node().pos; }
    [[nodiscard]] std::size_t offset() const { return node().offset; }

    [[nodiscard]] Element parent() const { return {tree_, node().parent}; }
    [[nodiscard]] Element first_child() const { return {tree_, node().first_child}; }
    [[nodiscard]] Element next_sibling() const { return {tree_, node().next_sibling}; }
    // The first child element named `name`, and the next sibling element of that name.
    [[nodiscard]] Element child(std::string_view child_name) const;
    [[nodiscard]] Element next_sibling(std::string_view sibling_name) const;

    [[nodiscard]] std::span<const Attribute> attributes() const;
    [[nodiscard]] const Attribute* attribute(std::string_view attribute_name) const;

    // The element's character data as pugixml's text() gave it: its own text, or else the first
    // pcdata or cdata child's (text after a child element or a CDATA section).
    [[nodiscard]] std::string_view text() const;

private:
    const Tree* tree_ = nullptr;
    std::uint32_t index_ = 0;
};

class Tree {
public:
    Tree() { grow(256); }  // index 0 stands for "none"

    [[nodiscard]] Element element(std::uint32_t index) const { return {this, index}; }
    [[nodiscard]] const Node& node(std::uint32_t index) const { return nodes_.get()[index]; }
    [[nodiscard]] Node& node(std::uint32_t index) { return nodes_.get()[index]; }
    [[nodiscard]] std::span<const Attribute> attributes_of(const Node& n) const {
        return {attributes_.data() + n.first_attribute, n.attribute_count};
    }

    // Everything added after a mark is dropped again by truncate(mark).
    struct Mark {
        std::uint32_t nodes = 0;
        std::size_t attributes = 0;
        std::size_t decoded = 0;
    };
    [[nodiscard]] Mark mark() const { return {size_, attributes_.size(), decoded_.size()}; }
    void truncate(const Mark& m) {
        size_ = m.nodes;
        attributes_.resize(m.attributes);
        decoded_.resize(m.decoded);
    }

    // For the parser. Nodes live in one array that grows by doubling and is never shrunk: the
    // largest device of a document sets its size, and every later one reuses it.
    void reserve(std::size_t nodes) {
        if (nodes > capacity_) grow(nodes);
    }
    std::uint32_t add_node() {
        if (size_ == capacity_) grow(2 * capacity_);
        nodes_.get()[size_] = Node{};
        return size_++;
    }
    // An element the parser read a start tag of, its fields written once (the parser's inner loop
    // adds one for nearly every element of a file). Its attributes, if any, are the ones added
    // after it (first_attribute is then attributes().size(); without any it does not matter).
    std::uint32_t add_element(std::string_view name, std::uint32_t parent, std::uint32_t offset, SourcePos pos,
                              std::uint32_t first_attribute = 0) {
        if (size_ == capacity_) grow(2 * capacity_);
        Node& n = nodes_.get()[size_];
        n.name = name;
        n.value = {};
        n.parent = parent;
        n.first_child = 0;
        n.next_sibling = 0;
        n.first_attribute = first_attribute;
        n.attribute_count = 0;
        n.offset = offset;
        n.pos = pos;
        n.kind = NodeKind::element;
        n.has_value = false;
        n.complete = false;
        return size_++;
    }
    AttributeList& attributes() { return attributes_; }
    // Keeps a decoded value; the view stays valid until a truncate() before it.
    std::string_view keep(std::string&& decoded) { return decoded_.emplace_back(std::move(decoded)); }
    [[nodiscard]] std::size_t node_count() const { return size_ - 1; }

private:
    // Raw storage: a node is written whole when it is added (Node is an aggregate, so its objects
    // begin their lifetime in the allocated storage), and growing keeps only the nodes in use (a
    // large buffer is lengthened in place, esi/large_buffer.hpp).
    static_assert(std::is_trivially_copyable_v<Node>, "nodes are moved as bytes when the array grows");
    struct Release {
        Release() noexcept : bytes(0) {}
        explicit Release(std::size_t capacity) noexcept : bytes(capacity * sizeof(Node)) {}
        std::size_t bytes;
        void operator()(Node* p) const { free_large_buffer(p, bytes); }
    };
    void grow(std::size_t capacity) {
        const std::size_t old_bytes = nodes_.get_deleter().bytes;
        Node* nodes = static_cast<Node*>(
            reallocate_large_buffer(nodes_.get(), old_bytes, capacity * sizeof(Node), size_ * sizeof(Node)));
        (void)nodes_.release();  // reallocated: `nodes` holds them now
        nodes_ = std::unique_ptr<Node, Release>(nodes, Release(capacity));
        if (size_ == 0) {
            nodes[0] = Node{};  // the first, "none"
            size_ = 1;
        }
        capacity_ = static_cast<std::uint32_t>(capacity);
    }

    std::unique_ptr<Node, Release> nodes_;
    std::uint32_t size_ = 0;
    std::uint32_t capacity_ = 0;
    AttributeList attributes_;
    std::deque<std::string> decoded_;  // a deque: growing it moves no string, so views stay valid
};

inline const Node& Element::node() const { return tree_->node(index_); }

inline std::span<const Attribute> Element::attributes() const { return tree_->attributes_of(node()); }

inline const Attribute* Element::attribute(std::string_view attribute_name) const {
    for (const Attribute& a : attributes())
        if (a.name == attribute_name) return &a;
    return nullptr;
}

inline Element Element::child(std::string_view child_name) const {
    for (Element c = first_child(); c; c = c.next_sibling())
        if (c.kind() == NodeKind::element && c.name() == child_name) return c;
    return {};
}

inline Element Element::next_sibling(std::string_view sibling_name) const {
    for (Element c = next_sibling(); c; c = c.next_sibling())
        if (c.kind() == NodeKind::element && c.name() == sibling_name) return c;
    return {};
}

inline std::string_view Element::text() const {
    const Node& n = node();
    if (n.has_value) return n.value;
    for (Element c = first_child(); c; c = c.next_sibling())
        if (c.kind() != NodeKind::element) return c.value();
    return {};
}

}  // namespace esi::xml_tree
