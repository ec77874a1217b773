#pragma once
// The code-generation view as an immutable tree in one arena (docs/codegen.md, "The model view").
//
// Why not nlohmann::ordered_json: a 5,000-object device has about a million view values; as JSON
// each is a separate heap node (ordered_json objects look keys up linearly on every insert, and
// strings are std::strings), so building and freeing the view alone took longer than the whole
// 200 ms budget of issue 3 section 5. Here every value is 16 bytes, objects and lists are
// contiguous arrays and strings are copied once into the arena, so the view is built with a
// handful of allocations and freed at once. The --dump-model JSON is produced by converting this
// tree (to_json, codegen/view_json.hpp), so the documented output is unchanged.
//
// Public because every back end that renders templates builds its view with it: esi-gen's code
// and esi-doc's pages (esi/doc).

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace esi::codegen {

struct ViewMember;

// One value: null, boolean, signed or unsigned integer, real, string, list or object. Values are
// views into a ViewArena (or into static storage) and are copied freely.
struct ViewValue {
    enum class Kind : std::uint8_t { null, boolean, integer, unsigned_integer, real, string, list, object };

    Kind kind = Kind::null;
    std::uint32_t size = 0;  // string length, list items, object members
    union {
        bool boolean;
        std::int64_t integer;
        std::uint64_t unsigned_integer;
        double real;
        const char* chars;
        const ViewValue* items;
        const ViewMember* members;
    };

    constexpr ViewValue() : unsigned_integer(0) {}

    [[nodiscard]] static ViewValue null() { return {}; }
    [[nodiscard]] static ViewValue of_bool(bool b) {
        ViewValue v;
        v.kind = Kind::boolean;
        v.boolean = b;
        return v;
    }
    [[nodiscard]] static ViewValue of_int(std::int64_t i) {
        ViewValue v;
        v.kind = Kind::integer;
        v.integer = i;
        return v;
    }
    [[nodiscard]] static ViewValue of_uint(std::uint64_t u) {
        ViewValue v;
        v.kind = Kind::unsigned_integer;
        v.unsigned_integer = u;
        return v;
    }
    [[nodiscard]] static ViewValue of_real(double d) {
        ViewValue v;
        v.kind = Kind::real;
        v.real = d;
        return v;
    }
    // Text that outlives the view (string literals, the data-type table): not copied.
    [[nodiscard]] static ViewValue of_static(std::string_view text) {
        ViewValue v;
        v.kind = Kind::string;
        v.size = static_cast<std::uint32_t>(text.size());
        v.chars = text.data();
        return v;
    }

    [[nodiscard]] bool is_object() const { return kind == Kind::object; }
    [[nodiscard]] bool is_list() const { return kind == Kind::list; }
    [[nodiscard]] std::string_view text() const { return kind == Kind::string ? std::string_view(chars, size) : std::string_view(); }
    [[nodiscard]] const ViewValue* begin_items() const { return kind == Kind::list ? items : nullptr; }
    [[nodiscard]] const ViewValue* end_items() const { return kind == Kind::list ? items + size : nullptr; }
    [[nodiscard]] const ViewMember* begin_members() const { return kind == Kind::object ? members : nullptr; }
    [[nodiscard]] const ViewMember* end_members() const;

    // The member called `key` of an object (linear: objects are small and lookups in templates
    // are cached by position, see mustache_render.cpp); null for other kinds.
    [[nodiscard]] const ViewValue* find(std::string_view key) const;
};

// An object member. Keys are string literals of the view builders, or copied into the arena.
struct ViewMember {
    std::string_view key;
    ViewValue value;
};

inline const ViewMember* ViewValue::end_members() const { return kind == Kind::object ? members + size : nullptr; }

static_assert(sizeof(ViewValue) == 16);
static_assert(std::is_trivially_copyable_v<ViewValue> && std::is_trivially_copyable_v<ViewMember>);

// A key that outlives the view: only string literals convert implicitly; anything else must be
// copied into the arena first (ViewArena::key).
class ViewKey {
public:
    template <std::size_t N>
    consteval ViewKey(const char (&literal)[N]) : text_(literal, N - 1) {}  // NOLINT: implicit on purpose
    [[nodiscard]] static ViewKey stored(std::string_view text) { return ViewKey(text); }
    [[nodiscard]] std::string_view text() const { return text_; }

private:
    explicit ViewKey(std::string_view text) : text_(text) {}
    std::string_view text_;
};

// Owns the memory of one view: strings and the member/item arrays of finished objects and lists,
// in large blocks freed together. Builders borrow scratch vectors from it, so building a view
// allocates almost nothing per value.
class ViewArena {
public:
    ViewArena() = default;
    ViewArena(const ViewArena&) = delete;
    ViewArena& operator=(const ViewArena&) = delete;

    [[nodiscard]] ViewValue string(std::string_view text);
    [[nodiscard]] ViewKey key(std::string_view text) { return ViewKey::stored(string(text).text()); }

    template <typename T>
    [[nodiscard]] T* copy(const T* data, std::size_t count) {
        static_assert(std::is_trivially_copyable_v<T>);
        if (count == 0) return nullptr;
        T* out = static_cast<T*>(allocate(sizeof(T) * count, alignof(T)));
        std::memcpy(static_cast<void*>(out), data, sizeof(T) * count);
        return out;
    }

    [[nodiscard]] std::vector<ViewMember> take_member_scratch();
    void return_member_scratch(std::vector<ViewMember>&& scratch);
    [[nodiscard]] std::vector<ViewValue> take_item_scratch();
    void return_item_scratch(std::vector<ViewValue>&& scratch);

    [[nodiscard]] std::size_t bytes_used() const { return used_; }

private:
    void* allocate(std::size_t bytes, std::size_t alignment);

    std::vector<std::unique_ptr<std::byte[]>> blocks_;
    std::byte* cursor_ = nullptr;
    std::size_t left_ = 0;
    std::size_t next_block_ = 64 * 1024;
    std::size_t used_ = 0;
    std::vector<std::vector<ViewMember>> member_scratch_;
    std::vector<std::vector<ViewValue>> item_scratch_;
};

namespace view_detail {
template <typename T>
ViewValue to_value(ViewArena& arena, const T& value) {
    using U = std::remove_cvref_t<T>;
    if constexpr (std::is_same_v<U, ViewValue>) {
        return value;
    } else if constexpr (std::is_same_v<U, bool>) {
        return ViewValue::of_bool(value);
    } else if constexpr (std::is_integral_v<U> && std::is_signed_v<U>) {
        return ViewValue::of_int(value);
    } else if constexpr (std::is_integral_v<U>) {
        return ViewValue::of_uint(value);
    } else if constexpr (std::is_floating_point_v<U>) {
        return ViewValue::of_real(value);
    } else if constexpr (std::is_same_v<U, std::nullptr_t>) {
        return ViewValue::null();
    } else if constexpr (std::is_convertible_v<const U&, std::string_view>) {
        return arena.string(std::string_view(value));
    } else {
        static_assert(sizeof(U) == 0, "no view value for this type");
    }
}
}  // namespace view_detail

// Builds one object; members keep the order they are added in (the documented key order).
class ObjectBuilder {
public:
    explicit ObjectBuilder(ViewArena& arena) : arena_(&arena), members_(arena.take_member_scratch()) {}
    ~ObjectBuilder() {
        if (arena_) arena_->return_member_scratch(std::move(members_));
    }
    ObjectBuilder(const ObjectBuilder&) = delete;
    ObjectBuilder& operator=(const ObjectBuilder&) = delete;

    // Adds a member; strings are copied into the arena (use ViewValue::of_static for literals).
    template <typename T>
    void add(ViewKey key, const T& value) {
        members_.push_back({key.text(), view_detail::to_value(*arena_, value)});
    }
    // std::optional numbers: null when absent.
    template <typename T>
    void add(ViewKey key, const std::optional<T>& value) {
        members_.push_back({key.text(), value ? view_detail::to_value(*arena_, *value) : ViewValue::null()});
    }
    // Copies every member of an object (e.g. the document's root fields into a device context).
    void add_members_of(const ViewValue& object);

    [[nodiscard]] ViewArena& arena() const { return *arena_; }
    [[nodiscard]] ViewValue finish();

private:
    ViewArena* arena_;
    std::vector<ViewMember> members_;
};

// Builds one list.
class ListBuilder {
public:
    explicit ListBuilder(ViewArena& arena) : arena_(&arena), items_(arena.take_item_scratch()) {}
    ~ListBuilder() {
        if (arena_) arena_->return_item_scratch(std::move(items_));
    }
    ListBuilder(const ListBuilder&) = delete;
    ListBuilder& operator=(const ListBuilder&) = delete;

    template <typename T>
    void add(const T& value) {
        items_.push_back(view_detail::to_value(*arena_, value));
    }
    [[nodiscard]] ViewArena& arena() const { return *arena_; }
    [[nodiscard]] std::size_t size() const { return items_.size(); }
    [[nodiscard]] const ViewValue& back() const { return items_.back(); }
    [[nodiscard]] bool empty() const { return items_.empty(); }
    [[nodiscard]] ViewValue finish();

private:
    ViewArena* arena_;
    std::vector<ViewValue> items_;
};

}  // namespace esi::codegen
