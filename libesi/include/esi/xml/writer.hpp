#pragma once
// The ESI XML back end: model -> ESI XML text. Deterministic (the same model gives byte-identical
// text), schema-ordered, with the elements the model keeps verbatim (Extras) put back where they
// were.

#include <string>

#include "esi/model/ethercat_info.hpp"

namespace esi {

struct WriteOptions {
    std::string indent = "  ";
};

[[nodiscard]] std::string write_esi(const EsiDocument& document, const WriteOptions& options = {});

}  // namespace esi
