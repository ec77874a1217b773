#pragma once
// Helpers of the esi-doc tests: running the tools, loading a source the way they do, and the
// data-entry keys every PDO entry of a device page must carry (docs/esi-doc.md).

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "codegen/codegen_test_support.hpp"
#include "doc/modules.hpp"
#include "esi/load/document.hpp"
#include "support/test_support.hpp"

namespace esi::test::doc {

using esi::test::codegen::tree;

inline std::filesystem::path samples_dir() { return source_dir() / "samples"; }
inline std::filesystem::path sample_esi() { return samples_dir() / "esi" / "example-digital-io.xml"; }

// Every device source of samples/: the YAML sources and the ESI file.
inline std::vector<std::filesystem::path> sample_sources() {
    std::vector<std::filesystem::path> out{sample_esi()};
    for (const auto& e : std::filesystem::directory_iterator(samples_dir()))
        if (e.path().extension() == ".yaml") out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

// esi-doc SOURCE -o OUT [extra...]
inline RunResult esi_doc(const std::filesystem::path& source, const std::filesystem::path& out, const std::vector<std::string>& extra = {}) {
    std::vector<std::string> argv{tool("esi-doc").string(), source.string(), "-o", out.string()};
    argv.insert(argv.end(), extra.begin(), extra.end());
    return run(argv);
}

inline EsiDocument load(const std::filesystem::path& path) {
    LoadedDocument loaded = load_document_file(path);
    EXPECT_TRUE(loaded.usable()) << path;
    return loaded.usable() ? std::move(*loaded.document) : EsiDocument{};
}

// "dev:R0:3": owner (the device, or module m<position>), direction and PDO position, entry position.
inline void add_entry_keys(const std::vector<Pdo>& pdos, const std::string& owner, char direction, std::vector<std::string>& out) {
    for (std::size_t p = 0; p < pdos.size(); ++p)
        for (std::size_t e = 0; e < pdos[p].entries.size(); ++e)
            out.push_back(owner + ":" + direction + std::to_string(p) + ":" + std::to_string(e));
}

// The keys of every PDO entry a device's page shows: its own PDOs and those of the modules its
// slots accept.
inline std::vector<std::string> expected_entry_keys(const EsiDocument& document, const Device& device) {
    std::vector<std::string> out;
    add_entry_keys(device.rx_pdos, "dev", 'R', out);
    add_entry_keys(device.tx_pdos, "dev", 'T', out);
    if (const EtherCATInfo* info = document.info_of(device))
        for (const std::size_t m : esi::doc::accepted_modules(*info, device)) {
            add_entry_keys(info->modules[m].rx_pdos, "m" + std::to_string(m), 'R', out);
            add_entry_keys(info->modules[m].tx_pdos, "m" + std::to_string(m), 'T', out);
        }
    return out;
}

inline std::size_t occurrences(const std::string& text, const std::string& needle) {
    std::size_t n = 0;
    for (std::size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + needle.size())) ++n;
    return n;
}

}  // namespace esi::test::doc
