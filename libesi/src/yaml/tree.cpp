#include "esi/yaml/tree.hpp"

#include <unordered_map>

#include <yaml.h>

namespace esi::yaml {

namespace {

const TreeNode empty_map_node = [] {
    TreeNode n;
    n.kind = TreeNode::Kind::map;
    return n;
}();

SourcePos pos_of(const yaml_mark_t& mark) {
    return SourcePos{static_cast<std::uint32_t>(mark.line) + 1u, static_cast<std::uint32_t>(mark.column) + 1u};
}

bool is_null_scalar(const yaml_event_t& e) {
    if (e.data.scalar.style != YAML_PLAIN_SCALAR_STYLE) return false;
    if (e.data.scalar.tag) return false;
    const std::string_view v(reinterpret_cast<const char*>(e.data.scalar.value), e.data.scalar.length);
    return v.empty() || v == "~" || v == "null" || v == "Null" || v == "NULL";
}

}  // namespace

const std::string& Node::Scalar() const {
    static const std::string empty;
    return node_ && node_->kind == TreeNode::Kind::scalar ? node_->value : empty;
}

std::size_t Node::size() const {
    if (!node_) return 0;
    if (node_->kind == TreeNode::Kind::map) return node_->items.size() / 2;
    if (node_->kind == TreeNode::Kind::sequence) return node_->items.size();
    return 0;
}

Node::Iterator Node::begin() const { return Iterator(node_ ? node_ : &empty_map_node, 0); }
Node::Iterator Node::end() const { return Iterator(node_ ? node_ : &empty_map_node, node_ ? node_->items.size() : 0); }
Node Node::empty_map() { return Node(&empty_map_node); }

// Builds the tree from libyaml events; see tree.hpp for what it enforces.
class TreeBuilder {
public:
    TreeBuilder(Tree& tree, const std::string& path, const TreeLimits& limits, Diagnostics& diagnostics)
        : tree_(tree), path_(path), limits_(limits), diagnostics_(diagnostics) {}

    // false: stop (a diagnostic was reported).
    bool on_event(const yaml_event_t& e) {
        switch (e.type) {
            case YAML_SCALAR_EVENT: {
                TreeNode& n = make(e.start_mark, e.end_mark);
                if (is_null_scalar(e)) {
                    n.kind = TreeNode::Kind::null;
                } else {
                    n.kind = TreeNode::Kind::scalar;
                    n.value.assign(reinterpret_cast<const char*>(e.data.scalar.value), e.data.scalar.length);
                    const std::string_view tag = e.data.scalar.tag ? reinterpret_cast<const char*>(e.data.scalar.tag) : "";
                    n.quoted = e.data.scalar.style != YAML_PLAIN_SCALAR_STYLE || tag == YAML_STR_TAG;
                }
                return leaf(n, e.data.scalar.anchor, 1, e.start_mark, false);
            }
            case YAML_ALIAS_EVENT: {
                const std::string anchor(reinterpret_cast<const char*>(e.data.alias.anchor));
                const auto it = anchors_.find(anchor);
                if (it == anchors_.end()) {
                    error(e.start_mark, "yaml-syntax", "alias *" + anchor + " names no anchor defined before it");
                    return false;
                }
                return leaf(*it->second.node, nullptr, it->second.size, e.start_mark, true);
            }
            case YAML_SEQUENCE_START_EVENT:
                return open(e, TreeNode::Kind::sequence, e.data.sequence_start.anchor);
            case YAML_MAPPING_START_EVENT:
                return open(e, TreeNode::Kind::map, e.data.mapping_start.anchor);
            case YAML_SEQUENCE_END_EVENT:
            case YAML_MAPPING_END_EVENT:
                return close(e.end_mark);
            case YAML_DOCUMENT_START_EVENT:
                if (documents_++ > 0) {
                    error(e.start_mark, "yaml-syntax", "a device source holds one YAML document; this is a second one");
                    return false;
                }
                return true;
            default:
                return true;
        }
    }

private:
    struct Frame {
        TreeNode* node = nullptr;
        std::string anchor;
        std::uint64_t size = 1;
        bool expecting_key = true;
        std::unordered_map<std::string, SourcePos> keys;
    };
    struct Anchor {
        const TreeNode* node = nullptr;
        std::uint64_t size = 1;
    };

    void error(const yaml_mark_t& mark, std::string rule, std::string message) {
        diagnostics_.emplace(Severity::error, std::move(rule), std::move(message), path_, pos_of(mark));
    }

    TreeNode& make(const yaml_mark_t& start, const yaml_mark_t& end) {
        TreeNode& n = tree_.nodes_.emplace_back();
        n.pos = pos_of(start);
        n.end = pos_of(end);
        return n;
    }

    // Counts nodes as a full walk would visit them, aliases expanded.
    bool count(std::uint64_t nodes, const yaml_mark_t& mark, bool through_alias) {
        tree_.expanded_ += nodes;
        if (tree_.expanded_ <= limits_.max_nodes) return true;
        if (through_alias)
            error(mark, "yaml-alias-expansion",
                  "alias expansion exceeds " + std::to_string(limits_.max_nodes) +
                      " nodes at this alias (an anchor/alias bomb such as \"billion laughs\"); anchors may be reused, "
                      "but not nested into exponential growth");
        else
            error(mark, "yaml-too-large", "the document has more than " + std::to_string(limits_.max_nodes) + " nodes");
        return false;
    }

