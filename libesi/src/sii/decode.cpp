#include "esi/sii/decode.hpp"

#include <algorithm>
#include <fmt/format.h>

#include "byte_io.hpp"
#include "esi/sii/encode.hpp"

namespace esi::sii {

namespace {

void fault(std::vector<Fault>& faults, Severity severity, std::string rule, std::uint64_t offset, std::string message) {
    faults.push_back(Fault{severity, std::move(rule), std::move(message), offset});
}

std::string category_label(std::uint16_t type) {
    return fmt::format("{} category ({})", category_name(type), type);
}

Strings decode_strings(std::span<const std::uint8_t> payload, std::uint64_t at, std::vector<Fault>& faults) {
    Strings out;
    if (payload.empty()) {
        fault(faults, Severity::warning, "sii-strings-empty", at, "Strings category has no payload (not even the string count)");
        return out;
    }
    ByteReader r(payload);
    const std::size_t count = r.u8();
    out.items.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        const std::size_t length_at = r.position();
        if (r.remaining() == 0) {
            fault(faults, Severity::error, "sii-strings-overrun", at + length_at,
                  fmt::format("Strings category declares {} strings but ends after {}", count, i));
            break;
        }
        const std::size_t length = r.u8();
        if (length > r.remaining()) {
            fault(faults, Severity::error, "sii-strings-overrun", at + length_at,
                  fmt::format("string {} declares {} bytes but only {} remain in the Strings category", i + 1, length,
                              r.remaining()));
            break;
        }
        const std::size_t start = r.position();
        out.items.emplace_back(reinterpret_cast<const char*>(payload.data() + start), length);
        r.skip(length);
    }
    return out;
}

General decode_general(ByteReader& r) {
    General g;
    g.group_idx = r.u8();
    g.image_idx = r.u8();
    g.order_idx = r.u8();
    g.name_idx = r.u8();
    g.reserved_4 = r.u8();
    g.coe_details = r.u8();
    g.foe_details = r.u8();
    g.eoe_details = r.u8();
    g.soe_channels = r.u8();
    g.ds402_channels = r.u8();
    g.sysman_class = r.u8();
    g.flags = r.u8();
    g.current_on_ebus = static_cast<std::int16_t>(r.u16());
    g.group_idx_duplicate = r.u8();
    g.reserved_15 = r.u8();
    g.physical_ports = r.u16();
    g.physical_memory_address = r.u16();
    for (auto& b : g.reserved_20) b = r.u8();
    return g;
}

}  // namespace

