// Completion in a YAML device source: object references in a PDO's `entries` and an InitCmd's
// `object`, type names in `type`, `base_type` and `data_type`. The source is rarely valid YAML
// while it is typed, so the place is read from the cursor's line.

#include <cctype>
#include <set>
#include <string>

#include "navigate/format.hpp"
#include "navigate/index.hpp"

namespace esi::navigate {

namespace {

enum class YamlSlot { none, object, data_type };

bool is_token_char(char c) { return c != ' ' && c != '\t' && c != '[' && c != ',' && c != '{' && c != '"' && c != '\''; }

// The key whose value the cursor types on this line ("type" in "{ name: x, type: UI|"), and
// whether the cursor is inside a flow sequence opened after it ("entries: [0x6000, |").
YamlSlot slot_of(std::string_view line_to_cursor) {
    const auto after_key = [&](std::string_view key) -> std::size_t {
        std::size_t best = std::string_view::npos;
        for (std::size_t at = line_to_cursor.find(key); at != std::string_view::npos; at = line_to_cursor.find(key, at + 1)) {
            const bool starts = at == 0 || (!std::isalnum(static_cast<unsigned char>(line_to_cursor[at - 1])) &&
                                             line_to_cursor[at - 1] != '_');
            if (starts) best = at + key.size();
        }
        return best;
    };
    // The last key on the line before the cursor decides.
    std::size_t last = 0;
    YamlSlot slot = YamlSlot::none;
    const auto consider = [&](std::string_view key, YamlSlot meaning) {
        const std::size_t at = after_key(key);
        if (at != std::string_view::npos && at >= last) {
            last = at;
            slot = meaning;
        }
    };
    consider("entries:", YamlSlot::object);
    consider("object:", YamlSlot::object);
    consider("type:", YamlSlot::data_type);
    consider("base_type:", YamlSlot::data_type);
    consider("data_type:", YamlSlot::data_type);
    if (slot == YamlSlot::none) return slot;
    // Another key after the value ("type: UINT, access: |") ends the slot; a value's own ':'
    // ("0x6000:1") does not, and entries' items follow commas.
    const std::string_view rest = line_to_cursor.substr(last);
    for (std::size_t i = 0; i + 1 < rest.size(); ++i)
        if (rest[i] == ':' && rest[i + 1] == ' ') return YamlSlot::none;
    if (slot == YamlSlot::data_type && rest.find(',') != std::string_view::npos) return YamlSlot::none;
    return slot;
}

}  // namespace

std::vector<CompletionItem> complete_yaml(const Index& index, std::size_t offset) {
    std::vector<CompletionItem> out;
    const std::string_view text = index.text;
    const Position position = index.lines.position_of(offset);
    const std::size_t line_start = *index.lines.offset_of(Position{position.line, 0});
    std::string_view line = text.substr(line_start, offset - line_start);
    YamlSlot slot = slot_of(line);
    // A block sequence item ("      - 0x60") under `entries:` on a line above: walk up over the
    // sibling items to the key that holds them.
    if (slot == YamlSlot::none) {
        const std::size_t first = line.find_first_not_of(' ');
        std::size_t above_start = line_start;
        bool item = first != std::string_view::npos && line[first] == '-';
        while (item && above_start > 0) {
            const std::size_t above_end = above_start - 1;  // the line's '\n'
            const std::size_t before = above_end == 0 ? std::string_view::npos : text.rfind('\n', above_end - 1);
            above_start = before == std::string_view::npos ? 0 : before + 1;
            const std::string_view above = text.substr(above_start, above_end - above_start);
            const std::size_t indent = above.find_first_not_of(' ');
            if (indent == std::string_view::npos) continue;  // a blank line
            if (above[indent] == '-') continue;              // a sibling item
            if (above.find("entries:") != std::string_view::npos) slot = YamlSlot::object;
            item = false;
        }
    }
    if (slot == YamlSlot::none) return out;
    std::size_t begin = offset;
    while (begin > line_start && is_token_char(text[begin - 1])) --begin;
    if (slot == YamlSlot::data_type)
        while (begin > line_start && text[begin - 1] != ':' && text[begin - 1] != '"') --begin;
    while (begin < offset && text[begin] == ' ') ++begin;
    std::size_t end = offset;
    while (end < text.size() && is_token_char(text[end]) && text[end] != '\n' && text[end] != ']' && text[end] != '}') ++end;
    const Range replace = index.lines.range_of(begin, end);

    const auto scope_number = index.scope_at(offset);
    const Scope* scope = scope_number ? &index.scopes[*scope_number] : nullptr;
    if (slot == YamlSlot::object) {
        if (!scope) return out;
        for (const ObjectDef& object : scope->objects) {
            std::string label = format_index(object.index, true);
            out.push_back(CompletionItem{label, CompletionKind::object, object.name, label, replace});
            const DataTypeDef* type = scope->find_data_type(object.type);
            if (!type) continue;
            for (const SubItemDef& item : type->sub_items) {
                if (!item.subindex || *item.subindex == 0) continue;
                std::string sub = label + ":" + std::to_string(*item.subindex);
                // Quoted: a plain "0x6000:1" is not one scalar in every YAML reader's flow context.
                out.push_back(CompletionItem{sub, CompletionKind::object, item.name, "\"" + sub + "\"", replace});
            }
        }
        return out;
    }
    // Types the source declares itself (derived ones are named after objects, never typed),
    // then the basic types.
    std::set<std::string_view> seen;
    if (scope)
        for (const DataTypeDef& type : scope->data_types)
            if (!type.decl.empty() && seen.insert(type.name).second)
                out.push_back(CompletionItem{type.name, CompletionKind::data_type, bits_text(type.bit_size), type.name, replace});
    add_basic_types(replace, seen, out);
    return out;
}

}  // namespace esi::navigate
