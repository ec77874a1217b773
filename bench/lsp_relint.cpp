// esi-lsp's latency after a keystroke (issue 26: a 1 MB file re-linted in under 50 ms): for the
// corpus files of about 1 MB, the time from an incremental didChange to the publishDiagnostics
// message, as the lint worker spends it: apply the edit to the document store, lint the snapshot
// (config lookup, read, every rule, suppressions) and build the notification's JSON. The
// debounce wait is not included (it is the editor's choice, --debounce). Best of 15 runs.
//   lsp_relint [FILE...]   (default: the corpus files between 0.9 and 1.3 MB)

#include <cstdio>
#include <string>
#include <vector>

#include "bench_support.hpp"
#include "esi/encoding.hpp"
#include "esi/io/read_file.hpp"
#include "esi/lsp/code_actions.hpp"
#include "esi/lsp/document_store.hpp"
#include "esi/lsp/lint_document.hpp"

int main(int argc, char** argv) {
    std::vector<std::filesystem::path> files;
    for (int i = 1; i < argc; ++i) files.emplace_back(argv[i]);
    if (files.empty()) {
        for (const auto& f : esi::bench::largest_corpus_files(1000)) {
            const auto size = std::filesystem::file_size(f);
            if (size >= 900'000 && size <= 1'300'000) files.push_back(f);
        }
    }
    if (files.empty()) {
        std::fprintf(stderr, "lsp_relint: no files (../shared/corpus absent?)\n");
        return 2;
    }
    std::printf("%-52s %9s %8s %8s %8s %9s\n", "file", "bytes", "edit ms", "lint ms", "json ms", "total ms");
    for (const auto& path : files) {
        std::string error;
        const auto bytes = esi::read_file_bytes(path, error);
        if (!bytes) continue;
        const std::string text = esi::decode_xml_bytes(*bytes).utf8;
        esi::lsp::DocumentStore store;
        const std::string uri = "file://" + path.string();
        store.open(uri, "xml", 1, text);
        std::int64_t version = 1;
        double edit_ms = 1e300;
        double lint_ms = 1e300;
        double json_ms = 1e300;
        const double total = esi::bench::best_of(15, [&] {
            // A keystroke on line 3: one character typed (then removed on the next run).
            const auto start = esi::bench::Clock::now();
            const bool insert = version % 2 == 1;
            const esi::lsp::Range at{{2, 1}, {2, static_cast<std::uint32_t>(insert ? 1 : 2)}};
            (void)store.change(uri, ++version, {{at, insert ? " " : ""}});
            const esi::lsp::Document document = *store.find(uri);
            const auto edited = esi::bench::Clock::now();
            esi::lsp::LintResult result{uri, version, document.text, esi::lsp::lint_document(*document.text, path.string())};
            const auto linted = esi::bench::Clock::now();
            const std::string message = esi::lsp::publish_params(result).dump();
            json_ms = std::min(json_ms, esi::bench::milliseconds(esi::bench::Clock::now() - linted));
            edit_ms = std::min(edit_ms, esi::bench::milliseconds(edited - start));
            lint_ms = std::min(lint_ms, esi::bench::milliseconds(linted - edited));
            if (message.empty()) std::abort();
        });
        std::printf("%-52s %9zu %8.2f %8.2f %8.2f %9.2f\n", path.filename().string().c_str(), text.size(), edit_ms, lint_ms, json_ms,
                    total);
    }
    return 0;
}
