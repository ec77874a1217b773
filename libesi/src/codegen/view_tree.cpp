#include "codegen/view_tree.hpp"

#include <algorithm>

namespace esi::codegen {

const ViewValue* ViewValue::find(std::string_view key) const {
    if (kind != Kind::object) return nullptr;
    for (const ViewMember* m = members; m != members + size; ++m)
        if (m->key == key) return &m->value;
    return nullptr;
}

void* ViewArena::allocate(std::size_t bytes, std::size_t alignment) {
    std::size_t pad = (alignment - reinterpret_cast<std::uintptr_t>(cursor_) % alignment) % alignment;
    if (!cursor_ || pad + bytes > left_) {
        // Blocks grow geometrically (up to 4 MiB) so that a large device needs few of them.
        const std::size_t size = std::max(next_block_, bytes + alignment);
        next_block_ = std::min<std::size_t>(next_block_ * 2, 4u << 20);
        blocks_.push_back(std::make_unique_for_overwrite<std::byte[]>(size));
        cursor_ = blocks_.back().get();
        left_ = size;
        pad = (alignment - reinterpret_cast<std::uintptr_t>(cursor_) % alignment) % alignment;
    }
    void* out = cursor_ + pad;
    cursor_ += pad + bytes;
    left_ -= pad + bytes;
    used_ += pad + bytes;
    return out;
}

ViewValue ViewArena::string(std::string_view text) {
    ViewValue v;
    v.kind = ViewValue::Kind::string;
    v.size = static_cast<std::uint32_t>(text.size());
    if (text.empty()) {
        v.chars = "";
        return v;
    }
    char* out = static_cast<char*>(allocate(text.size(), 1));
    std::memcpy(out, text.data(), text.size());
    v.chars = out;
    return v;
}

std::vector<ViewMember> ViewArena::take_member_scratch() {
    if (member_scratch_.empty()) {
        std::vector<ViewMember> fresh;
        fresh.reserve(64);
        return fresh;
    }
    std::vector<ViewMember> out = std::move(member_scratch_.back());
    member_scratch_.pop_back();
    return out;
}

void ViewArena::return_member_scratch(std::vector<ViewMember>&& scratch) {
    scratch.clear();
    member_scratch_.push_back(std::move(scratch));
}

std::vector<ViewValue> ViewArena::take_item_scratch() {
    if (item_scratch_.empty()) {
        std::vector<ViewValue> fresh;
        fresh.reserve(64);
        return fresh;
    }
    std::vector<ViewValue> out = std::move(item_scratch_.back());
    item_scratch_.pop_back();
    return out;
}

void ViewArena::return_item_scratch(std::vector<ViewValue>&& scratch) {
    scratch.clear();
    item_scratch_.push_back(std::move(scratch));
}

void ObjectBuilder::add_members_of(const ViewValue& object) {
    for (const ViewMember* m = object.begin_members(); m != object.end_members(); ++m) members_.push_back(*m);
}

ViewValue ObjectBuilder::finish() {
    ViewValue v;
    v.kind = ViewValue::Kind::object;
    v.size = static_cast<std::uint32_t>(members_.size());
    v.members = arena_->copy(members_.data(), members_.size());
    members_.clear();
    return v;
}

ViewValue ListBuilder::finish() {
    ViewValue v;
    v.kind = ViewValue::Kind::list;
    v.size = static_cast<std::uint32_t>(items_.size());
    v.items = arena_->copy(items_.data(), items_.size());
    items_.clear();
    return v;
}

nlohmann::ordered_json to_json(const ViewValue& value) {
    using Json = nlohmann::ordered_json;
    switch (value.kind) {
        case ViewValue::Kind::null: return Json(nullptr);
        case ViewValue::Kind::boolean: return Json(value.boolean);
        case ViewValue::Kind::integer: return Json(value.integer);
        case ViewValue::Kind::unsigned_integer: return Json(value.unsigned_integer);
        case ViewValue::Kind::real: return Json(value.real);
        case ViewValue::Kind::string: return Json(std::string(value.text()));
        case ViewValue::Kind::list: {
            Json out = Json::array();
            auto& items = out.get_ref<Json::array_t&>();
            items.reserve(value.size);
            for (const ViewValue* item = value.begin_items(); item != value.end_items(); ++item) items.push_back(to_json(*item));
            return out;
        }
        case ViewValue::Kind::object: {
            Json out = Json::object();
            // Keys are unique by construction: appending keeps the order without ordered_map's
            // linear search per insert.
            auto& members = out.get_ref<Json::object_t&>();
            members.reserve(value.size);
            for (const ViewMember* m = value.begin_members(); m != value.end_members(); ++m)
                members.emplace_back(std::string(m->key), to_json(m->value));
            return out;
        }
    }
    return Json(nullptr);
}

ViewValue from_json(ViewArena& arena, const nlohmann::ordered_json& json) {
    using Json = nlohmann::ordered_json;
    switch (json.type()) {
        case Json::value_t::boolean: return ViewValue::of_bool(json.get<bool>());
        case Json::value_t::number_integer: return ViewValue::of_int(json.get<std::int64_t>());
        case Json::value_t::number_unsigned: return ViewValue::of_uint(json.get<std::uint64_t>());
        case Json::value_t::number_float: return ViewValue::of_real(json.get<double>());
        case Json::value_t::string: return arena.string(json.get_ref<const std::string&>());
        case Json::value_t::array: {
            ListBuilder list(arena);
            for (const auto& item : json) list.add(from_json(arena, item));
            return list.finish();
        }
        case Json::value_t::object: {
            ObjectBuilder object(arena);
            for (const auto& [key, child] : json.items()) object.add(arena.key(key), from_json(arena, child));
            return object.finish();
        }
        default: return ViewValue::null();
    }
}

}  // namespace esi::codegen
