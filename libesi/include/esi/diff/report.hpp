#pragma once
// The diff report, rendered three ways: readable text grouped by device (most severe first),
// JSON for machines, and Markdown for a pull-request comment (esi-diff --format). All are
// deterministic.

#include <string>

#include "esi/diff/diff.hpp"

namespace esi {

struct DiffLabels {
    std::string old_path;  // as the user named the files; used in positions
    std::string new_path;
};

[[nodiscard]] std::string render_diff_text(const DiffResult& result, const DiffLabels& labels);

// {verdict, changes:[{device:{name, product_code, revision}|null, path, kind, class, old, new,
//  old_pos:{line, column}|null, new_pos, message}]}; product code and revision are numbers.
[[nodiscard]] std::string render_diff_json(const DiffResult& result);

[[nodiscard]] std::string render_diff_markdown(const DiffResult& result, const DiffLabels& labels);

}  // namespace esi