CategoryContent decode_content(std::uint16_t type, std::span<const std::uint8_t> payload, std::uint64_t at,
                               std::vector<Fault>& faults) {
    switch (type) {
        case category::strings: return decode_strings(payload, at, faults);
        case category::general: {
            if (payload.size() < general_bytes) {
                fault(faults, Severity::error, "sii-general-size", at,
                      fmt::format("General category has {} bytes; it must have {} (IgH rejects other sizes)", payload.size(),
                                  general_bytes));
                return RawData{{payload.begin(), payload.end()}};
            }
            if (payload.size() > general_bytes)
                fault(faults, Severity::error, "sii-general-size", at,
                      fmt::format("General category has {} bytes; it must have {} (IgH rejects other sizes)", payload.size(),
                                  general_bytes));
            ByteReader r(payload);
            return decode_general(r);
        }
        case category::fmmu: return Fmmus{{payload.begin(), payload.end()}};
        case category::sync_manager: {
            if (payload.size() % sync_manager_bytes != 0)
                fault(faults, Severity::error, "sii-sync-manager-size", at,
                      fmt::format("SyncM category has {} bytes, not a multiple of {}; the last {} bytes are ignored",
                                  payload.size(), sync_manager_bytes, payload.size() % sync_manager_bytes));
            SyncManagers out;
            ByteReader r(payload);
            while (r.remaining() >= sync_manager_bytes) {
                SyncManagerRecord sm;
                sm.start_address = r.u16();
                sm.length = r.u16();
                sm.control = r.u8();
                sm.status = r.u8();
                sm.enable = r.u8();
                sm.type = r.u8();
                out.items.push_back(sm);
            }
            return out;
        }
        case category::tx_pdo:
        case category::rx_pdo: {
            Pdos out;
            ByteReader r(payload);
            while (r.remaining() > 0) {
                const std::size_t pdo_at = r.position();
                if (r.remaining() < pdo_header_bytes) {
                    fault(faults, Severity::error, "sii-pdo-overrun", at + pdo_at,
                          fmt::format("{} ends with {} stray bytes, too few for a PDO header ({} bytes)", category_label(type),
                                      r.remaining(), pdo_header_bytes));
                    break;
                }
                PdoRecord pdo;
                pdo.index = r.u16();
                const std::size_t entry_count = r.u8();
                pdo.sync_manager = r.u8();
                pdo.dc_sync = r.u8();
                pdo.name_idx = r.u8();
                pdo.flags = r.u16();
                if (entry_count * pdo_entry_bytes > r.remaining()) {
                    fault(faults, Severity::error, "sii-pdo-overrun", at + pdo_at,
                          fmt::format("PDO 0x{:04X} declares {} entries ({} bytes) but only {} bytes remain in the {}",
                                      pdo.index, entry_count, entry_count * pdo_entry_bytes, r.remaining(),
                                      category_label(type)));
                    break;
                }
                pdo.entries.reserve(entry_count);
                for (std::size_t i = 0; i < entry_count; ++i) {
                    PdoEntryRecord e;
                    e.index = r.u16();
                    e.subindex = r.u8();
                    e.name_idx = r.u8();
                    e.data_type = r.u8();
                    e.bit_len = r.u8();
                    e.flags = r.u16();
                    pdo.entries.push_back(e);
                }
                out.items.push_back(std::move(pdo));
            }
            return out;
        }
        case category::dc: {
            if (payload.size() % dc_op_mode_bytes != 0)
                fault(faults, Severity::error, "sii-dc-size", at,
                      fmt::format("DC category has {} bytes, not a multiple of {} (ETG.2010 Table 12); the last {} bytes are "
                                  "ignored",
                                  payload.size(), dc_op_mode_bytes, payload.size() % dc_op_mode_bytes));
            DcOpModes out;
            ByteReader r(payload);
            while (r.remaining() >= dc_op_mode_bytes) {
                DcOpModeRecord m;
                m.cycle_time0 = r.u32();
                m.shift_time0 = r.u32();
                m.shift_time1 = r.u32();
                m.sync1_cycle_factor = static_cast<std::int16_t>(r.u16());
                m.assign_activate = r.u16();
                m.sync0_cycle_factor = static_cast<std::int16_t>(r.u16());
                m.name_idx = r.u8();
                m.desc_idx = r.u8();
                for (auto& b : m.reserved) b = r.u8();
                out.items.push_back(m);
            }
            return out;
        }
        default: return RawData{{payload.begin(), payload.end()}};
    }
}

