// Fuzz target: esi-diff. The input holds two ESI files separated by four NUL bytes (a sequence
// no well-formed XML file contains; without it the input is split in half). Both are read and
// compared in both directions and with a device selector, every rendering is produced, and a
// document compared with itself must come out identical.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "esi/diff/diff.hpp"
#include "esi/diff/report.hpp"
#include "esi/xml/reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view input(reinterpret_cast<const char*>(data), size);
    constexpr std::string_view separator("\0\0\0\0", 4);
    std::string_view old_bytes, new_bytes;
    if (const auto at = input.find(separator); at != std::string_view::npos) {
        old_bytes = input.substr(0, at);
        new_bytes = input.substr(at + separator.size());
    } else {
        old_bytes = input.substr(0, size / 2);
        new_bytes = input.substr(size / 2);
    }
    const esi::ReadOptions options{.keep_source = false};
    const esi::ReadResult old_read = esi::read_esi(old_bytes, "old.xml", options);
    const esi::ReadResult new_read = esi::read_esi(new_bytes, "new.xml", options);
    if (!old_read.document || !new_read.document) return 0;

    const esi::DiffLabels labels{"old.xml", "new.xml"};
    const esi::DiffResult forward = esi::diff_documents(*old_read.document, *new_read.document);
    (void)esi::render_diff_text(forward, labels);
    (void)esi::render_diff_json(forward);
    (void)esi::render_diff_markdown(forward, labels);
    (void)esi::diff_documents(*new_read.document, *old_read.document);

    // The first device of the old file as --device, as esi-diff --device would select it.
    for (const auto& info : old_read.document->infos) {
        if (info.devices.empty()) continue;
        const auto& type = info.devices.front().type;
        esi::DiffOptions selected;
        selected.device = esi::DeviceSelector{type.product_code.value_or(0), type.revision_no};
        (void)esi::render_diff_json(esi::diff_documents(*old_read.document, *new_read.document, selected));
        break;
    }

    const esi::DiffResult self = esi::diff_documents(*old_read.document, *old_read.document);
    if (!self.identical()) {
        std::fprintf(stderr, "a document differs from itself:\n%s\n", esi::render_diff_text(self, {"old.xml", "old.xml"}).c_str());
        std::abort();
    }
    return 0;
}
