#pragma once
// What every section of a page is built with: the view arena, the page language, and the
// catalogue and device the page is about. Sections read the model only and return view values
// (docs/esi-doc.md, "The page view").

#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>

#include "esi/codegen/view_tree.hpp"
#include "esi/model/ethercat_info.hpp"
#include "esi/model/language.hpp"

namespace esi::doc {

using codegen::ListBuilder;
using codegen::ObjectBuilder;
using codegen::ViewArena;
using codegen::ViewValue;

// Builds one object of the page view. Empty text becomes null: in the templates' Mustache an empty
// string is true, and {{#comment}}…{{/comment}} must leave out what the file does not give.
class PageObject {
public:
    explicit PageObject(ViewArena& arena) : builder_(arena) {}

    void add(codegen::ViewKey key, std::string_view text) {
        builder_.add(key, text.empty() ? ViewValue::null() : builder_.arena().string(text));
    }
    void add(codegen::ViewKey key, const std::string& text) { add(key, std::string_view(text)); }
    void add(codegen::ViewKey key, const char* text) { add(key, std::string_view(text)); }
    template <typename T>
        requires(!std::is_convertible_v<const T&, std::string_view>)
    void add(codegen::ViewKey key, const T& value) {
        builder_.add(key, value);
    }
    [[nodiscard]] ViewValue finish() { return builder_.finish(); }

private:
    ObjectBuilder builder_;
};

struct PageContext {
    ViewArena* arena = nullptr;
    std::uint32_t lcid = default_lcid;
    const EtherCATInfo* info = nullptr;  // the catalogue of the device (vendor, groups, modules)

    [[nodiscard]] const std::string& text(const Names& names) const { return localized_text(names, lcid); }
};

}  // namespace esi::doc
