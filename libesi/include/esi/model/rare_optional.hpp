#pragma once
// An optional field that is usually absent, kept behind a pointer so that the element holding it
// stays small. It reads and writes like std::optional (has_value, *, ->, value_or, = value,
// = std::nullopt, ==), with value semantics: copying copies the value.
//
// Why: a dictionary is mostly Object/Info/SubItem, DataType/SubItem and Flags elements, tens of
// thousands of them in a vendor catalogue, and most of their typed fields (limits, restrictions,
// a default string) are absent in all but a few. Inline, each such std::optional<std::string>
// costs 40 bytes and a std::optional<HexData> 48 whether set or not; here 8, and the value's own
// size only where it is set.

#include <concepts>
#include <memory>
#include <optional>
#include <type_traits>
#include <utility>

namespace esi {

template <typename T>
class RareOptional {
public:
    using value_type = T;

    RareOptional() noexcept = default;
    RareOptional(std::nullopt_t) noexcept {}  // NOLINT(google-explicit-constructor): like std::optional
    template <typename U = T>
        requires(std::is_constructible_v<T, U &&> && !std::is_same_v<std::remove_cvref_t<U>, RareOptional> &&
                 !std::is_same_v<std::remove_cvref_t<U>, std::nullopt_t> &&
                 !std::is_same_v<std::remove_cvref_t<U>, std::in_place_t>)
    RareOptional(U&& value)  // NOLINT(google-explicit-constructor): like std::optional
        : value_(std::make_unique<T>(std::forward<U>(value))) {}
    // From a std::optional, taken by value: a temporary's value is moved in, not copied.
    template <typename U>
        requires std::is_constructible_v<T, U &&>
    RareOptional(std::optional<U> value) {  // NOLINT(google-explicit-constructor)
        if (value) value_ = std::make_unique<T>(std::move(*value));
    }

    RareOptional(const RareOptional& other) : value_(other.value_ ? std::make_unique<T>(*other.value_) : nullptr) {}
    RareOptional(RareOptional&&) noexcept = default;
    RareOptional& operator=(const RareOptional& other) {
        if (this != &other) value_ = other.value_ ? std::make_unique<T>(*other.value_) : nullptr;
        return *this;
    }
    RareOptional& operator=(RareOptional&&) noexcept = default;
    RareOptional& operator=(std::nullopt_t) noexcept {
        value_.reset();
        return *this;
    }
    template <typename U = T>
        requires(std::is_constructible_v<T, U &&> && std::is_assignable_v<T&, U &&> &&
                 !std::is_same_v<std::remove_cvref_t<U>, RareOptional> &&
                 !std::is_same_v<std::remove_cvref_t<U>, std::nullopt_t>)
    RareOptional& operator=(U&& value) {
        if (value_) {
            *value_ = std::forward<U>(value);
        } else {
            value_ = std::make_unique<T>(std::forward<U>(value));
        }
        return *this;
    }
    template <typename U>
        requires std::is_constructible_v<T, U &&>
    RareOptional& operator=(std::optional<U> value) {
        return *this = RareOptional(std::move(value));
    }

    ~RareOptional() = default;

    // A std::optional holding a copy, for code written against std::optional.
    operator std::optional<T>() const {  // NOLINT(google-explicit-constructor)
        return value_ ? std::optional<T>(*value_) : std::nullopt;
    }

    [[nodiscard]] bool has_value() const noexcept { return value_ != nullptr; }
    explicit operator bool() const noexcept { return value_ != nullptr; }

    [[nodiscard]] T& operator*() noexcept { return *value_; }
    [[nodiscard]] const T& operator*() const noexcept { return *value_; }
    [[nodiscard]] T* operator->() noexcept { return value_.get(); }
    [[nodiscard]] const T* operator->() const noexcept { return value_.get(); }

    [[nodiscard]] T& value() {
        if (!value_) throw std::bad_optional_access();
        return *value_;
    }
    [[nodiscard]] const T& value() const {
        if (!value_) throw std::bad_optional_access();
        return *value_;
    }
    template <typename U>
    [[nodiscard]] T value_or(U&& fallback) const {
        return value_ ? *value_ : static_cast<T>(std::forward<U>(fallback));
    }

    template <typename... Args>
    T& emplace(Args&&... args) {
        value_ = std::make_unique<T>(std::forward<Args>(args)...);
        return *value_;
    }
    void reset() noexcept { value_.reset(); }

    friend bool operator==(const RareOptional& a, const RareOptional& b) {
        if (a.has_value() != b.has_value()) return false;
        return !a.has_value() || *a == *b;
    }
    friend bool operator==(const RareOptional& a, std::nullopt_t) noexcept { return !a.has_value(); }
    template <typename U>
    friend bool operator==(const RareOptional& a, const std::optional<U>& b) {
        if (a.has_value() != b.has_value()) return false;
        return !a.has_value() || *a == *b;
    }
    template <typename U>
        requires(!std::is_same_v<U, RareOptional> && !std::is_same_v<U, std::nullopt_t> &&
                 requires(const T& t, const U& u) {
                     { t == u } -> std::convertible_to<bool>;
                 })
    friend bool operator==(const RareOptional& a, const U& b) {
        return a.has_value() && *a == b;
    }

private:
    std::unique_ptr<T> value_;
};

}  // namespace esi