namespace {

void decode_header(std::span<const std::uint8_t> bytes, DecodedImage& out) {
    ByteReader r(bytes);
    Header& h = out.image.header;
    for (auto& b : h.config_data) b = r.u8();
    h.checksum = r.u16();
    h.vendor_id = r.u32();
    h.product_code = r.u32();
    h.revision_no = r.u32();
    h.serial_no = r.u32();
    h.execution_delay = r.u16();
    h.port0_delay = r.u16();
    h.port1_delay = r.u16();
    h.reserved_0x13 = r.u16();
    h.bootstrap_receive_offset = r.u16();
    h.bootstrap_receive_size = r.u16();
    h.bootstrap_send_offset = r.u16();
    h.bootstrap_send_size = r.u16();
    h.standard_receive_offset = r.u16();
    h.standard_receive_size = r.u16();
    h.standard_send_offset = r.u16();
    h.standard_send_size = r.u16();
    h.mailbox_protocols = r.u16();
    for (auto& w : h.reserved_0x1d) w = r.u16();
    h.size = r.u16();
    h.version = r.u16();
    out.header_complete = !r.overrun();
}

void check_header(std::span<const std::uint8_t> bytes, DecodedImage& out) {
    const Header& h = out.image.header;
    if (bytes.size() >= config_area_bytes + 1) {
        out.computed_crc = config_crc(bytes.subspan(0, config_area_bytes));
        if (h.checksum == crc_disabled_marker) {
            fault(out.faults, Severity::warning, "sii-crc-disabled", 2 * word::checksum,
                  "checksum word is 0x88A4, which makes the ESC skip the CRC check (debugging only, never for production)");
        } else if ((h.checksum & 0xFF) != out.computed_crc) {
            fault(out.faults, Severity::error, "sii-crc", 2 * word::checksum,
                  fmt::format("checksum byte is 0x{:02X} but the CRC-8 of words 0-6 is 0x{:02X}; the ESC will refuse the "
                              "configuration area",
                              h.checksum & 0xFF, out.computed_crc));
        } else {
            out.crc_ok = true;
        }
    }
    if (!out.header_complete) return;
    if (h.version != 1)
        fault(out.faults, Severity::warning, "sii-version", 2 * word::version,
              fmt::format("version word is {}, expected 1", h.version));
    if (h.mailbox_protocols != 0 && (h.standard_receive_size == 0 || h.standard_send_size == 0))
        fault(out.faults, Severity::warning, "sii-mailbox-size", 2 * word::standard_receive_offset,
              fmt::format("mailbox protocols 0x{:04X} are announced but a standard mailbox size (words 0x19/0x1B) is 0",
                          h.mailbox_protocols));
}

// The categories decode_content turns into records (the others stay raw bytes anyway).
bool is_typed(std::uint16_t type) {
    switch (type) {
        case category::strings:
        case category::general:
        case category::fmmu:
        case category::sync_manager:
        case category::tx_pdo:
        case category::rx_pdo:
        case category::dc: return true;
        default: return false;
    }
}

// The category walk of ETG.1000.6 (and IgH sii_write): type word, length word in words, payload.
void walk_categories(std::span<const std::uint8_t> bytes, DecodedImage& out) {
    const std::uint64_t size = bytes.size();
    const std::uint64_t declared = out.image.header.eeprom_bytes();
    std::uint64_t pos = header_bytes;
    std::size_t blank_run = 0;
    std::uint64_t blank_start = 0;
    bool past_size_reported = false;
    std::size_t decoded_bytes = 0;  // payload of typed categories decoded so far
    bool decode_limit_reported = false;
    while (true) {
        if (pos + 2 > size) {
            fault(out.faults, Severity::error, "sii-no-end-marker", std::min(pos, size),
                  fmt::format("the category chain reaches the end of the image ({} bytes) without the end marker 0xFFFF",
                              size));
            return;
        }
        // Past the declared size a real EEPROM wraps around, so a master reading on loops or
        // reads the header as categories. Reported once; the file is still decoded to its end
        // so that the dump shows what is there.
        if (pos + 2 > declared && !past_size_reported) {
            fault(out.faults, Severity::error, "sii-chain-past-size", pos,
                  fmt::format("the category chain goes on at 0x{:04X} but word 0x3E (0x{:04X}) declares an EEPROM of {} "
                              "bytes; a master reading on wraps around",
                              pos, out.image.header.size, declared));
            past_size_reported = true;
        }
        const std::uint16_t type = static_cast<std::uint16_t>(bytes[pos] | (bytes[pos + 1] << 8));
        if (type == end_marker) {
            out.end_offset = pos;
            return;
        }
        if (out.image.categories.size() >= max_categories) {
            fault(out.faults, Severity::error, "sii-too-many-categories", pos,
                  fmt::format("the category chain has more than {} categories at 0x{:04X}; the walk stops here (real "
                              "images have a few dozen)",
                              max_categories, pos));
            return;
        }
        if (pos + 4 > size) {
            fault(out.faults, Severity::error, "sii-category-truncated", pos,
                  fmt::format("{} header at 0x{:04X} is cut off by the end of the image", category_label(type), pos));
            return;
        }
        const std::uint16_t words = static_cast<std::uint16_t>(bytes[pos + 2] | (bytes[pos + 3] << 8));
        const std::uint64_t payload_at = pos + 4;
        const std::uint64_t payload_end = payload_at + 2u * words;
        if (payload_end > size) {
            fault(out.faults, Severity::error, "sii-category-overrun", pos,
                  fmt::format("{} at 0x{:04X} declares {} words ({} bytes) but only {} bytes remain in the image",
                              category_label(type), pos, words, 2u * words, size - payload_at));
            Category partial;
            partial.type = type;
            partial.offset = static_cast<std::uint32_t>(pos);
            partial.declared_words = words;
            partial.content = RawData{{bytes.begin() + static_cast<std::ptrdiff_t>(payload_at), bytes.end()}};
            out.image.categories.push_back(std::move(partial));
            return;
        }
        if (payload_end + 2 > declared && !past_size_reported) {
            fault(out.faults, Severity::error, "sii-chain-past-size", pos,
                  fmt::format("{} at 0x{:04X} ends at 0x{:04X}, past the {} bytes word 0x3E (0x{:04X}) declares",
                              category_label(type), pos, payload_end, declared, out.image.header.size));
            past_size_reported = true;
        }
        if (type == category::nop && words == 0) {
            if (blank_run == 0) blank_start = pos;
            if (++blank_run >= blank_category_run_limit) {
                fault(out.faults, Severity::error, "sii-chain-blank", blank_start,
                      fmt::format("the category chain runs into blank memory: {} empty NOP categories in a row from 0x{:04X} "
                                  "(erased or zeroed EEPROM?)",
                                  blank_run, blank_start));
                return;
            }
        } else {
            blank_run = 0;
        }
        Category c;
        c.type = type;
        c.offset = static_cast<std::uint32_t>(pos);
        c.declared_words = words;
        const auto payload = bytes.subspan(payload_at, 2u * words);
        if (is_typed(type) && decoded_bytes + payload.size() > max_decoded_payload_bytes) {
            if (!decode_limit_reported)
                fault(out.faults, Severity::warning, "sii-decode-limit", pos,
                      fmt::format("{} at 0x{:04X} and every typed category after it are kept as raw bytes: the image has "
                                  "more than {} bytes of them (real images have a few KiB)",
                                  category_label(type), pos, max_decoded_payload_bytes));
            decode_limit_reported = true;
            c.content = RawData{{payload.begin(), payload.end()}};
        } else {
            if (is_typed(type)) decoded_bytes += payload.size();
            c.content = decode_content(type, payload, payload_at, out.faults);
        }
        out.image.categories.push_back(std::move(c));
        pos = payload_end;
    }
}

// Checks across categories: duplicates, string references, mailbox words vs SyncM category.
void check_categories(DecodedImage& out) {
    const Image& image = out.image;
    for (const std::uint16_t type : {category::strings, category::general, category::fmmu, category::sync_manager,
                                     category::tx_pdo, category::rx_pdo, category::dc}) {
        const Category* first = nullptr;
        for (const auto& c : image.categories) {
            if (c.type != type) continue;
            if (!first) {
                first = &c;
                continue;
            }
            fault(out.faults, Severity::warning, "sii-duplicate-category", c.offset,
                  fmt::format("second {} (the first is at 0x{:04X}); masters read only the first", category_label(type),
                              first->offset));
        }
    }
    const bool chain_complete = out.end_offset.has_value();
    if (out.header_complete && chain_complete && !image.find(category::general))
        fault(out.faults, Severity::warning, "sii-no-general", header_bytes,
              "the image has no General category (masters read CoE/FoE/EoE details and the port types from it)");

    const std::size_t string_count = image.strings() ? image.strings()->items.size() : 0;
    auto check_index = [&](std::uint8_t index, std::uint64_t at, std::string_view what) {
        if (index == 0 || index <= string_count) return;
        fault(out.faults, Severity::warning, "sii-string-index", at,
              fmt::format("{} refers to string {} but the Strings category has {}", what, index, string_count));
    };
    for (const auto& c : image.categories) {
        const std::uint64_t payload = c.offset + 4u;
        if (const auto* g = std::get_if<General>(&c.content)) {
            check_index(g->group_idx, payload + 0, "General group index");
            check_index(g->image_idx, payload + 1, "General image index");
            check_index(g->order_idx, payload + 2, "General order index");
            check_index(g->name_idx, payload + 3, "General name index");
        } else if (const auto* p = std::get_if<Pdos>(&c.content)) {
            std::uint64_t at = payload;
            for (const auto& pdo : p->items) {
                check_index(pdo.name_idx, at + 5, fmt::format("PDO 0x{:04X} name", pdo.index));
                std::uint64_t entry_at = at + pdo_header_bytes;
                for (const auto& e : pdo.entries) {
                    check_index(e.name_idx, entry_at + 3, fmt::format("PDO 0x{:04X} entry 0x{:04X}:{:02X} name", pdo.index, e.index, e.subindex));
                    entry_at += pdo_entry_bytes;
                }
                at = entry_at;
            }
        } else if (const auto* d = std::get_if<DcOpModes>(&c.content)) {
            std::uint64_t at = payload;
            for (const auto& m : d->items) {
                check_index(m.name_idx, at + 0x12, "DC op mode name");
                check_index(m.desc_idx, at + 0x13, "DC op mode description");
                at += dc_op_mode_bytes;
            }
        }
    }

    // Masters set up the mailbox SyncManagers from words 0x18-0x1B; a SyncM category that says
    // otherwise is the "Invalid mailbox configuration" field failure (SOEM #459).
    if (const SyncManagers* sms = image.sync_managers(); sms && out.header_complete) {
        const Header& h = image.header;
        const Category* cat = image.find(category::sync_manager);
        for (std::size_t i = 0; i < sms->items.size(); ++i) {
            const auto& sm = sms->items[i];
            const std::uint64_t at = cat->offset + 4u + i * sync_manager_bytes;
            if (sm.type == sm_type::mailbox_out &&
                (sm.start_address != h.standard_receive_offset || sm.length != h.standard_receive_size))
                fault(out.faults, Severity::warning, "sii-mailbox-sm-mismatch", at,
                      fmt::format("SyncM {} (MBoxOut) is 0x{:04X}/{} bytes but words 0x18/0x19 say 0x{:04X}/{}", i,
                                  sm.start_address, sm.length, h.standard_receive_offset, h.standard_receive_size));
            if (sm.type == sm_type::mailbox_in &&
                (sm.start_address != h.standard_send_offset || sm.length != h.standard_send_size))
                fault(out.faults, Severity::warning, "sii-mailbox-sm-mismatch", at,
                      fmt::format("SyncM {} (MBoxIn) is 0x{:04X}/{} bytes but words 0x1A/0x1B say 0x{:04X}/{}", i,
                                  sm.start_address, sm.length, h.standard_send_offset, h.standard_send_size));
        }
    }
}

}  // namespace

