#pragma once
// Semantic comparison of two XML documents, for the writer's losslessness checks: elements and
// attributes by name, values by meaning (numbers by value, so "#x10" == "16"; booleans as 1/0, so
// "true" == "1"; hexBinary case- and whitespace-insensitive; text trimmed) and the children of
// each element as a multiset (order-insensitive). Comments and processing instructions are not
// compared (the model does not keep them).

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace esi::test {

struct TreeDifference {
    enum class Kind { missing_element, added_element, missing_attribute, added_attribute, changed_attribute, changed_text };
    Kind kind;
    std::string path;    // element names from the root, '/'-separated (no indices)
    std::string detail;  // attribute name, or the values that differ
    std::uint32_t line = 0;  // in the first document (0 for added items)
};

[[nodiscard]] std::string_view to_string(TreeDifference::Kind kind);

struct TreeComparison {
    bool parsed = false;  // both documents well-formed
    std::string error;
    std::vector<TreeDifference> differences;
};

// `original` and `rewritten` are UTF-8 XML texts. Reports at most `limit` differences.
[[nodiscard]] TreeComparison compare_xml_trees(std::string_view original, std::string_view rewritten, std::size_t limit = 200);

}  // namespace esi::test
