#pragma once
// The ESI XML back end: model -> ESI XML text. Deterministic (the same model gives byte-identical
// text), schema-ordered (ETG.2000 schema 1.17), with the elements the model keeps verbatim
// (Extras) put back where they were. The reader's inverse: write(read(write(read(x)))) is
// byte-identical to write(read(x)). Number formats, element order and limits: docs/esi-writer.md.

#include <filesystem>
#include <string>

#include "esi/diagnostic.hpp"
#include "esi/model/ethercat_info.hpp"

namespace esi {

struct WriteOptions {
    // One level of indentation; "" writes every element on its own line without indentation.
    std::string indent = "  ";
    // Written after the declaration, after each element line and at the end of the document.
    std::string line_ending = "\n";
};

// The root element follows document.kind; a model whose kind is `unknown` (e.g. built by a
// generator that did not set it) is written as EtherCATDict when it holds only a dictionary, as
// EtherCATInfoList when it holds several infos, else as EtherCATInfo. Never throws for any model
// content: strings that XML cannot carry are repaired (see the docs), not rejected.
[[nodiscard]] std::string write_esi(const EsiDocument& document, const WriteOptions& options = {});

// Writes the document to `path` atomically (temporary file + rename). Errors are io-error
// diagnostics; on error the target is left as it was.
[[nodiscard]] Diagnostics write_esi_file(const std::filesystem::path& path, const EsiDocument& document,
                                         const WriteOptions& options = {});

}  // namespace esi
