#include "sii_image.hpp"

#include "esi/sii/build.hpp"
#include "esi/sii/image_file.hpp"

namespace esi::codegen {

namespace {

Diagnostics produce_sii(const ProduceContext& context, std::string& content, sii::ImageFormat format) {
    Diagnostics diagnostics;
    // The SII header needs the catalogue's Vendor/Id and group names.
    const EtherCATInfo* info = context.device ? context.document.info_of(*context.device) : nullptr;
    if (!context.device || !info) {
        diagnostics.emplace(Severity::error, "codegen-sii-device", "the SII image needs a device of an EtherCATInfo catalogue",
                            context.document.path, {});
        return diagnostics;
    }
    // An image whose mandatory part does not fit Eeprom/ByteSize (or a string over 255 bytes) is
    // an error from the builder: esi-gen then writes nothing, rather than an image the master
    // would misread. Optional content it leaves out to fit is a note.
    sii::BuildOptions build;
    build.fit_to_eeprom = !context.options.sii_strict_size;
    build.refuse_pdi_off = context.options.sii_strict;
    sii::BuildResult built = sii::build_image(*info, *context.device, build, context.document.path);
    diagnostics.append(std::move(built.diagnostics));
    if (diagnostics.has_errors()) return diagnostics;
    content = sii::format_image(built.bytes, format);
    return diagnostics;
}

}  // namespace

Diagnostics produce_sii_binary(const ProduceContext& context, std::string& content) {
    return produce_sii(context, content, sii::ImageFormat::bin);
}

Diagnostics produce_sii_intel_hex(const ProduceContext& context, std::string& content) {
    // The "sii" kind always produces eeprom.bin from the same device first, and its diagnostics
    // already say everything about this image; a failed image there means no file is written at
    // all (generate_outputs is all or nothing). Reporting them twice would only add noise.
    Diagnostics repeated = produce_sii(context, content, sii::ImageFormat::hex);
    (void)repeated;
    return {};
}

}  // namespace esi::codegen
