#pragma once
// Renders kainjow mustache templates over a view. Code templates are not HTML: {{name}} is
// inserted as it is (no HTML escaping); the view carries ready-made C literals where escaping
// matters (name_literal, string_literal, comment).

#include <memory>
#include <string>
#include <string_view>

#include "codegen/view_parts.hpp"
#include "esi/source_pos.hpp"

namespace esi::codegen {

struct Rendered {
    bool ok = false;
    std::string text;
    std::string error;  // the template's syntax error
    SourcePos pos;      // where in the template
};

// The view converted once into mustache data: JSON objects, arrays and strings map directly,
// numbers become their decimal text, booleans stay booleans (sections), null becomes false.
class MustacheContext {
public:
    explicit MustacheContext(const Json& view);
    ~MustacheContext();
    MustacheContext(const MustacheContext&) = delete;
    MustacheContext& operator=(const MustacheContext&) = delete;

    [[nodiscard]] Rendered render(const std::string& template_text) const;

private:
    [[nodiscard]] Rendered render_checked(const std::string& template_text) const;
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace esi::codegen
