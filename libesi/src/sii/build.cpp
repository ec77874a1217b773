#include "esi/sii/build.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "esi/number.hpp"
#include "esi/sii/decode.hpp"
#include "esi/sii/encode.hpp"
#include "esi/sii/mapping.hpp"
#include "esi/sii/text.hpp"
#include "fit.hpp"

namespace esi::sii {

namespace {

constexpr std::size_t max_strings = 255;
constexpr std::size_t max_string_bytes = 255;

class Builder {
public:
    Builder(const EtherCATInfo& info, const Device& device, const BuildOptions& options, const Omissions& omitted,
            const std::string& path, BuildResult& result)
        : info_(info), device_(device), options_(options), omitted_(omitted), path_(path), result_(result) {}

    void run();

private:
    Diagnostic& diag(Severity severity, std::string rule, std::string message, SourcePos pos) {
        return result_.diagnostics.emplace(severity, std::move(rule), std::move(message), path_, pos);
    }

    // Value -> field of `bits` bits; an error (never a silent truncation) when it does not fit.
    std::uint64_t fit_unsigned(std::int64_t value, unsigned bits, std::string_view what, SourcePos pos) {
        const std::uint64_t max = bits >= 64 ? ~0ull : ((1ull << bits) - 1);
        if (value < 0 || static_cast<std::uint64_t>(value) > max) {
            diag(Severity::error, "sii-value-range",
                 fmt::format("{} is {}; the SII field holds {}-bit unsigned values (0..{})", what, value, bits, max), pos);
            return static_cast<std::uint64_t>(value) & max;
        }
        return static_cast<std::uint64_t>(value);
    }
    std::int64_t fit_signed(std::int64_t value, unsigned bits, std::string_view what, SourcePos pos) {
        const std::int64_t max = (std::int64_t{1} << (bits - 1)) - 1;
        const std::int64_t min = -max - 1;
        if (value < min || value > max)
            diag(Severity::error, "sii-value-range",
                 fmt::format("{} is {}; the SII field holds {}-bit signed values ({}..{})", what, value, bits, min, max), pos);
        return value;
    }
    // Shift times are signed in the ESI (ns) and stored as 32 bits: accept both ranges.
    std::uint32_t fit_time(std::int64_t value, std::string_view what, SourcePos pos) {
        if (value < INT32_MIN || value > static_cast<std::int64_t>(UINT32_MAX))
            diag(Severity::error, "sii-value-range",
                 fmt::format("{} is {} ns; the SII field holds 32 bits", what, value), pos);
        return static_cast<std::uint32_t>(static_cast<std::uint64_t>(value) & 0xFFFFFFFFu);
    }

    std::uint8_t add_string(std::string_view utf8, SourcePos pos, std::string_view what);
    const std::string& localized(const Names& names) const {
        if (const LocalizedText* t = find_lcid(names, options_.name_lcid)) return t->text;
        return primary_text(names);
    }

    void build_header();
    void build_copied_categories();
    General build_general();
    void build_fmmus();
    void build_sync_managers();
    std::optional<DcOpModes> build_dc();
    Pdos build_pdos(const std::vector<Pdo>& pdos);
    void finish();
    static bool is_generated(std::uint16_t type);
    // Appends a generated category, or the explicit Eeprom/Category of that type instead.
    void add_category(std::uint16_t type, CategoryContent content);

    const EtherCATInfo& info_;
    const Device& device_;
    const BuildOptions& options_;
    const Omissions& omitted_;
    const std::string& path_;
    BuildResult& result_;
    Image& image_ = result_.image;