    // A node is complete: attach it to its parent (checking keys), account for its size.
    void attach(const TreeNode& n, std::uint64_t size) {
        if (stack_.empty()) {
            if (!tree_.root_) tree_.root_ = &n;
            return;
        }
        Frame& parent = stack_.back();
        if (parent.node->kind == TreeNode::Kind::map && parent.expecting_key && n.kind == TreeNode::Kind::scalar) {
            const auto [it, inserted] = parent.keys.emplace(n.value, n.pos);
            if (!inserted) {
                Diagnostic& d = diagnostics_.emplace(Severity::error, "yaml-duplicate-key",
                                                     "duplicate key '" + n.value + "': a key may appear once in a mapping", path_,
                                                     n.pos);
                d.notes.push_back({path_, it->second, "first given here"});
            }
        }
        if (parent.node->kind == TreeNode::Kind::map) parent.expecting_key = !parent.expecting_key;
        parent.node->items.push_back(&n);
        parent.size += size;
        if (parent.size > limits_.max_nodes) parent.size = limits_.max_nodes + 1;
    }

    bool leaf(const TreeNode& n, const yaml_char_t* anchor, std::uint64_t size, const yaml_mark_t& mark, bool through_alias) {
        if (!count(size, mark, through_alias)) return false;
        if (anchor) anchors_[reinterpret_cast<const char*>(anchor)] = Anchor{&n, 1};
        attach(n, size);
        return true;
    }

    bool open(const yaml_event_t& e, TreeNode::Kind kind, const yaml_char_t* anchor) {
        if (!count(1, e.start_mark, false)) return false;
        if (stack_.size() + 1 > limits_.max_depth) {
            error(e.start_mark, "yaml-nesting-depth",
                  "nesting deeper than " + std::to_string(limits_.max_depth) + " levels; a device source never needs that many");
            return false;
        }
        TreeNode& n = make(e.start_mark, e.end_mark);
        n.kind = kind;
        Frame f;
        f.node = &n;
        if (anchor) f.anchor = reinterpret_cast<const char*>(anchor);
        stack_.push_back(std::move(f));
        return true;
    }

    bool close(const yaml_mark_t& end) {
        if (stack_.empty()) return true;
        Frame f = std::move(stack_.back());
        stack_.pop_back();
        f.node->end = pos_of(end);
        if (!f.anchor.empty()) anchors_[f.anchor] = Anchor{f.node, f.size};
        attach(*f.node, f.size);
        return true;
    }

    Tree& tree_;
    const std::string& path_;
    const TreeLimits& limits_;
    Diagnostics& diagnostics_;
    std::vector<Frame> stack_;
    std::unordered_map<std::string, Anchor> anchors_;
    int documents_ = 0;
};

std::unique_ptr<Tree> Tree::parse(std::string_view text, const std::string& path, const TreeLimits& limits,
                                  Diagnostics& diagnostics, bool& empty) {
    empty = false;
    auto tree = std::make_unique<Tree>();
    TreeBuilder builder(*tree, path, limits, diagnostics);
    yaml_parser_t parser;
    if (!yaml_parser_initialize(&parser)) {
        diagnostics.emplace(Severity::error, "yaml-internal", "cannot initialise the YAML parser", path, SourcePos{});
        return nullptr;
    }
    yaml_parser_set_input_string(&parser, reinterpret_cast<const unsigned char*>(text.data()), text.size());
    yaml_parser_set_encoding(&parser, YAML_UTF8_ENCODING);
    bool ok = true;
    for (;;) {
        yaml_event_t event;
        if (!yaml_parser_parse(&parser, &event)) {
            std::string message = "YAML syntax: ";
            message += parser.problem ? parser.problem : "malformed input";
            if (parser.context) message += std::string(" ") + parser.context;
            SourcePos pos;
            if (parser.error == YAML_READER_ERROR) {
                // Encoding problems carry a byte offset instead of a mark.
                pos = SourcePos{1, 1};
                for (std::size_t i = 0; i < parser.problem_offset && i < text.size(); ++i) {
                    if (text[i] == '\n') pos = SourcePos{pos.line + 1, 1};
                    else if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) ++pos.column;
                }
            } else {
                pos = parser.problem_mark.line || parser.problem_mark.column || parser.problem_mark.index ? pos_of(parser.problem_mark)
                                                                                                           : pos_of(parser.context_mark);
            }
            diagnostics.emplace(Severity::error, "yaml-syntax", message, path, pos);
            ok = false;
            break;
        }
        const bool done = event.type == YAML_STREAM_END_EVENT;
        const bool keep_going = builder.on_event(event);
        yaml_event_delete(&event);
        if (!keep_going) {
            ok = false;
            break;
        }
        if (done) break;
    }
    yaml_parser_delete(&parser);
    if (!ok) return nullptr;
    if (!tree->root_) {
        empty = true;
        return nullptr;
    }
    // Duplicate keys are errors, but the tree is still safe to walk for further findings.
    return tree;
}

}  // namespace esi::yaml
