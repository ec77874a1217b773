#pragma once
// esi-doc as a library: one self-contained HTML page per device of an ESI document (inline CSS
// and SVG, no script, no external request) plus an index, rendered from templates a vendor can
// replace (templates/doc/, docs/esi-doc.md). Deterministic: the same document, language and
// templates give byte-identical files.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string_view>
#include <vector>

#include "esi/device_selector.hpp"
#include "esi/diagnostic.hpp"
#include "esi/io/atomic_write.hpp"
#include "esi/model/ethercat_info.hpp"
#include "esi/model/language.hpp"

namespace esi::doc {

// --lang: a language code of esi/model/language.hpp (en, de, zh-TW …) or a decimal LcId.
[[nodiscard]] std::optional<std::uint32_t> parse_language(std::string_view text);

// Where esi-doc's templates are searched, first match wins: `user_dirs` as given, then the doc/
// folder of the installed and of the source template directories (esi/codegen/template_lookup.hpp).
[[nodiscard]] std::vector<std::filesystem::path> template_search_path(const std::vector<std::filesystem::path>& user_dirs,
                                                                      const std::optional<std::filesystem::path>& executable);

struct DatasheetOptions {
    std::optional<DeviceSelector> device;              // only the matching devices (all when absent)
    std::uint32_t lcid = default_lcid;                 // page language; texts fall back to English, then the first
    std::vector<std::filesystem::path> template_dirs;  // the search list (template_search_path)
};

struct Datasheets {
    // output_dir/index.html first, then one page per device in document order. Empty when
    // `diagnostics` has errors: nothing is to be written.
    std::vector<OutputFile> files;
    Diagnostics diagnostics;  // doc-no-device, doc-template-missing, doc-template-error, io-error
};

[[nodiscard]] Datasheets render_datasheets(const EsiDocument& document, const std::filesystem::path& output_dir,
                                           const DatasheetOptions& options);

// The page file name of each device of `devices`, in the same order: "<Type>-rev<RevisionNo>.html"
// made file-safe, with "-2", "-3" … where two devices would share one.
[[nodiscard]] std::vector<std::string> page_file_names(const std::vector<const Device*>& devices);

}  // namespace esi::doc
