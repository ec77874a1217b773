// SII image builder: the header words, the Strings category, the order of the categories and
// the EEPROM size (ETG.2010); then fitting the image to its EEPROM (fit.hpp). The categories
// built from the device are in build_categories.cpp; see builder.hpp.

#include "esi/sii/build.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "esi/model/esc_preset.hpp"
#include "esi/number.hpp"
#include "esi/sii/decode.hpp"
#include "esi/sii/encode.hpp"
#include "esi/sii/mapping.hpp"
#include "esi/sii/text.hpp"
#include "sii/builder.hpp"
#include "fit.hpp"

namespace esi::sii {

namespace build_detail {

namespace {

constexpr std::size_t max_strings = 255;
constexpr std::size_t max_string_bytes = 255;

}  // namespace

std::uint8_t Builder::add_string(std::string_view utf8, SourcePos pos, std::string_view what) {
    if (utf8.empty()) return 0;
    bool latin1 = true;
    std::string stored = to_sii_text(utf8, &latin1);
    if (const auto it = string_index_.find(stored); it != string_index_.end()) return it->second;
    if (stored.size() > max_string_bytes) {
        diag(Severity::error, "sii-string-too-long",
             fmt::format("{} \"{}\" takes {} bytes; an SII string holds at most {} (its length is one byte)", what,
                         std::string(utf8.substr(0, 40)) + "…", stored.size(), max_string_bytes),
             pos);
        return 0;
    }
    if (!latin1)
        diag(Severity::warning, "sii-string-encoding",
             fmt::format("{} \"{}\" has characters outside ISO-8859-1; it is stored as UTF-8 bytes", what, utf8), pos);
    ++distinct_strings_;
    if (strings_.size() >= max_strings) {
        if (!first_overflow_pos_.known()) first_overflow_pos_ = pos.known() ? pos : device_.pos;
        string_index_.emplace(std::move(stored), 0);
        return 0;
    }
    strings_.push_back(stored);
    const auto index = static_cast<std::uint8_t>(strings_.size());
    string_index_.emplace(std::move(stored), index);
    return index;
}

void Builder::build_header() {
    Header& h = image_.header;
    const Eeprom* eeprom = device_.eeprom ? &*device_.eeprom : nullptr;
    if (eeprom && eeprom->config_data) {
        const auto bytes = eeprom->config_data->bytes();
        if (!bytes) {
            diag(Severity::error, "sii-config-data", "Eeprom/ConfigData is not valid hexBinary", eeprom->config_data->pos);
        } else {
            if (bytes->size() > config_area_bytes)
                diag(Severity::warning, "sii-config-data",
                     fmt::format("Eeprom/ConfigData has {} bytes; words 0-6 take {}, bytes from {} on are not written "
                                 "(word 7 is the computed CRC)",
                                 bytes->size(), config_area_bytes, config_area_bytes),
                     eeprom->config_data->pos);
            for (std::size_t i = 0; i < bytes->size() && i < config_area_bytes; ++i) h.config_data[i] = (*bytes)[i];
        }
    }

    if (!eeprom || !eeprom->config_data) {
        // Nothing a master reads offline shows it, but the image leaves the microcontroller
        // without any access to the ESC (issue 23): say so, and how to fix it.
        diag(options_.refuse_pdi_off ? Severity::error : Severity::warning, "sii-pdi-off",
             fmt::format("no Eeprom/ConfigData: PDI control (word 0) is 0, so the image switches the ESC's process data "
                         "interface off and the device's microcontroller cannot reach the ESC; name the ESC in the device "
                         "source (esc: {}) or give Eeprom/ConfigData from its datasheet",
                         esc_preset_names()),
             eeprom ? eeprom->pos : device_.pos);
    }

    if (info_.vendor && info_.vendor->id) h.vendor_id = *info_.vendor->id;
    else diag(Severity::warning, "sii-identity", "Vendor/Id is missing; words 0x08-0x09 are 0", info_.vendor ? info_.vendor->pos : info_.pos);
    if (device_.type.product_code) h.product_code = *device_.type.product_code;
    else diag(Severity::warning, "sii-identity", "Type@ProductCode is missing; words 0x0A-0x0B are 0", device_.type.pos);
    if (device_.type.revision_no) h.revision_no = *device_.type.revision_no;
    else diag(Severity::warning, "sii-identity", "Type@RevisionNo is missing; words 0x0C-0x0D are 0", device_.type.pos);
    h.serial_no = device_.type.serial_no.value_or(0);

    if (eeprom && eeprom->boot_strap) {
        const auto bytes = eeprom->boot_strap->bytes();
        if (!bytes || bytes->size() != 8) {
            diag(Severity::error, "sii-boot-strap",
                 "Eeprom/BootStrap must be 8 bytes of hexBinary (receive offset, receive size, send offset, send size as "
                 "little-endian words)",
                 eeprom->boot_strap->pos);
        } else {
            auto w = [&](std::size_t i) { return static_cast<std::uint16_t>((*bytes)[2 * i] | ((*bytes)[2 * i + 1] << 8)); };
            h.bootstrap_receive_offset = w(0);
            h.bootstrap_receive_size = w(1);
            h.bootstrap_send_offset = w(2);
            h.bootstrap_send_size = w(3);
        }
    }

    // Words 0x18-0x1B come from the mailbox SyncManagers: SM0 MBoxOut is the receive mailbox.
    auto mailbox_words = [&](std::string_view type, std::uint16_t& offset, std::uint16_t& size) {
        const SyncManager* sm = find_sm(device_, type);
        if (!sm) {
            if (device_.mailbox)
                diag(Severity::warning, "sii-mailbox-sm",
                     fmt::format("the device has a Mailbox but no {} Sm; the standard mailbox words are 0", type),
                     device_.mailbox->pos);
            return;
        }
        offset = static_cast<std::uint16_t>(
            fit_unsigned(sm->start_address.value_or(0), 16, fmt::format("{} Sm StartAddress", type), sm->pos));
        size = static_cast<std::uint16_t>(fit_unsigned(sm->default_size.value_or(0), 16, fmt::format("{} Sm DefaultSize", type), sm->pos));
        if (!sm->default_size)
            diag(Severity::warning, "sii-mailbox-sm", fmt::format("{} Sm has no DefaultSize; the mailbox size word is 0", type), sm->pos);
    };
    mailbox_words("MBoxOut", h.standard_receive_offset, h.standard_receive_size);
    mailbox_words("MBoxIn", h.standard_send_offset, h.standard_send_size);
    if (device_.mailbox) h.mailbox_protocols = device_.mailbox->protocol_bits();
    h.version = 1;
}

void Builder::run() {
    const Eeprom* eeprom = device_.eeprom ? &*device_.eeprom : nullptr;
    if (eeprom && eeprom->data) {
        const auto bytes = eeprom->data->bytes();
        if (!bytes) {
            diag(Severity::error, "sii-eeprom-data", "Eeprom/Data is not valid hexBinary", eeprom->data->pos);
            return;
        }
        result_.from_eeprom_data = true;
        result_.bytes = *bytes;
        result_.content_bytes = bytes->size();
        DecodedImage decoded = decode_image(result_.bytes);
        result_.image = std::move(decoded.image);
        result_.eeprom_bytes = result_.image.header.eeprom_bytes();
        diag(Severity::info, "sii-eeprom-data",
             "Eeprom/Data holds a complete image; it is used as it is (--no-pdo and --no-dc do not apply)", eeprom->data->pos);
        for (const auto& f : decoded.faults)
            diag(Severity::warning, "sii-eeprom-data-fault", fmt::format("Eeprom/Data byte 0x{:04X}: {} [{}]", f.offset, f.message, f.rule),
                 eeprom->data->pos);
        if (eeprom->byte_size && bytes->size() > *eeprom->byte_size)
            diag(Severity::error, "sii-image-too-large",
                 fmt::format("Eeprom/Data has {} bytes but Eeprom/ByteSize is {}", bytes->size(), *eeprom->byte_size),
                 eeprom->byte_size_pos);
        return;
    }

    build_header();
    build_copied_categories();
    // Strings are collected while the other categories are built; the order of the strings
    // follows Beckhoff's images (identity strings, DC names, TxPDO, RxPDO).
    const std::size_t strings_position = image_.categories.size();
    add_category(category::general, build_general());
    build_fmmus();
    build_sync_managers();
    std::optional<DcOpModes> dc = build_dc();
    if (options_.include_pdos && !omitted_.pdos) {
        Pdos tx = build_pdos(device_.tx_pdos);
        Pdos rx = build_pdos(device_.rx_pdos);
        if (!tx.items.empty() || explicit_.count(category::tx_pdo)) add_category(category::tx_pdo, std::move(tx));
        if (!rx.items.empty() || explicit_.count(category::rx_pdo)) add_category(category::rx_pdo, std::move(rx));
    }
    if (dc || explicit_.count(category::dc)) add_category(category::dc, dc ? std::move(*dc) : DcOpModes{});
    // Explicit categories whose generated counterpart is absent (no Fmmu elements, --no-pdo …)
    // are still the vendor's bytes: keep them.
    for (auto& [type, c] : explicit_)
        if (type != category::strings) image_.categories.push_back(std::move(c));
    Category strings{category::strings, Strings{strings_}, 0, 0};
    if (const auto it = explicit_.find(category::strings); it != explicit_.end()) strings = std::move(it->second);
    explicit_.clear();
    image_.categories.insert(image_.categories.begin() + static_cast<std::ptrdiff_t>(strings_position), std::move(strings));
    if (distinct_strings_ > max_strings)
        diag(Severity::error, "sii-too-many-strings",
             fmt::format("the device needs {} distinct strings; the Strings category holds at most {} (its count is one "
                         "byte); strings from here on would get index 0",
                         distinct_strings_, max_strings),
             first_overflow_pos_);
    finish();
}

void Builder::finish() {
    Header& h = image_.header;
    for (const auto& c : image_.categories) {
        const std::size_t words = (encode_content(c.content).size() + 1) / 2;
        if (words > max_category_words)
            diag(Severity::error, "sii-category-size",
                 fmt::format("the {} category ({}) takes {} words; its length word holds at most {}", category_name(c.type),
                             c.type, words, max_category_words),
                 device_.pos);
    }
    result_.content_bytes = encoded_size(image_);
    const Eeprom* eeprom = device_.eeprom ? &*device_.eeprom : nullptr;
    std::uint64_t eeprom_bytes = 0;
    if (eeprom && eeprom->byte_size) {
        const std::uint64_t byte_size = *eeprom->byte_size;
        const SourcePos pos = eeprom->byte_size_pos.known() ? eeprom->byte_size_pos : eeprom->pos;
        if (byte_size < 128 || byte_size % 128 != 0 || byte_size > eeprom_bytes_from_size_word(0xFFFF)) {
            diag(Severity::error, "sii-byte-size",
                 fmt::format("Eeprom/ByteSize {} cannot be written to word 0x3E, which holds (bytes / 128) - 1: it must be a "
                             "multiple of 128 from 128 to {}",
                             byte_size, eeprom_bytes_from_size_word(0xFFFF)),
                 pos);
        } else {
            h.size = static_cast<std::uint16_t>(byte_size / 128 - 1);
            eeprom_bytes = byte_size;
        }
        if (result_.content_bytes > byte_size)
            diag(Severity::error, "sii-image-too-large",
                 fmt::format("the image takes {} bytes but Eeprom/ByteSize is {} ({} bytes too many)", result_.content_bytes,
                             byte_size, result_.content_bytes - byte_size),
                 pos);
    } else {
        // No ByteSize: the smallest power of two that holds the image (EEPROMs come in powers of two).
        std::uint64_t bytes = 128;
        while (bytes < result_.content_bytes) bytes *= 2;
        if (bytes > eeprom_bytes_from_size_word(0xFFFF)) {
            diag(Severity::error, "sii-image-too-large",
                 fmt::format("the image takes {} bytes, more than the largest EEPROM word 0x3E can describe", result_.content_bytes),
                 device_.pos);
        } else {
            h.size = static_cast<std::uint16_t>(bytes / 128 - 1);
            eeprom_bytes = bytes;
            diag(Severity::info, "sii-byte-size",
                 fmt::format("no Eeprom/ByteSize: word 0x3E declares {} bytes, the smallest power of two that holds the {}-byte "
                             "image",
                             bytes, result_.content_bytes),
                 eeprom ? eeprom->pos : device_.pos);
        }
    }
    result_.eeprom_bytes = h.eeprom_bytes();
    const bool fits = eeprom_bytes != 0 && result_.content_bytes <= eeprom_bytes;
    result_.bytes = encode_image(image_, options_.pad_to_eeprom_size && fits ? static_cast<std::size_t>(eeprom_bytes) : 0);
    h.checksum = config_crc(h.config_data);
}

}  // namespace build_detail

namespace {

BuildResult build_with(const EtherCATInfo& info, const Device& device, const BuildOptions& options, const Omissions& omitted,
                       const std::string& path) {
    BuildResult result;
    build_detail::Builder(info, device, options, omitted, path, result).run();
    return result;
}

// The errors that leaving out optional content can cure: the image or its strings do not fit.
bool is_fit_error(const Diagnostic& d) {
    return d.severity == Severity::error && (d.rule == "sii-image-too-large" || d.rule == "sii-too-many-strings");
}

bool does_not_fit(const BuildResult& result) {
    return std::any_of(result.diagnostics.begin(), result.diagnostics.end(), is_fit_error);
}

void append_to_fit_errors(BuildResult& result, std::string_view text) {
    for (auto& d : result.diagnostics.items())
        if (is_fit_error(d)) d.message += text;
}

SourcePos byte_size_pos(const Device& device) {
    if (!device.eeprom) return device.pos;
    return device.eeprom->byte_size_pos.known() ? device.eeprom->byte_size_pos : device.eeprom->pos;
}

}  // namespace

BuildResult build_image(const EtherCATInfo& info, const Device& device, const BuildOptions& options, const std::string& path) {
    BuildResult full = build_with(info, device, options, {}, path);
    if (full.from_eeprom_data || !does_not_fit(full)) return full;
    if (!options.fit_to_eeprom) {
        append_to_fit_errors(full, "; without --strict-size optional content is left out until the image fits (docs/sii.md §1)");
        return full;
    }
    const std::vector<FitStep> steps = fit_steps(device, options);
    for (std::size_t taken = 0; taken < steps.size(); ++taken) {
        BuildResult reduced = build_with(info, device, options, steps[taken].omissions, path);
        if (does_not_fit(reduced)) {
            if (taken + 1 < steps.size()) continue;
            std::string left_out;
            for (const auto& step : steps) left_out += (left_out.empty() ? "" : ", ") + step.what;
            append_to_fit_errors(reduced, fmt::format(" even without {}: the mandatory part (header, Strings, General, FMMU, "
                                                      "SyncM and the ESI's Eeprom/Category entries) does not fit",
                                                      left_out));
            return reduced;
        }
        reduced.omitted = steps[taken].omissions;
        for (std::size_t k = 0; k <= taken; ++k) {
            reduced.left_out.push_back(steps[k].what);
            reduced.diagnostics.emplace(Severity::info, "sii-left-out",
                                        fmt::format("{} left out so that the image fits its {}-byte EEPROM ({} bytes with "
                                                    "everything, {} without): {}",
                                                    steps[k].what, reduced.eeprom_bytes, full.content_bytes, reduced.content_bytes,
                                                    steps[k].why),
                                        path, byte_size_pos(device));
        }
        return reduced;
    }
    append_to_fit_errors(full, "; the device has no optional content to leave out: the mandatory part (header, Strings, General, "
                               "FMMU, SyncM and the ESI's Eeprom/Category entries) does not fit");
    return full;
}

}  // namespace esi::sii