bool DecodedImage::has_errors() const { return count(Severity::error) > 0; }

std::size_t DecodedImage::count(Severity severity) const {
    return static_cast<std::size_t>(
        std::count_if(faults.begin(), faults.end(), [&](const Fault& f) { return f.severity == severity; }));
}

namespace {

// PDI control 0 leaves a microcontroller no access to the ESC; it is a fault when the image itself
// says the device has one to serve (a mailbox or PDOs) and the ESC does not emulate the device
// (0x0141 bit 0, as couplers without a microcontroller have).
void check_pdi(DecodedImage& out) {
    const Header& h = out.image.header;
    const std::uint8_t pdi_control = h.config_data[0];
    const bool device_emulation = (h.config_data[1] & 0x01) != 0;
    if (pdi_control != 0 || device_emulation) return;
    const bool mailbox = h.standard_receive_size != 0 || h.mailbox_protocols != 0;
    const bool process_data = out.image.find(category::tx_pdo) || out.image.find(category::rx_pdo);
    if (!mailbox && !process_data) return;
    fault(out.faults, Severity::error, "sii-pdi-off", 0,
          fmt::format("PDI control (word 0) is 0: the ESC's process data interface is off and the ESC does not emulate the "
                      "device, but the image describes {}, which only a microcontroller behind the PDI can serve; the "
                      "device stays in INIT",
                      mailbox && process_data ? "a mailbox and process data" : mailbox ? "a mailbox" : "process data"));
}

}  // namespace

