#pragma once
// esi-net's process-image map as one self-contained HTML page (process_image.html: inline CSS
// and SVG, no script, no external request): the master's output and input images of each frame
// drawn as bit-layout pictures (esi/doc/bit_layout.hpp) with byte offsets from the start of the
// logical image, every variable a labelled box "slave: variable", and a table of the variables
// under each picture. Rendered from templates/doc/process_image.html.mustache with page.css
// inlined, so a vendor brands it like the datasheets. Deterministic: the same network and
// templates give a byte-identical page.
//
// The doc layer links net privately: the network model is declared here, not included, so a
// user of libesi::doc alone does not need esi-net's headers.

#include <filesystem>
#include <vector>

#include "esi/diagnostic.hpp"
#include "esi/io/atomic_write.hpp"

namespace esi::net {
struct Network;
}  // namespace esi::net

namespace esi::doc {

struct ProcessImagePageOptions {
    std::vector<std::filesystem::path> template_dirs;  // the search list (esi/doc/datasheet.hpp template_search_path)
};

struct ProcessImagePage {
    std::vector<OutputFile> files;  // output_dir/process_image.html; empty when `diagnostics` has errors
    Diagnostics diagnostics;        // doc-template-missing, doc-template-error, io-error
};

[[nodiscard]] ProcessImagePage render_process_image_page(const net::Network& network, const std::filesystem::path& output_dir,
                                                         const ProcessImagePageOptions& options);

}  // namespace esi::doc
