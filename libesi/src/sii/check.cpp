#include "esi/sii/check.hpp"

#include <fmt/format.h>

#include "esi/model/mailbox_protocol.hpp"
#include "esi/sii/mapping.hpp"
#include "esi/sii/text.hpp"

namespace esi::sii {

namespace {

std::string protocol_names(std::uint16_t bits) { return mailbox_protocol_names(bits, "none"); }

class Checker {
public:
    Checker(const EtherCATInfo& info, const Device& device, const DecodedImage& decoded, const std::string& esi_path,
            const std::string& image_path)
        : info_(info), device_(device), image_(decoded.image), esi_path_(esi_path), image_path_(image_path) {}

    Diagnostics run();

private:
    void mismatch(Severity severity, std::string rule, std::string message, SourcePos pos, std::uint64_t offset) {
        Diagnostic& d = out_.emplace(severity, std::move(rule), std::move(message), esi_path_, pos);
        d.notes.push_back(DiagnosticNote{image_path_, {}, offset < header_bytes && offset % 2 == 0
                                                              ? fmt::format("image byte 0x{:04X} (word 0x{:02X})", offset, offset / 2)
                                                              : fmt::format("image byte 0x{:04X}", offset)});
    }
    void error(std::string rule, std::string message, SourcePos pos, std::uint64_t offset) {
        mismatch(Severity::error, std::move(rule), std::move(message), pos, offset);
    }

    void identity();
    void mailbox_words();
    void eeprom_words();
    void general();
    void fmmus();
    void sync_managers();
    void pdos(std::uint16_t type, const std::vector<Pdo>& esi_pdos);
    void dc();

    std::uint64_t payload_offset(std::uint16_t type) const {
        const Category* c = image_.find(type);
        return c ? c->offset + 4u : 0;
    }