DecodedImage decode_image(std::span<const std::uint8_t> bytes) {
    DecodedImage out;
    out.byte_count = bytes.size();
    decode_header(bytes, out);
    if (!out.header_complete) {
        fault(out.faults, Severity::error, "sii-truncated", bytes.size(),
              fmt::format("the image has {} bytes; the header alone takes {} and a valid image at least {} (0x41 words)",
                          bytes.size(), header_bytes, minimum_image_bytes));
    }
    if (bytes.size() % 2 != 0)
        fault(out.faults, Severity::warning, "sii-odd-length", bytes.size() - 1,
              fmt::format("the image has an odd number of bytes ({}); the EEPROM is organised in words", bytes.size()));
    check_header(bytes, out);
    if (out.header_complete) {
        walk_categories(bytes, out);
        check_categories(out);
        check_pdi(out);
        if (bytes.size() > out.image.header.eeprom_bytes())
            fault(out.faults, Severity::warning, "sii-larger-than-size", out.image.header.eeprom_bytes(),
                  fmt::format("the image has {} bytes but word 0x3E (0x{:04X}) declares an EEPROM of {} bytes",
                              bytes.size(), out.image.header.size, out.image.header.eeprom_bytes()));
    }
    std::stable_sort(out.faults.begin(), out.faults.end(), [](const Fault& a, const Fault& b) { return a.offset < b.offset; });
    return out;
}

Diagnostics to_diagnostics(const std::vector<Fault>& faults, const std::string& path) {
    Diagnostics out;
    for (const auto& f : faults)
        out.emplace(f.severity, f.rule, fmt::format("byte 0x{:04X}: {}", f.offset, f.message), path, {});
    return out;
}

}  // namespace esi::sii
