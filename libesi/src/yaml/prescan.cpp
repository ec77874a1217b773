#include "yaml/prescan.hpp"

#include <sstream>
#include <unordered_map>
#include <vector>

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/exceptions.h>
#include <yaml-cpp/mark.h>
#include <yaml-cpp/parser.h>

#include "yaml/yaml_reader.hpp"

namespace esi::yaml {

namespace {

// Thrown inside the handler to stop the parser at the first fatal finding; never leaves prescan().
struct StopScan {};

class ScanHandler final : public YAML::EventHandler {
public:
    ScanHandler(const std::string& path, const PrescanLimits& limits, Diagnostics& diagnostics)
        : path_(path), limits_(limits), diagnostics_(diagnostics) {}

    void OnDocumentStart(const YAML::Mark&) override {}
    void OnDocumentEnd() override {}

    void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override { leaf(mark, anchor, nullptr); }
    void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor, const std::string& value) override {
        leaf(mark, anchor, &value);
    }
    void OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) override {
        const auto it = anchor_sizes_.find(anchor);
        // An alias to an anchor that is still open (a recursive structure) has no finite size.
        const std::uint64_t size = it != anchor_sizes_.end() ? it->second : limits_.max_nodes + 1;
        begin_node(mark, nullptr);
        add(size, mark, true);
        end_node(size, 0);
    }
    void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor, YAML::EmitterStyle::value) override {
        open(mark, anchor, false);
    }
    void OnSequenceEnd() override { close(); }
    void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor, YAML::EmitterStyle::value) override {
        open(mark, anchor, true);
    }
    void OnMapEnd() override { close(); }

    [[nodiscard]] std::uint64_t total() const { return total_; }

private:
    struct Frame {
        bool is_map = false;
        bool expecting_key = true;
        YAML::anchor_t anchor = 0;
        std::uint64_t size = 1;  // this node plus its expanded children
        std::unordered_map<std::string, YAML::Mark> keys;
    };

    void error(const YAML::Mark& mark, std::string rule, std::string message) {
        diagnostics_.emplace(Severity::error, std::move(rule), std::move(message), path_, pos_of(mark));
    }

    // A node begins inside the innermost collection: record a key when it is one.
    void begin_node(const YAML::Mark& mark, const std::string* scalar) {
        if (stack_.empty()) return;
        Frame& parent = stack_.back();
        if (!parent.is_map || !parent.expecting_key || !scalar) return;
        const auto [it, inserted] = parent.keys.emplace(*scalar, mark);
        if (!inserted) {
            Diagnostic& d = diagnostics_.emplace(Severity::error, "yaml-duplicate-key",
                                                 "duplicate key '" + *scalar + "': a key may appear once in a mapping",
                                                 path_, pos_of(mark));
            d.notes.push_back({path_, pos_of(it->second), "first given here"});
        }
    }

    // A node ended: its expanded size goes to its parent, and keys alternate with values.
    void end_node(std::uint64_t size, YAML::anchor_t anchor) {
        if (anchor != 0) anchor_sizes_[anchor] = size;
        if (stack_.empty()) return;
        Frame& parent = stack_.back();
        parent.size = saturating_add(parent.size, size);
        if (parent.is_map) parent.expecting_key = !parent.expecting_key;
    }

    void leaf(const YAML::Mark& mark, YAML::anchor_t anchor, const std::string* scalar) {
        begin_node(mark, scalar);
        add(1, mark, false);
        end_node(1, anchor);
    }

    void open(const YAML::Mark& mark, YAML::anchor_t anchor, bool is_map) {
        begin_node(mark, nullptr);
        add(1, mark, false);
        if (stack_.size() + 1 > limits_.max_depth) {
            error(mark, "yaml-nesting-depth",
                  "nesting deeper than " + std::to_string(limits_.max_depth) + " levels; a device source never needs that many");
            throw StopScan{};
        }
        Frame f;
        f.is_map = is_map;
        f.anchor = anchor;
        stack_.push_back(std::move(f));
    }

    void close() {
        if (stack_.empty()) return;
        const std::uint64_t size = stack_.back().size;
        const YAML::anchor_t anchor = stack_.back().anchor;
        stack_.pop_back();
        end_node(size, anchor);
    }

    static std::uint64_t saturating_add(std::uint64_t a, std::uint64_t b) {
        const std::uint64_t sum = a + b;
        return sum < a ? UINT64_MAX : sum;
    }

    // Counts nodes as a full (alias-expanded) walk would visit them.
    void add(std::uint64_t count, const YAML::Mark& mark, bool through_alias) {
        total_ = saturating_add(total_, count);
        if (total_ <= limits_.max_nodes) return;
        if (through_alias)
            error(mark, "yaml-alias-expansion",
                  "alias expansion exceeds " + std::to_string(limits_.max_nodes) +
                      " nodes at this alias (an anchor/alias bomb such as \"billion laughs\"); anchors may be reused, "
                      "but not nested into exponential growth");
        else
            error(mark, "yaml-too-large", "the document has more than " + std::to_string(limits_.max_nodes) + " nodes");
        throw StopScan{};
    }

    const std::string& path_;
    const PrescanLimits& limits_;
    Diagnostics& diagnostics_;
    std::vector<Frame> stack_;
    std::unordered_map<YAML::anchor_t, std::uint64_t> anchor_sizes_;
    std::uint64_t total_ = 0;
};

// A handler that only notices that a second document exists.
class CountHandler final : public YAML::EventHandler {
public:
    void OnDocumentStart(const YAML::Mark& mark) override { start = mark; }
    void OnDocumentEnd() override {}
    void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
    void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
    void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t, const std::string&) override {}
    void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
    void OnSequenceEnd() override {}
    void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
    void OnMapEnd() override {}
    YAML::Mark start;
};

}  // namespace

PrescanResult prescan(std::string_view text, const std::string& path, const PrescanLimits& limits, Diagnostics& diagnostics) {
    PrescanResult result;
    std::istringstream in{std::string(text)};
    YAML::Parser parser(in);
    ScanHandler handler(path, limits, diagnostics);
    try {
        if (!parser.HandleNextDocument(handler)) {
            result.empty = true;
            result.ok = true;
            return result;
        }
        CountHandler second;
        if (parser.HandleNextDocument(second)) {
            diagnostics.emplace(Severity::error, "yaml-syntax",
                                "a device source holds one YAML document; this is a second one ('---')", path,
                                pos_of(second.start));
            return result;
        }
    } catch (const StopScan&) {
        return result;
    } catch (const YAML::Exception& e) {
        diagnostics.emplace(Severity::error, "yaml-syntax", "YAML syntax: " + e.msg, path, pos_of(e.mark));
        return result;
    }
    // Duplicate keys are errors, but the tree is still safe to walk for further findings.
    result.expanded_nodes = handler.total();
    result.ok = true;
    return result;
}

}  // namespace esi::yaml