    const EtherCATInfo& info_;
    const Device& device_;
    const Image& image_;
    const std::string& esi_path_;
    const std::string& image_path_;
    Diagnostics out_;
};

void Checker::identity() {
    const Header& h = image_.header;
    if (info_.vendor && info_.vendor->id && *info_.vendor->id != h.vendor_id)
        error("sii-vendor-id",
              fmt::format("CTT 2-1 vendor id: the ESI has 0x{:08X}, the image 0x{:08X}", *info_.vendor->id, h.vendor_id),
              info_.vendor->id_pos.known() ? info_.vendor->id_pos : info_.vendor->pos, 2 * word::vendor_id);
    if (device_.type.product_code && *device_.type.product_code != h.product_code)
        error("sii-product-code",
              fmt::format("CTT 2-2 product code: the ESI has 0x{:08X}, the image 0x{:08X}", *device_.type.product_code,
                          h.product_code),
              device_.type.pos, 2 * word::product_code);
    if (device_.type.revision_no && *device_.type.revision_no != h.revision_no)
        error("sii-revision",
              fmt::format("CTT 2-3 revision: the ESI has 0x{:08X}, the image 0x{:08X}", *device_.type.revision_no, h.revision_no),
              device_.type.pos, 2 * word::revision_no);
}

void Checker::mailbox_words() {
    const Header& h = image_.header;
    const std::uint16_t expected = device_.mailbox ? device_.mailbox->protocol_bits() : 0;
    if (expected != h.mailbox_protocols)
        error("sii-mailbox-protocols",
              fmt::format("CTT 2-5 mailbox protocols: the ESI names {} (0x{:04X}), word 0x1C holds {} (0x{:04X})",
                          protocol_names(expected), expected, protocol_names(h.mailbox_protocols), h.mailbox_protocols),
              device_.mailbox ? device_.mailbox->pos : device_.pos, 2 * word::mailbox_protocols);

    auto standard = [&](std::string_view type, std::uint16_t offset, std::uint16_t size, std::uint16_t word_address) {
        const SyncManager* sm = find_sm(device_, type);
        if (!sm) return;
        if (sm->start_address && *sm->start_address != offset)
            error("sii-standard-mailbox",
                  fmt::format("{} Sm starts at 0x{:04X}, word 0x{:02X} says 0x{:04X}", type, *sm->start_address, word_address, offset),
                  sm->pos, 2u * word_address);
        if (sm->default_size && *sm->default_size != size)
            error("sii-standard-mailbox",
                  fmt::format("{} Sm DefaultSize is {}, word 0x{:02X} says {}", type, *sm->default_size, word_address + 1, size),
                  sm->pos, 2u * (word_address + 1u));
    };
    standard("MBoxOut", h.standard_receive_offset, h.standard_receive_size, word::standard_receive_offset);
    standard("MBoxIn", h.standard_send_offset, h.standard_send_size, word::standard_send_offset);

    if (device_.eeprom && device_.eeprom->boot_strap) {
        const auto bytes = device_.eeprom->boot_strap->bytes();
        if (bytes && bytes->size() == 8) {
            const std::uint16_t image_words[4] = {h.bootstrap_receive_offset, h.bootstrap_receive_size, h.bootstrap_send_offset,
                                                  h.bootstrap_send_size};
            for (std::size_t i = 0; i < 4; ++i) {
                const auto esi = static_cast<std::uint16_t>((*bytes)[2 * i] | ((*bytes)[2 * i + 1] << 8));
                if (esi != image_words[i])
                    error("sii-boot-strap",
                          fmt::format("Eeprom/BootStrap word {} is 0x{:04X}, image word 0x{:02X} holds 0x{:04X}", i, esi,
                                      word::bootstrap_receive_offset + i, image_words[i]),
                          device_.eeprom->boot_strap->pos, 2u * (word::bootstrap_receive_offset + i));
            }
        }
    }
}

void Checker::eeprom_words() {
    if (!device_.eeprom) return;
    const Eeprom& e = *device_.eeprom;
    const Header& h = image_.header;
    if (e.byte_size && *e.byte_size >= 128 && *e.byte_size % 128 == 0) {
        const std::uint64_t expected = *e.byte_size / 128 - 1;
        if (expected != h.size)
            error("sii-eeprom-size",
                  fmt::format("CTT 2-6 EEPROM size: ByteSize {} means word 0x3E = 0x{:04X}; the image holds 0x{:04X} ({} bytes)",
                              *e.byte_size, expected, h.size, h.eeprom_bytes()),
                  e.byte_size_pos.known() ? e.byte_size_pos : e.pos, 2 * word::size);
    }
    if (e.config_data) {
        if (const auto bytes = e.config_data->bytes()) {
            for (std::size_t i = 0; i < bytes->size() && i < config_area_bytes; i += 2) {
                const std::uint16_t esi =
                    static_cast<std::uint16_t>((*bytes)[i] | (i + 1 < bytes->size() ? (*bytes)[i + 1] << 8 : h.config_data[i + 1] << 8));
                const std::uint16_t img = h.config_word(i / 2);
                if (esi != img)
                    error("sii-config-data",
                          fmt::format("CTT 2-8 ConfigData: bytes {}-{} of the ESI give word 0x{:02X} = 0x{:04X}, the image holds "
                                      "0x{:04X}",
                                      i, std::min(i + 1, bytes->size() - 1), i / 2, esi, img),
                          e.config_data->pos, i);
            }
        }
    }
}

void Checker::general() {
    const General* g = image_.general();
    if (!g) {
        error("sii-general-missing", "CTT 2-10 General category: the image has none", device_.pos,
              image_.find(category::general) ? image_.find(category::general)->offset : header_bytes);
        return;
    }
    const std::uint64_t at = payload_offset(category::general);
    const SourcePos mailbox_pos = device_.mailbox ? device_.mailbox->pos : device_.pos;
    const std::uint8_t coe = device_.mailbox ? coe_details_byte(*device_.mailbox) : 0;
    if (coe != g->coe_details)
        error("sii-general-coe",
              fmt::format("CTT 2-10 General CoE details: the ESI's CoE flags give 0x{:02X}, the image holds 0x{:02X}", coe, g->coe_details),
              device_.mailbox && device_.mailbox->coe ? device_.mailbox->coe->pos : mailbox_pos, at + 5);
    const bool foe = device_.mailbox && device_.mailbox->foe;
    if (foe != ((g->foe_details & 1) != 0))
        error("sii-general-foe",
              fmt::format("CTT 2-10 General FoE details: the ESI {} FoE, the image byte is 0x{:02X}", foe ? "has" : "has no", g->foe_details),
              mailbox_pos, at + 6);
    const bool eoe = device_.mailbox && device_.mailbox->eoe;
    if (eoe != ((g->eoe_details & 1) != 0))
        error("sii-general-eoe",
              fmt::format("CTT 2-10 General EoE details: the ESI {} EoE, the image byte is 0x{:02X}", eoe ? "has" : "has no", g->eoe_details),
              mailbox_pos, at + 7);
    const bool dll = device_.mailbox && device_.mailbox->data_link_layer.value_or(false);
    if (dll != ((g->flags & general_flag::mailbox_data_link_layer) != 0))
        error("sii-general-flags",
              fmt::format("CTT 2-10 General flags: Mailbox@DataLinkLayer is {}, the image's MBoxDataLinkLayer bit is {}",
                          dll ? "true" : "false", (g->flags & general_flag::mailbox_data_link_layer) ? "set" : "clear"),
              mailbox_pos, at + 11);
    const std::int64_t current = ebus_current(device_).value_or(0);
    if (current != g->current_on_ebus)
        error("sii-ebus-current",
              fmt::format("CTT 2-10 General CurrentOnEBus: the ESI gives {} mA, the image {} mA", current, g->current_on_ebus),
              device_.pos, at + 12);
    for (std::size_t port = 0; port < 4; ++port) {
        const char letter = port < device_.physics.size() ? device_.physics[port] : ' ';
        const auto expected = port_code(letter);
        if (!expected) continue;
        if (*expected != g->port(static_cast<unsigned>(port)))
            error("sii-physical-ports",
                  fmt::format("CTT 1-3 port type: Physics \"{}\" makes port {} '{}' (type {}), the image's General category "
                              "says type {}",
                              device_.physics, port, letter, *expected, g->port(static_cast<unsigned>(port))),
                  device_.pos, at + 16);
    }

    // The strings are compared as text; the language may legitimately differ (Beckhoff writes
    // the German names), so a name of any language matches.
    auto text_of = [&](std::uint8_t index) { return image_.string_at(index); };
    if (const auto name = text_of(g->name_idx)) {
        bool any = false;
        for (const auto& n : device_.names) any = any || to_sii_text(n.text) == *name || n.text == *name;
        if (!any)
            mismatch(Severity::warning, "sii-general-strings",
                     fmt::format("General name string \"{}\" is none of the device's Names", sii_text_to_utf8(*name)), device_.pos,
                     at + 3);
    }
    if (const auto group = text_of(g->group_idx); group && device_.group_type && to_sii_text(*device_.group_type) != *group)
        mismatch(Severity::warning, "sii-general-strings",
                 fmt::format("General group string \"{}\" differs from GroupType \"{}\"", sii_text_to_utf8(*group), *device_.group_type),
                 device_.group_type_pos, at + 0);
    if (const auto order = text_of(g->order_idx); order && to_sii_text(device_.type.text) != *order)
        mismatch(Severity::warning, "sii-general-strings",
                 fmt::format("General order string \"{}\" differs from the Type text \"{}\"", sii_text_to_utf8(*order), device_.type.text),
                 device_.type.pos, at + 2);
}

void Checker::fmmus() {
    const Fmmus* f = image_.fmmus();
    if (!f) {
        if (!device_.fmmus.empty())
            error("sii-fmmu", fmt::format("CTT 2-11 FMMU category: the ESI lists {} Fmmu elements, the image has no FMMU category", device_.fmmus.size()),
                  device_.fmmus.front().pos, header_bytes);
        return;
    }
    std::vector<std::uint8_t> usages = f->usages;
    while (!usages.empty() && (usages.back() == fmmu_usage::unused || usages.back() == fmmu_usage::unused_ff)) usages.pop_back();
    const std::uint64_t at = payload_offset(category::fmmu);
    std::size_t expected_count = device_.fmmus.size();
    while (expected_count > 0 && fmmu_usage_code(device_.fmmus[expected_count - 1].type).value_or(0) == fmmu_usage::unused) --expected_count;
    if (usages.size() != expected_count)
        error("sii-fmmu",
              fmt::format("CTT 2-11 FMMU category: the ESI lists {} FMMUs, the image {}", expected_count, usages.size()),
              device_.fmmus.empty() ? device_.pos : device_.fmmus.front().pos, at);
    for (std::size_t i = 0; i < usages.size() && i < expected_count; ++i) {
        const auto expected = fmmu_usage_code(device_.fmmus[i].type);
        if (expected && *expected != usages[i])
            error("sii-fmmu",
                  fmt::format("CTT 2-11 FMMU {}: the ESI says \"{}\" (usage {}), the image usage {}", i, device_.fmmus[i].type,
                              *expected, usages[i]),
                  device_.fmmus[i].pos, at + i);
    }
}

void Checker::sync_managers() {
    const SyncManagers* s = image_.sync_managers();
    if (!s) {
        if (!device_.sms.empty())
            error("sii-sync-manager",
                  fmt::format("CTT 2-12 SyncM category: the ESI lists {} Sm elements, the image has no SyncM category", device_.sms.size()),
                  device_.sms.front().pos, header_bytes);
        return;
    }
    const std::uint64_t at = payload_offset(category::sync_manager);
    if (s->items.size() != device_.sms.size())
        error("sii-sync-manager",
              fmt::format("CTT 2-12 SyncM category: the ESI lists {} SyncManagers, the image {}", device_.sms.size(), s->items.size()),
              device_.sms.empty() ? device_.pos : device_.sms.front().pos, at);
    for (std::size_t i = 0; i < s->items.size() && i < device_.sms.size(); ++i) {
        const SyncManager& sm = device_.sms[i];
        const SyncManagerRecord& r = s->items[i];
        const std::uint64_t rec = at + i * sync_manager_bytes;
        std::vector<std::string> diffs;
        if (sm.start_address && *sm.start_address != r.start_address)
            diffs.push_back(fmt::format("start 0x{:04X} vs 0x{:04X}", *sm.start_address, r.start_address));
        if (sm.default_size && *sm.default_size != r.length)
            diffs.push_back(fmt::format("length {} vs {}", *sm.default_size, r.length));
        if (sm.control_byte && *sm.control_byte != r.control)
            diffs.push_back(fmt::format("control byte 0x{:02X} vs 0x{:02X}", *sm.control_byte, r.control));
        if (sm_enable_byte(sm) != r.enable) diffs.push_back(fmt::format("enable 0x{:02X} vs 0x{:02X}", sm_enable_byte(sm), r.enable));
        if (const auto type = sm_type_code(sm.type); type && *type != r.type)
            diffs.push_back(fmt::format("type {} ({}) vs {}", *type, sm.type, r.type));
        if (!diffs.empty()) {
            std::string joined;
            for (const auto& d : diffs) joined += (joined.empty() ? "" : ", ") + d;
            error("sii-sync-manager", fmt::format("CTT 2-12 SyncM {} (ESI vs image): {}", i, joined), sm.pos, rec);
        }
    }
}

void Checker::pdos(std::uint16_t type, const std::vector<Pdo>& esi_pdos) {
    const Pdos* p = image_.pdos(type);
    const std::string_view name = category_name(type);
    if (!p) {
        if (!esi_pdos.empty() && !image_.find(type))
            mismatch(Severity::info, "sii-pdo",
                     fmt::format("the image has no {} category (optional: masters then read the PDOs over CoE); {} PDOs not compared",
                                 name, esi_pdos.size()),
                     esi_pdos.front().pos, header_bytes);
        return;
    }
    const std::uint64_t at = payload_offset(type);
    std::vector<std::uint64_t> offsets;
    std::uint64_t walk = at;
    for (const auto& r : p->items) {
        offsets.push_back(walk);
        walk += pdo_header_bytes + r.entries.size() * pdo_entry_bytes;
    }
    std::vector<bool> matched(p->items.size(), false);
    for (const auto& pdo : esi_pdos) {
        std::size_t found = p->items.size();
        for (std::size_t i = 0; i < p->items.size(); ++i)
            if (!matched[i] && p->items[i].index == pdo.index) {
                found = i;
                break;
            }
        if (found == p->items.size()) {
            // A PDO outside the default assignment (no Sm) is what an image leaves out first
            // when the PDOs do not all fit its EEPROM (docs/sii.md §1); the default ones a master
            // without the ESI needs are errors.
            if (!pdo.sm)
                mismatch(Severity::info, "sii-pdo",
                         fmt::format("{} #x{:04X} (no Sm: not assigned by default) is not in the image's {} category",
                                     pdo.element_name(), pdo.index, name),
                         pdo.pos, at);
            else
                error("sii-pdo", fmt::format("{} #x{:04X} is not in the image's {} category", pdo.element_name(), pdo.index, name),
                      pdo.pos, at);
            continue;
        }
        matched[found] = true;
        const PdoRecord& r = p->items[found];
        std::vector<std::string> diffs;
        const std::uint8_t sm = pdo.sm ? static_cast<std::uint8_t>(*pdo.sm & 0xFF) : pdo_no_sync_manager;
        if (sm != r.sync_manager) diffs.push_back(fmt::format("SM {} vs {}", sm, r.sync_manager));
        constexpr std::uint16_t compared = pdo_flag::mandatory | pdo_flag::fixed_content | pdo_flag::virtual_content;
        if ((pdo_flags(pdo) & compared) != (r.flags & compared))
            diffs.push_back(fmt::format("flags 0x{:04X} vs 0x{:04X}", pdo_flags(pdo) & compared, r.flags & compared));
        if (pdo.entries.size() != r.entries.size()) diffs.push_back(fmt::format("{} entries vs {}", pdo.entries.size(), r.entries.size()));
        for (std::size_t i = 0; i < pdo.entries.size() && i < r.entries.size(); ++i) {
            const PdoEntry& e = pdo.entries[i];
            const PdoEntryRecord& x = r.entries[i];
            if (e.index != x.index || e.effective_subindex() != x.subindex)
                diffs.push_back(fmt::format("entry {} is #x{:04X}:{:02X} vs 0x{:04X}:{:02X}", i, e.index, e.effective_subindex(), x.index, x.subindex));
            if (e.bit_len != x.bit_len) diffs.push_back(fmt::format("entry {} BitLen {} vs {}", i, e.bit_len, x.bit_len));
            if (const auto dt = pdo_entry_data_type(device_, e); dt && !same_pdo_data_type(*dt, x.data_type))
                diffs.push_back(fmt::format("entry {} data type 0x{:02X} vs 0x{:02X}", i, *dt, x.data_type));
        }
        if (!diffs.empty()) {
            std::string joined;
            for (const auto& d : diffs) joined += (joined.empty() ? "" : ", ") + d;
            error("sii-pdo", fmt::format("{} #x{:04X} (ESI vs image): {}", pdo.element_name(), pdo.index, joined), pdo.pos, offsets[found]);
        }
    }
    for (std::size_t i = 0; i < p->items.size(); ++i)
        if (!matched[i])
            error("sii-pdo", fmt::format("the image's {} category has PDO 0x{:04X}, which the ESI does not list", name, p->items[i].index),
                  device_.pos, offsets[i]);
}

// What differs between an ESI op mode and a DC record (empty when they agree).
std::vector<std::string> op_mode_differences(const DcOpMode& op, const DcOpModeRecord& r) {
    std::vector<std::string> diffs;
    if ((op.assign_activate & 0xFFFF) != r.assign_activate)
        diffs.push_back(fmt::format("AssignActivate 0x{:04X} vs 0x{:04X}", op.assign_activate, r.assign_activate));
    const auto u32 = [](std::int64_t v) { return static_cast<std::uint32_t>(static_cast<std::uint64_t>(v) & 0xFFFFFFFFu); };
    if (op.cycle_time_sync0 && u32(op.cycle_time_sync0->value) != r.cycle_time0)
        diffs.push_back(fmt::format("CycleTimeSync0 {} vs {}", op.cycle_time_sync0->value, r.cycle_time0));
    if (op.shift_time_sync0 && u32(op.shift_time_sync0->value) != r.shift_time0)
        diffs.push_back(fmt::format("ShiftTimeSync0 {} vs {}", op.shift_time_sync0->value, static_cast<std::int32_t>(r.shift_time0)));
    if (op.shift_time_sync1 && u32(op.shift_time_sync1->value) != r.shift_time1)
        diffs.push_back(fmt::format("ShiftTimeSync1 {} vs {}", op.shift_time_sync1->value, static_cast<std::int32_t>(r.shift_time1)));
    const std::int32_t f0 = op.cycle_time_sync0 ? op.cycle_time_sync0->factor.value_or(0) : 0;
    const std::int32_t f1 = op.cycle_time_sync1 ? op.cycle_time_sync1->factor.value_or(0) : 0;
    if (f0 != r.sync0_cycle_factor) diffs.push_back(fmt::format("CycleTimeSync0@Factor {} vs {}", f0, r.sync0_cycle_factor));
    if (f1 != r.sync1_cycle_factor) diffs.push_back(fmt::format("CycleTimeSync1@Factor {} vs {}", f1, r.sync1_cycle_factor));
    return diffs;
}

void Checker::dc() {
    const DcOpModes* d = image_.dc();
    if (!d) return;  // the DC category is optional
    const std::uint64_t at = payload_offset(category::dc);
    if (!device_.dc) {
        error("sii-dc", fmt::format("the image has a DC category with {} op modes; the ESI has no Dc element", d->items.size()), device_.pos, at);
        return;
    }
    for (std::size_t i = 0; i < d->items.size(); ++i) {
        const DcOpModeRecord& r = d->items[i];
        const auto name = image_.string_at(r.name_idx);
        const std::uint64_t rec = at + i * dc_op_mode_bytes;
        // Op mode names repeat (Beckhoff keeps legacy modes of the same name), so the record is
        // compared with the same-named mode it agrees with best, current modes first.
        const DcOpMode* best = nullptr;
        std::vector<std::string> best_diffs;
        for (const auto& candidate : device_.dc->op_modes) {
            if (name && to_sii_text(candidate.name) != *name && candidate.name != *name) continue;
            std::vector<std::string> diffs = op_mode_differences(candidate, r);
            const bool better = !best || diffs.size() < best_diffs.size() ||
                                (diffs.size() == best_diffs.size() && is_legacy_op_mode(*best) && !is_legacy_op_mode(candidate));
            if (better) {
                best = &candidate;
                best_diffs = std::move(diffs);
            }
        }
        if (!best) {
            error("sii-dc", fmt::format("the image's DC op mode {} \"{}\" is not in the ESI", i, name ? sii_text_to_utf8(*name) : ""),
                  device_.dc->pos, rec);
            continue;
        }
        if (!best_diffs.empty()) {
            std::string joined;
            for (const auto& x : best_diffs) joined += (joined.empty() ? "" : ", ") + x;
            error("sii-dc", fmt::format("Dc/OpMode \"{}\" (ESI vs image): {}", best->name, joined), best->pos, rec);
        }
    }
}

Diagnostics Checker::run() {
    identity();
    mailbox_words();
    eeprom_words();
    general();
    fmmus();
    sync_managers();
    pdos(category::tx_pdo, device_.tx_pdos);
    pdos(category::rx_pdo, device_.rx_pdos);
    dc();
    return std::move(out_);
}

}  // namespace

Diagnostics check_image(const EtherCATInfo& info, const Device& device, const DecodedImage& image, const std::string& esi_path,
                        const std::string& image_path) {
    return Checker(info, device, image, esi_path, image_path).run();
}

ImageDevice find_device_for_image(const EsiDocument& document, const Header& header) {
    ImageDevice best;
    std::size_t total = 0;
    ImageDevice only;
    for (const auto& info : document.infos) {
        for (const auto& device : info.devices) {
            ++total;
            only = {&info, &device, false};
            if (device.type.product_code != header.product_code) continue;
            if (device.type.revision_no == header.revision_no) return {&info, &device, true};
            if (!best.device || device.type.revision_no.value_or(0) > best.device->type.revision_no.value_or(0))
                best = {&info, &device, false};
        }
    }
    if (best.device) return best;
    if (total == 1) return only;
    return {};
}

}  // namespace esi::sii
