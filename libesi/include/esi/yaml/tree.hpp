#pragma once
// A YAML document as libesi reads it (device sources, .esi-lint.yaml): a compact tree built in
// one pass over libyaml's event stream, fast enough for the esi-gen budget of 200 ms for a
// 5,000-object source (docs/performance.md).
//
// The same pass enforces what a node API cannot see or would make expensive:
//  - nesting depth;
//  - the node count after anchor/alias expansion: an alias shares the anchored subtree instead of
//    copying it, so a "billion laughs" file is small to parse but exponential to walk. Every alias
//    adds the size of its anchored subtree to the count, and the first alias that crosses the
//    limit stops the parse with its position;
//  - duplicate mapping keys (YAML forbids them; many parsers keep the first or the last silently);
//  - exactly one document.
// Positions are 1-based line:column (columns count code points), as everywhere in libesi.

#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "esi/diagnostic.hpp"

namespace esi::yaml {

struct TreeNode {
    enum class Kind : std::uint8_t { null, scalar, map, sequence };
    Kind kind = Kind::null;
    bool quoted = false;  // a quoted or block scalar, or one tagged !!str: always text
    SourcePos pos;        // where the node starts
    SourcePos end;        // where it ends (exclusive)
    std::string value;    // scalar text after YAML unescaping/folding
    std::vector<const TreeNode*> items;  // map: key, value, key, value …; sequence: the items
};

struct TreeLimits {
    std::size_t max_depth = 64;
    std::uint64_t max_nodes = 1'000'000;  // after alias expansion
};

class Tree {
public:
    // Parses one YAML document. Returns null (with diagnostics) when the text is not YAML, breaks
    // a bound, or holds no document; `empty` tells the last case apart.
    static std::unique_ptr<Tree> parse(std::string_view text, const std::string& path, const TreeLimits& limits,
                                       Diagnostics& diagnostics, bool& empty);

    [[nodiscard]] const TreeNode* root() const { return root_; }
    [[nodiscard]] std::uint64_t expanded_nodes() const { return expanded_; }

private:
    friend class TreeBuilder;
    std::deque<TreeNode> nodes_;  // stable addresses
    const TreeNode* root_ = nullptr;
    std::uint64_t expanded_ = 0;
};

// A read-only view of a tree node (IsMap, Scalar, iteration over items or key/value pairs).
// A default-constructed Node is "not defined".
class Node {
public:
    struct Pair;
    class Iterator;

    Node() = default;
    explicit Node(const TreeNode* node) : node_(node) {}

    [[nodiscard]] bool IsDefined() const { return node_ != nullptr; }
    [[nodiscard]] bool IsNull() const { return node_ && node_->kind == TreeNode::Kind::null; }
    [[nodiscard]] bool IsScalar() const { return node_ && node_->kind == TreeNode::Kind::scalar; }
    [[nodiscard]] bool IsMap() const { return node_ && node_->kind == TreeNode::Kind::map; }
    [[nodiscard]] bool IsSequence() const { return node_ && node_->kind == TreeNode::Kind::sequence; }
    [[nodiscard]] const std::string& Scalar() const;
    [[nodiscard]] bool quoted() const { return node_ && node_->quoted; }
    [[nodiscard]] SourcePos pos() const { return node_ ? node_->pos : SourcePos{}; }
    [[nodiscard]] SourcePos end_pos() const { return node_ ? node_->end : SourcePos{}; }
    [[nodiscard]] std::size_t size() const;  // entries of a map, items of a sequence
    [[nodiscard]] const TreeNode* get() const { return node_; }

    // Sequences iterate their items (`*it`); maps iterate key/value pairs (`it->first`, `it->second`).
    [[nodiscard]] Iterator begin() const;
    [[nodiscard]] Iterator end() const;

    // An empty mapping, for `coe: true` read as "CoE with no settings".
    [[nodiscard]] static Node empty_map();

private:
    const TreeNode* node_ = nullptr;
};

struct Node::Pair {
    Node first;
    Node second;
};

class Node::Iterator {
public:
    Iterator(const TreeNode* parent, std::size_t index) : parent_(parent), index_(index) {}
    Node operator*() const { return Node(parent_->items[index_]); }
    const Pair* operator->() const {
        pair_ = Pair{Node(parent_->items[index_]), Node(parent_->items[index_ + 1])};
        return &pair_;
    }
    Iterator& operator++() {
        index_ += parent_->kind == TreeNode::Kind::map ? 2 : 1;
        return *this;
    }
    bool operator!=(const Iterator& other) const { return index_ != other.index_ || parent_ != other.parent_; }
    bool operator==(const Iterator& other) const { return !(*this != other); }

private:
    const TreeNode* parent_;
    std::size_t index_;
    mutable Pair pair_;
};

}  // namespace esi::yaml
