// Fuzz target: the SII front end. Bytes (raw image or Intel HEX) -> decoder -> every rendering
// esi-sii dump prints -> the ESI-vs-image check against a fixed device (the bundled sample) ->
// re-encoding of what was decoded. Any input must give faults and text, never a crash, a hang,
// an out-of-bounds read or an allocation that grows with a length field instead of the input.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <string_view>

#include "esi/sii/check.hpp"
#include "esi/sii/decode.hpp"
#include "esi/sii/encode.hpp"
#include "esi/sii/image_file.hpp"
#include "esi/sii/render.hpp"
#include "esi/xml/reader.hpp"

namespace {

// The device every image is checked against: the sample ESI (EX-DIO-8), read once.
const esi::EsiDocument& reference_document() {
    static const esi::EsiDocument document = [] {
        esi::ReadResult read = esi::read_esi_file(ESI_FUZZ_REFERENCE_ESI);
        if (!read.document || read.document->infos.empty() || read.document->infos.front().devices.empty()) std::abort();
        return std::move(*read.document);
    }();
    return document;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const esi::EsiDocument& document = reference_document();
    const std::string_view raw(reinterpret_cast<const char*>(data), size);
    // load_image routes text starting with ':' through the Intel HEX parser.
    const esi::sii::LoadedImage loaded = esi::sii::load_image(raw);
    if (!loaded.bytes) return 0;
    const esi::sii::DecodedImage decoded = esi::sii::decode_image(*loaded.bytes);
    (void)esi::sii::render_dump_text(decoded, "fuzz.bin");
    (void)esi::sii::render_dump_json(decoded, "fuzz.bin");
    (void)esi::sii::render_faults_text(decoded, "fuzz.bin");
    (void)esi::sii::to_diagnostics(decoded.faults, "fuzz.bin");

    const esi::EtherCATInfo& info = document.infos.front();
    const esi::Diagnostics mismatches = esi::sii::check_image(info, info.devices.front(), decoded, "sample.xml", "fuzz.bin");
    (void)esi::sii::render_check_text(decoded, "fuzz.bin", mismatches, "EX-DIO-8");
    (void)esi::sii::find_device_for_image(document, decoded.image.header);

    // What was decoded must encode again (the length words take the low 16 bits by contract).
    const std::vector<std::uint8_t> again = esi::sii::encode_image(decoded.image);
    (void)esi::sii::decode_image(again);
    (void)esi::sii::to_intel_hex(*loaded.bytes);
    return 0;
}
