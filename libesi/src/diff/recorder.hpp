#pragma once
// Internal to the differ: where changes are collected while two models are walked side by side,
// and the small helpers every comparison uses (paths, value spelling, "changed from … to …").

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "esi/diff/change.hpp"
#include "esi/diff/classification.hpp"
#include "esi/model/common.hpp"
#include "esi/number.hpp"

namespace esi::diff_detail {

// A model path as a prefix, a separator and a last part, joined only when a change is recorded:
// most comparisons find nothing, and building every path string would cost more than comparing.
// A Path refers to the strings it was made from; use it within the expression that made it, or
// turn it into a std::string.
class Path {
public:
    Path(const std::string& whole) : prefix_(whole) {}  // NOLINT: implicit by design
    Path(const char* whole) : prefix_(whole) {}         // NOLINT
    Path(std::string_view prefix, std::string_view separator, std::string_view leaf)
        : prefix_(prefix), separator_(separator), leaf_(leaf) {}
    [[nodiscard]] std::string str() const;
    operator std::string() const { return str(); }  // NOLINT

private:
    std::string_view prefix_;
    std::string_view separator_;
    std::string_view leaf_;
};

class Recorder {
public:
    explicit Recorder(std::vector<Change>& out) : out_(out) {}

    // The device the following changes belong to (nullopt: the file as a whole), and how it relates
    // to the device it is compared with.
    void set_device(std::optional<DeviceRef> device, RevisionContext context) {
        device_ = std::move(device);
        context_ = context;
    }
    [[nodiscard]] RevisionContext context() const { return context_; }

    void add(ChangeKind kind, std::string path, std::optional<std::string> old_value, std::optional<std::string> new_value,
             SourcePos old_pos, SourcePos new_pos, std::string message);

    // Records "<what> changed from A to B" (or added/removed) when the spelled values differ.
    // `what` is a string, or a function returning one (called only when something is recorded).
    // Returns whether something was recorded.
    template <class What>
    bool value(ChangeKind kind, const Path& path, What&& what, const std::optional<std::string>& old_value,
               const std::optional<std::string>& new_value, SourcePos old_pos, SourcePos new_pos) {
        if (old_value == new_value) return false;
        if constexpr (std::is_invocable_v<What>)
            record_value(kind, path, std::string(what()), old_value, new_value, old_pos, new_pos);
        else
            record_value(kind, path, std::string_view(what), old_value, new_value, old_pos, new_pos);
        return true;
    }

    [[nodiscard]] std::size_t size() const { return out_.size(); }
    // Whether any change recorded after `mark` (a size()) is breaking.
    [[nodiscard]] bool breaking_since(std::size_t mark) const;

private:
    void record_value(ChangeKind kind, const Path& path, std::string_view what, const std::optional<std::string>& old_value,
                      const std::optional<std::string>& new_value, SourcePos old_pos, SourcePos new_pos);

    std::vector<Change>& out_;
    std::optional<DeviceRef> device_;
    RevisionContext context_ = RevisionContext::same_revision;
};

// ---- paths ---------------------------------------------------------------------------------
[[nodiscard]] Path child(std::string_view parent, std::string_view element);        // "a/b"
[[nodiscard]] Path attr(std::string_view element, std::string_view attribute);      // "a@b"
[[nodiscard]] std::string indexed(std::string_view element, std::string_view key);  // "a[key]"

// ---- spelling of values ----------------------------------------------------------------------
[[nodiscard]] std::string hex(std::uint64_t value, int digits = 4);  // "#x1600"
[[nodiscard]] std::optional<std::string> hex(const std::optional<std::uint32_t>& value, int digits = 4);
[[nodiscard]] std::string dec(std::uint64_t value);
[[nodiscard]] std::optional<std::string> dec(const std::optional<std::uint32_t>& value);
[[nodiscard]] std::optional<std::string> dec(const std::optional<std::int32_t>& value);
[[nodiscard]] std::optional<std::string> dec(const std::optional<std::int64_t>& value);
// xs:boolean attributes: absent means false (ETG.2000 gives no other default for these).
[[nodiscard]] std::string flag(const std::optional<bool>& value);
[[nodiscard]] std::optional<std::string> text(const std::optional<std::string>& value);
// "#x7000:01": the usual way to name an object entry.
[[nodiscard]] std::string entry_key(std::uint32_t index, std::uint32_t subindex);
[[nodiscard]] std::string quote(std::string_view text);

// Hex data compared case-insensitively; invalid data is compared as upper-cased text.
[[nodiscard]] std::string normalized_hex(const HexData& data);

// ---- shared comparisons --------------------------------------------------------------------
// Names/Comments/URLs per LcId: one change per language added, removed or changed.
void compare_texts(Recorder& r, ChangeKind kind, const std::string& path, std::string_view element, const Names& old_names,
                   const Names& new_names, SourcePos old_parent, SourcePos new_parent);

// Unmodelled XML (verbatim Extras): attributes by name, elements by name and occurrence,
// compared with same_content (attribute order does not matter).
void compare_extras(Recorder& r, const std::string& path, const Extras& old_extras, const Extras& new_extras,
                    SourcePos old_parent, SourcePos new_parent);

void compare_images(Recorder& r, const std::string& path, const Images& old_images, const Images& new_images,
                    SourcePos old_parent, SourcePos new_parent);

}  // namespace esi::diff_detail
