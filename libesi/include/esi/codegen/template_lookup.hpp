#pragma once
// Where templates come from. Each template is looked up by file name in a list of directories,
// first match wins, so a user can override one template and keep the others:
//   1. the directories given with --templates (in the order given),
//   2. the installed share directory, <prefix>/share/libesi/templates, found next to the running
//      executable (<exe dir>/../share/libesi/templates),
//   3. the source tree's templates/ (compiled in as ESI_TEMPLATE_DIR; for build-tree use).

#include <filesystem>
#include <optional>
#include <string_view>
#include <vector>

#include "esi/codegen/mustache.hpp"
#include "esi/diagnostic.hpp"

namespace esi::codegen {

// <executable's directory>/../share/libesi/templates (not checked for existence).
[[nodiscard]] std::filesystem::path installed_template_dir(const std::filesystem::path& executable);

// The source tree's templates/ directory this library was built from.
[[nodiscard]] std::filesystem::path source_template_dir();

// The search list: `user_dirs`, then the installed dir when `executable` is given, then the
// source dir. Installed and source dirs that do not exist are left out; user dirs are kept as
// given (the CLI reports one that does not exist).
[[nodiscard]] std::vector<std::filesystem::path> template_search_path(const std::vector<std::filesystem::path>& user_dirs,
                                                                      const std::optional<std::filesystem::path>& executable);

// The first `dirs[i] / name` that is a regular file.
[[nodiscard]] std::optional<std::filesystem::path> find_template(std::string_view name, const std::vector<std::filesystem::path>& dirs);

struct TemplateFile {
    std::filesystem::path path;                 // where it was found; empty when it was not
    std::optional<mustache::Template> parsed;  // absent when missing, unreadable or broken
};

// Finds, reads and parses one template. Errors go to `diagnostics`: `<tool>-template-missing`
// (naming the directories searched), io-error, `<tool>-template-error` at the tag's line:col;
// `tool` is the rule prefix of the back end ("codegen", "doc").
[[nodiscard]] TemplateFile load_template(std::string_view name, const std::vector<std::filesystem::path>& dirs,
                                         std::string_view tool, Diagnostics& diagnostics);

}  // namespace esi::codegen
