// The JSON report of esi-diff, exactly the shape of issue 4 §1:
// {verdict, changes:[{device:{name, product_code, revision}, path, kind, class, old, new, old_pos,
// new_pos, message}]}. Product code and revision are numbers; absent values are null.

#include <nlohmann/json.hpp>

#include "esi/diff/classification.hpp"
#include "esi/diff/report.hpp"

namespace esi {

namespace {

using ordered_json = nlohmann::ordered_json;

ordered_json position(SourcePos pos) {
    if (!pos.known()) return nullptr;
    ordered_json j;
    j["line"] = pos.line;
    j["column"] = pos.column;
    return j;
}

ordered_json optional_text(const std::optional<std::string>& s) {
    if (!s) return nullptr;
    return *s;
}

ordered_json optional_number(const std::optional<std::uint32_t>& n) {
    if (!n) return nullptr;
    return *n;
}

}  // namespace

std::string render_diff_json(const DiffResult& result) {
    ordered_json root;
    root["verdict"] = std::string(to_string(result.verdict));
    ordered_json changes = ordered_json::array();
    for (const auto& c : result.changes) {
        ordered_json j;
        if (c.device) {
            ordered_json d;
            d["name"] = c.device->name;
            d["product_code"] = optional_number(c.device->product_code);
            d["revision"] = optional_number(c.device->revision);
            j["device"] = d;
        } else {
            j["device"] = nullptr;
        }
        j["path"] = c.path;
        j["kind"] = std::string(to_string(c.kind));
        j["class"] = std::string(to_string(c.change_class));
        j["old"] = optional_text(c.old_value);
        j["new"] = optional_text(c.new_value);
        j["old_pos"] = position(c.old_pos);
        j["new_pos"] = position(c.new_pos);
        j["message"] = c.message;
        changes.push_back(std::move(j));
    }
    root["changes"] = std::move(changes);
    // Invalid UTF-8 from a badly encoded file must not make the dump throw.
    return root.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

}  // namespace esi