    std::vector<std::string> strings_;
    std::map<std::string, std::uint8_t, std::less<>> string_index_;
    std::size_t distinct_strings_ = 0;
    SourcePos first_overflow_pos_;
    std::map<std::uint16_t, Category> explicit_;  // Eeprom/Category entries of generated types
};

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

void Builder::build_copied_categories() {
    if (!device_.eeprom) return;
    for (const auto& cat : device_.eeprom->categories) {
        const SourcePos pos = cat.cat_no_pos.known() ? cat.cat_no_pos : cat.pos;
        if (cat.cat_no >= category::end) {
            diag(Severity::error, "sii-category-number",
                 fmt::format("Eeprom/Category CatNo {} is not a category number (0..0xFFFE)", cat.cat_no), pos);
            continue;
        }
        RawData raw;
        if (cat.data) {
            const auto bytes = cat.data->bytes();
            if (!bytes) {
                diag(Severity::error, "sii-category-data", "Eeprom/Category/Data is not valid hexBinary", cat.data->pos);
                continue;
            }
            raw.bytes = *bytes;
        } else if (cat.data_string) {
            const std::string s = to_sii_text(*cat.data_string);
            raw.bytes.assign(s.begin(), s.end());
        } else if (cat.data_uint) {
            const auto v = fit_unsigned(static_cast<std::int64_t>(*cat.data_uint), 16, "Eeprom/Category/DataUINT", cat.pos);
            raw.bytes = {static_cast<std::uint8_t>(v & 0xFF), static_cast<std::uint8_t>(v >> 8)};
        } else if (cat.data_udint) {
            const auto v = fit_unsigned(static_cast<std::int64_t>(*cat.data_udint), 32, "Eeprom/Category/DataUDINT", cat.pos);
            for (int i = 0; i < 4; ++i) raw.bytes.push_back(static_cast<std::uint8_t>((v >> (8 * i)) & 0xFF));
        } else {
            diag(Severity::warning, "sii-category-data", fmt::format("Eeprom/Category {} has no payload; it is written empty", cat.cat_no), cat.pos);
        }
        // The length word counts 16-bit words: a longer payload would be written with a
        // truncated length and break the category chain after it.
        if ((raw.bytes.size() + 1) / 2 > max_category_words) {
            diag(Severity::error, "sii-category-size",
                 fmt::format("Eeprom/Category {} has {} bytes of data; a category holds at most {} words ({} bytes), its "
                             "length word is 16 bits",
                             cat.cat_no, raw.bytes.size(), max_category_words, 2 * max_category_words),
                 cat.data ? cat.data->pos : pos);
            continue;
        }
        const auto type = static_cast<std::uint16_t>(cat.cat_no);
        if (!is_generated(type)) {
            image_.categories.push_back(Category{type, std::move(raw), 0, 0});
            continue;
        }
        // An explicit category of a type the builder writes itself wins (explicit declarations
        // win): it takes the generated one's place. It is decoded to report what a master
        // will trip over, since nothing else checks vendor-written bytes.
        if (explicit_.count(type)) {
            diag(Severity::warning, "sii-category-duplicate",
                 fmt::format("a second Eeprom/Category {} ({}); only the first is written", cat.cat_no, category_name(type)), pos);
            continue;
        }
        diag(type == category::strings ? Severity::warning : Severity::info, "sii-category-explicit",
             fmt::format("Eeprom/Category {} replaces the {} category the builder would write{}", cat.cat_no, category_name(type),
                         type == category::strings ? "; the string indices of the other categories then point into it" : ""),
             pos);
        std::vector<Fault> faults;
        CategoryContent content = decode_content(type, raw.bytes, 0, faults);
        for (const auto& f : faults)
            diag(Severity::warning, "sii-category-explicit",
                 fmt::format("Eeprom/Category {} ({}), payload byte {}: {}", cat.cat_no, category_name(type), f.offset, f.message), pos);
        // Keep the vendor's bytes exactly unless they decode cleanly.
        explicit_.emplace(type, Category{type, faults.empty() ? std::move(content) : CategoryContent{std::move(raw)}, 0, 0});
    }
}

bool Builder::is_generated(std::uint16_t type) {
    return type == category::strings || type == category::general || type == category::fmmu || type == category::sync_manager ||
           type == category::tx_pdo || type == category::rx_pdo || type == category::dc;
}

void Builder::add_category(std::uint16_t type, CategoryContent content) {
    if (const auto it = explicit_.find(type); it != explicit_.end()) {
        image_.categories.push_back(std::move(it->second));
        explicit_.erase(it);
        return;
    }
    image_.categories.push_back(Category{type, std::move(content), 0, 0});
}

General Builder::build_general() {
    General g;
    g.order_idx = add_string(device_.type.text, device_.type.pos, "Type");
    if (device_.group_type) g.group_idx = add_string(*device_.group_type, device_.group_type_pos, "GroupType");
    g.name_idx = add_string(localized(device_.names), device_.pos, "Device Name");
    g.group_idx_duplicate = g.group_idx;

    if (device_.mailbox) {
        const Mailbox& mb = *device_.mailbox;
        g.coe_details = coe_details_byte(mb);
        if (mb.foe) g.foe_details = 1;
        if (mb.eoe) g.eoe_details = 1;
        if (mb.soe)
            g.soe_channels = static_cast<std::uint8_t>(
                fit_unsigned(mb.soe->channel_count.value_or(1), 8, "SoE@ChannelCount", mb.soe->pos));
        if (mb.coe && mb.coe->ds402_channels)
            g.ds402_channels = static_cast<std::uint8_t>(fit_unsigned(*mb.coe->ds402_channels, 8, "CoE@DS402Channels", mb.coe->pos));
        if (mb.data_link_layer.value_or(false)) g.flags |= general_flag::mailbox_data_link_layer;
    }
    if (const XmlAttribute* a = device_.type.extras.attribute("UseLrdLwr"); a && parse_boolean(a->value).value_or(false))
        g.flags |= general_flag::enable_not_lrw;
    if (const XmlElement* e = device_.extras.find("Info/IdentificationReg134"); e && parse_boolean(e->text).value_or(false))
        g.flags |= general_flag::ident_al_status;
    if (const XmlElement* e = device_.extras.find("Info/IdentificationAdo")) {
        const ParsedNumber n = parse_number(e->text);
        if (n.ok() && !n.value.negative) {
            g.flags |= general_flag::ident_physical_memory;
            g.physical_memory_address = static_cast<std::uint16_t>(
                fit_unsigned(static_cast<std::int64_t>(n.value.magnitude & 0x7FFFFFFFFFFFFFFFull), 16, "Info/IdentificationAdo", e->pos));
        }
    }
    if (const XmlElement* e = device_.extras.find("Info/Electrical/EBusCurrent")) {
        if (const auto mA = ebus_current(device_))
            g.current_on_ebus = static_cast<std::int16_t>(fit_signed(*mA, 16, "Info/Electrical/EBusCurrent", e->pos));
        else
            diag(Severity::warning, "sii-ebus-current", fmt::format("Info/Electrical/EBusCurrent \"{}\" is not a number", e->text), e->pos);
    }

    // Physics: one letter per port, port 0 in the low nibble of bytes 16-17 (ETG.2010; the real
    // EK1100 image holds 0x0131 for Physics="YKY").
    if (device_.physics.size() > 4)
        diag(Severity::warning, "sii-physics",
             fmt::format("Physics \"{}\" names {} ports; the General category has room for 4", device_.physics,
                         device_.physics.size()),
             device_.pos);
    for (std::size_t i = 0; i < device_.physics.size() && i < 4; ++i) {
        const auto code = port_code(device_.physics[i]);
        if (!code)
            diag(Severity::warning, "sii-physics",
                 fmt::format("Physics letter '{}' (port {}) is not Y, H, K or space; the port is written as not used",
                             device_.physics[i], i),
                 device_.pos);
        g.physical_ports |= static_cast<std::uint16_t>(code.value_or(0) << (4 * i));
    }
    return g;
}

void Builder::build_fmmus() {
    if (device_.fmmus.empty()) return;
    Fmmus f;
    for (const auto& fmmu : device_.fmmus) {
        const auto code = fmmu_usage_code(fmmu.type);
        if (!code)
            diag(Severity::warning, "sii-fmmu-type",
                 fmt::format("Fmmu \"{}\" has no SII usage code; it is written as not used (0)", fmmu.type), fmmu.pos);
        f.usages.push_back(code.value_or(fmmu_usage::unused));
    }
    add_category(category::fmmu, std::move(f));
}

void Builder::build_sync_managers() {
    if (device_.sms.empty()) return;
    SyncManagers s;
    for (std::size_t i = 0; i < device_.sms.size(); ++i) {
        const SyncManager& sm = device_.sms[i];
        SyncManagerRecord r;
        r.start_address = static_cast<std::uint16_t>(fit_unsigned(sm.start_address.value_or(0), 16, fmt::format("Sm {} StartAddress", i), sm.pos));
        r.length = static_cast<std::uint16_t>(fit_unsigned(sm.default_size.value_or(0), 16, fmt::format("Sm {} DefaultSize", i), sm.pos));
        r.control = static_cast<std::uint8_t>(fit_unsigned(sm.control_byte.value_or(0), 8, fmt::format("Sm {} ControlByte", i), sm.pos));
        if (sm.enable && *sm.enable > 0xFF) fit_unsigned(*sm.enable, 8, fmt::format("Sm {} Enable", i), sm.pos);
        r.enable = sm_enable_byte(sm);
        const auto type = sm_type_code(sm.type);
        if (!type)
            diag(Severity::warning, "sii-sm-type",
                 fmt::format("Sm {} \"{}\" has no SII type code; it is written as unused (0)", i, sm.type), sm.pos);
        r.type = type.value_or(sm_type::unused);
        s.items.push_back(r);
    }
    add_category(category::sync_manager, std::move(s));
}

std::optional<DcOpModes> Builder::build_dc() {
    if (!options_.include_dc || omitted_.dc || !device_.dc) return std::nullopt;
    DcOpModes dc;
    std::size_t skipped = 0;
    for (const auto& op : device_.dc->op_modes) {
        if (is_legacy_op_mode(op)) {
            ++skipped;
            continue;
        }
        DcOpModeRecord r;
        const std::string label = fmt::format("Dc/OpMode \"{}\"", op.name);
        if (op.cycle_time_sync0) {
            r.cycle_time0 = static_cast<std::uint32_t>(fit_unsigned(op.cycle_time_sync0->value, 32, label + " CycleTimeSync0", op.cycle_time_sync0->pos));
            if (op.cycle_time_sync0->factor)
                r.sync0_cycle_factor = static_cast<std::int16_t>(fit_signed(*op.cycle_time_sync0->factor, 16, label + " CycleTimeSync0@Factor", op.cycle_time_sync0->pos));
        }
        if (op.shift_time_sync0) r.shift_time0 = fit_time(op.shift_time_sync0->value, label + " ShiftTimeSync0", op.shift_time_sync0->pos);
        if (op.shift_time_sync1) r.shift_time1 = fit_time(op.shift_time_sync1->value, label + " ShiftTimeSync1", op.shift_time_sync1->pos);
        if (op.cycle_time_sync1) {
            if (op.cycle_time_sync1->factor)
                r.sync1_cycle_factor = static_cast<std::int16_t>(fit_signed(*op.cycle_time_sync1->factor, 16, label + " CycleTimeSync1@Factor", op.cycle_time_sync1->pos));
            if (op.cycle_time_sync1->value != 0)
                diag(Severity::info, "sii-dc-cycle-time1",
                     fmt::format("{} CycleTimeSync1 is {} ns; the ETG.2010 DC category has no field for it (only its "
                                 "Factor), so it is not written",
                                 label, op.cycle_time_sync1->value),
                     op.cycle_time_sync1->pos);
        }
        r.assign_activate = static_cast<std::uint16_t>(fit_unsigned(op.assign_activate, 16, label + " AssignActivate", op.assign_activate_pos));
        r.name_idx = add_string(op.name, op.pos, "Dc/OpMode Name");
        if (op.desc && !omitted_.dc_descriptions) r.desc_idx = add_string(*op.desc, op.pos, "Dc/OpMode Desc");
        dc.items.push_back(r);
    }
    if (skipped > 0)
        diag(Severity::info, "sii-dc-legacy-op-mode",
             fmt::format("{} of {} Dc/OpMode elements are marked VendorSpecific/TwinCAT@IgnoreFromBuildNo (legacy modes) and "
                         "are not written, as in the vendor's own EEPROMs",
                         skipped, device_.dc->op_modes.size()),
             device_.dc->pos);
    if (dc.items.empty()) return std::nullopt;
    return dc;
}

Pdos Builder::build_pdos(const std::vector<Pdo>& pdos) {
    Pdos out;
    for (const auto& pdo : pdos) {
        if (omitted_.unassigned_pdos && !pdo.sm) continue;
        PdoRecord r;
        const std::string label = fmt::format("{} #x{:04X}", pdo.element_name(), pdo.index);
        r.index = static_cast<std::uint16_t>(fit_unsigned(pdo.index, 16, label + " Index", pdo.index_pos));
        if (pdo.sm) r.sync_manager = static_cast<std::uint8_t>(fit_unsigned(*pdo.sm, 8, label + " @Sm", pdo.pos));
        if (pdo.sm && *pdo.sm == pdo_no_sync_manager)
            diag(Severity::warning, "sii-value-range", label + " @Sm is 255, which SII reads as \"no SyncManager\"", pdo.pos);
        r.name_idx = add_string(localized(pdo.names), pdo.pos, label + " Name");
        r.flags = pdo_flags(pdo);
        if (pdo.entries.size() > 255)
            diag(Severity::error, "sii-pdo-entries",
                 fmt::format("{} has {} entries; the SII PDO header counts them in one byte (at most 255)", label, pdo.entries.size()),
                 pdo.pos);
        for (const auto& entry : pdo.entries) {
            PdoEntryRecord e;
            e.index = static_cast<std::uint16_t>(fit_unsigned(entry.index, 16, label + " Entry Index", entry.pos));
            e.subindex = static_cast<std::uint8_t>(fit_unsigned(entry.effective_subindex(), 8, label + " Entry SubIndex", entry.pos));
            e.bit_len = static_cast<std::uint8_t>(fit_unsigned(entry.bit_len, 8, fmt::format("{} Entry #x{:04X}:{:02X} BitLen", label, entry.index, entry.effective_subindex()), entry.bit_len_pos.known() ? entry.bit_len_pos : entry.pos));
            if (!entry.is_padding()) {
                e.name_idx = add_string(localized(entry.names), entry.pos, label + " Entry Name");
                if (const auto code = pdo_entry_data_type(device_, entry)) {
                    e.data_type = *code;
                } else {
                    diag(Severity::info, "sii-data-type",
                         fmt::format("{} entry #x{:04X}:{:02X}: data type \"{}\" has no one-byte CoE code; SII data type 0",
                                     label, entry.index, entry.effective_subindex(), entry.data_type.value_or("")),
                         entry.data_type_pos.known() ? entry.data_type_pos : entry.pos);
                }
            }
            r.entries.push_back(e);
        }
        out.items.push_back(std::move(r));
    }
    return out;
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

BuildResult build_with(const EtherCATInfo& info, const Device& device, const BuildOptions& options, const Omissions& omitted,
                       const std::string& path) {
    BuildResult result;
    Builder(info, device, options, omitted, path, result).run();
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
