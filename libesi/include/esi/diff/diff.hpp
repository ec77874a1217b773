#pragma once
// esi-diff as a library: compares two ESI models (not their text) and classifies every change.
// Devices are matched by (vendor, ProductCode, RevisionNo); a device whose product code stays and
// whose revision changes is compared with its predecessor (the highest lower revision of that
// product code in the old file). Formatting, attribute order, comments, number spelling (#x10 vs
// 16), hex-data case, and the order of elements whose order ETG does not give a meaning (objects,
// data types, groups, devices, modules) are not changes. The order of entries in a PDO and of the
// PDOs assigned to a SyncManager is the process-image layout, so it is compared.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "esi/device_selector.hpp"
#include "esi/diagnostic.hpp"
#include "esi/diff/change.hpp"
#include "esi/model/ethercat_info.hpp"

namespace esi {

struct DiffOptions {
    // Compare only the devices this selects (in either file); changes of the file as a whole
    // (vendor name, groups, modules) are then left out, a vendor Id change is kept.
    std::optional<DeviceSelector> device;
    // diff_files: keep both models in the result (an HTML report draws them).
    bool keep_documents = false;
};

struct DiffResult {
    // Sorted by device (file-level changes first, then by product code, revision, Type text),
    // then class (most severe first), then path. Deterministic for the same inputs.
    std::vector<Change> changes;
    Verdict verdict = Verdict::identical;
    // Devices of each file the selector picked; both zero means --device matched nothing.
    std::size_t old_devices_compared = 0;
    std::size_t new_devices_compared = 0;

    // No change at all, not even cosmetic.
    [[nodiscard]] bool identical() const { return changes.empty(); }
    [[nodiscard]] std::size_t count(ChangeClass change_class) const;
    // Number of changes whose kind is an error (a breaking change without a RevisionNo change).
    [[nodiscard]] std::size_t error_count() const;
};

[[nodiscard]] DiffResult diff_documents(const EsiDocument& old_document, const EsiDocument& new_document,
                                        const DiffOptions& options = {});

// Both files read and compared. `result` is absent when either file could not be read (missing,
// not well-formed, not an ESI root); `diagnostics` then holds the reason with its position.
struct FileDiff {
    std::optional<DiffResult> result;
    Diagnostics diagnostics;  // errors that prevented reading; reader warnings are not kept
    std::string old_path;
    std::string new_path;
    // Both models, when DiffOptions::keep_documents asked for them and both files were read.
    std::optional<EsiDocument> old_document;
    std::optional<EsiDocument> new_document;
};

[[nodiscard]] FileDiff diff_files(const std::filesystem::path& old_path, const std::filesystem::path& new_path,
                                  const DiffOptions& options = {});

// One side of a comparison: a file, or bytes already read (standard input, `git show REV:dev.xml`
// piped in) that diagnostics name by `path`.
struct DiffSource {
    std::filesystem::path path;
    std::optional<std::string> bytes;  // set: read these instead of the file at `path`
};

// diff_files for sources that may be in memory.
[[nodiscard]] FileDiff diff_sources(DiffSource old_source, DiffSource new_source, const DiffOptions& options = {});

}  // namespace esi
