// Runs one stage of esi-lint once over the given files, for instruction counting with
// `valgrind --tool=callgrind` (counts are repeatable on a loaded machine, wall time is not):
//   lint_stage bare FILE...   pugixml parse with the reader's options
//   lint_stage parse FILE...  libesi's own parse: decode, check well-formedness, build the tree
//   lint_stage read FILE...   read into the model (decode + parse + model)
//   lint_stage lint FILE...   read + every rule under the default config
// Prints what it did so a run can be checked; see docs/performance.md.

#include <pugixml.hpp>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "esi/encoding.hpp"
#include "esi/io/read_file.hpp"
#include "esi/lint/lint.hpp"
#include "esi/xml/well_formed.hpp"

int main(int argc, char** argv) {
    if (argc < 3 || (std::strcmp(argv[1], "bare") != 0 && std::strcmp(argv[1], "parse") != 0 && std::strcmp(argv[1], "read") != 0 &&
                     std::strcmp(argv[1], "lint") != 0)) {
        std::fprintf(stderr, "usage: lint_stage bare|parse|read|lint FILE...\n");
        return 2;
    }
    const std::string stage = argv[1];
    std::vector<std::pair<std::string, std::string>> inputs;
    for (int i = 2; i < argc; ++i) {
        std::string error;
        auto bytes = esi::read_file_bytes(argv[i], error);
        if (!bytes) {
            std::fprintf(stderr, "lint_stage: %s: %s\n", argv[i], error.c_str());
            return 2;
        }
        inputs.emplace_back(argv[i], std::move(*bytes));
    }
    std::size_t count = 0;
    // Each input is used once; lint and read take it over as esi-lint takes over the bytes of a file
    // it read (the bare parse copies it, as pugixml's load_buffer does).
    for (auto& [path, bytes] : inputs) {
        if (stage == "bare") {
            pugi::xml_document doc;
            const auto parsed = doc.load_buffer(bytes.data(), bytes.size(), pugi::parse_default | pugi::parse_embed_pcdata,
                                                pugi::encoding_utf8);
            count += parsed ? 1 : 0;
        } else if (stage == "parse") {
            const esi::DecodedText decoded = esi::decode_xml_bytes(bytes);
            count += esi::find_well_formedness_fault(decoded.utf8, decoded.encoding) ? 0 : 1;
        } else if (stage == "read") {
            const esi::ReadResult read = esi::read_esi_owned(std::move(bytes), path);
            count += read.document ? read.document->infos.size() : 0;
        } else {
            count += esi::lint_bytes(std::move(bytes), path, {}).diagnostics.size();
        }
    }
    std::printf("%s: %zu files, result %zu\n", stage.c_str(), inputs.size(), count);
    return 0;
}
