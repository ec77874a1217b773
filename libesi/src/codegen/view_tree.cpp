#include "esi/codegen/view_tree.hpp"

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

}  // namespace esi::codegen
