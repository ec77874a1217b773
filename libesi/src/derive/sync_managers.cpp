// SyncManagers, the default PDO assignment and FMMUs.
//
// The canonical layout (SOES tutorial; SOEM #247):
//   SM0 MBoxOut  #x1000, ControlByte #x26 (mailbox, write, ECAT+PDI IRQ)
//   SM1 MBoxIn   after SM0, ControlByte #x22 (mailbox, read)
//   SM2 Outputs  after the mailboxes, ControlByte #x64 (buffered, write, watchdog trigger)
//   SM3 Inputs   after SM2's three buffers, ControlByte #x20 (buffered, read)
// The mailbox sizes come from `mailbox:`; a process-data SM's size is the sum of the PDOs
// assigned to it by default (the servo manuals' errors 62-3/62-4 and STÖBER's "PDO Länge ist
// nicht korrekt" are what a wrong size costs). An SM without data is disabled, since devices
// reject an enabled SM of length 0 (ethercrab #354), except on a modular device, whose process
// data comes from the modules in its slots.

#include <algorithm>
#include <numeric>

#include "derive/steps.hpp"

namespace esi::derive {

namespace {

constexpr std::uint32_t default_mailbox_size = 128;
constexpr std::uint32_t default_mailbox_address = 0x1000;

std::uint32_t align_up(std::uint32_t value, std::uint32_t alignment) { return (value + alignment - 1) / alignment * alignment; }

bool is_mailbox(const SyncManager& sm) { return sm.type == "MBoxOut" || sm.type == "MBoxIn"; }

SyncManager make_sm(std::string type, SourcePos pos) {
    SyncManager sm;
    sm.type = std::move(type);
    sm.pos = pos;
    return sm;
}

std::uint64_t assigned_bits(const std::vector<Pdo>& pdos, std::uint32_t sm) {
    std::uint64_t bits = 0;
    for (const Pdo& p : pdos)
        if (p.sm && *p.sm == sm) bits += p.bit_size();
    return bits;
}

std::string assigned_list(const std::vector<Pdo>& pdos, std::uint32_t sm) {
    std::string out;
    for (const Pdo& p : pdos) {
        if (!p.sm || *p.sm != sm) continue;
        if (!out.empty()) out += ", ";
        out += hex4(p.index) + " (" + std::to_string(p.bit_size()) + " bits)";
    }
    return out;
}

}  // namespace

SmPlan plan_sms(const Device& device, const DeviceIntent& intent) {
    SmPlan plan;
    if (!device.sms.empty()) {
        for (std::uint32_t n = 0; n < device.sms.size(); ++n) {
            if (!plan.outputs && device.sms[n].type == "Outputs") plan.outputs = n;
            if (!plan.inputs && device.sms[n].type == "Inputs") plan.inputs = n;
        }
        return plan;
    }
    if (!intent.options.sync_managers) return plan;
    if (device.mailbox) {
        plan.outputs = 2;
        plan.inputs = 3;
        return plan;
    }
    std::uint32_t next = 0;
    if (!device.rx_pdos.empty()) plan.outputs = next++;
    if (!device.tx_pdos.empty()) plan.inputs = next++;
    return plan;
}

void derive_pdo_assignment(Device& device, const DeviceIntent& intent, const SmPlan& plan, Context& context) {
    auto assign = [&](std::vector<Pdo>& pdos, const std::vector<bool>& wanted, const std::optional<std::uint32_t>& sm,
                      std::string_view sm_type) {
        for (std::size_t i = 0; i < pdos.size(); ++i) {
            Pdo& p = pdos[i];
            if (p.sm || (i < wanted.size() && !wanted[i])) continue;
            if (!sm) {
                context.error(p.pos, "derive-pdo-assignment",
                              "PDO " + hex4(p.index) + " is assigned by default, but the device has no " + std::string(sm_type) +
                                  " SM; add one to 'sms' or set 'assigned: false'");
                continue;
            }
            p.sm = *sm;
        }
    };
    assign(device.rx_pdos, intent.rx_assign, plan.outputs, "Outputs");
    assign(device.tx_pdos, intent.tx_assign, plan.inputs, "Inputs");
}

void derive_sync_managers(Device& device, const DeviceIntent& intent, Context& context) {
    const MailboxLayout& mbx = intent.mailbox;
    std::vector<SourcePos> size_pos = intent.sm_size_pos;
    if (device.sms.empty()) {
        const SourcePos mailbox_pos = device.mailbox ? device.mailbox->pos : device.pos;
        if (device.mailbox) {
            device.sms.push_back(make_sm("MBoxOut", mailbox_pos));
            device.sms.push_back(make_sm("MBoxIn", mailbox_pos));
            device.sms.push_back(make_sm("Outputs", device.pos));
            device.sms.push_back(make_sm("Inputs", device.pos));
        } else {
            if (!device.rx_pdos.empty()) device.sms.push_back(make_sm("Outputs", device.pos));
            if (!device.tx_pdos.empty()) device.sms.push_back(make_sm("Inputs", device.pos));
        }
    }
    size_pos.resize(device.sms.size());

    // Mailbox SMs first: the process-data SMs are placed after them.
    std::uint32_t mailbox_end = default_mailbox_address;
    std::optional<std::uint32_t> out_end;
    for (std::size_t n = 0; n < device.sms.size(); ++n) {
        SyncManager& sm = device.sms[n];
        if (!is_mailbox(sm)) continue;
        const bool out = sm.type == "MBoxOut";
        const std::optional<std::uint32_t>& stated_size = out ? mbx.out_size : mbx.in_size;
        const std::optional<std::uint32_t>& stated_address = out ? mbx.out_address : mbx.in_address;
        if (sm.default_size && stated_size && *sm.default_size != *stated_size) {
            Diagnostic& d = context.error(size_pos[n].known() ? size_pos[n] : sm.pos, "derive-sm-size",
                                          "SM" + std::to_string(n) + " (" + sm.type + ") has size " + std::to_string(*sm.default_size) +
                                              ", but the mailbox settings say " + std::to_string(*stated_size));
            d.notes.push_back({context.path(), mbx.pos, "mailbox size given here"});
        }
        if (!sm.default_size) sm.default_size = stated_size.value_or(default_mailbox_size);
        if (!sm.start_address) {
            if (stated_address) sm.start_address = *stated_address;
            else if (!out && out_end) sm.start_address = *out_end;
            else sm.start_address = out ? default_mailbox_address : mailbox_end;
        }
        if (!sm.control_byte) sm.control_byte = out ? 0x26u : 0x22u;
        if (!sm.enable) sm.enable = 1;
        const std::uint32_t end = *sm.start_address + *sm.default_size;
        if (out) out_end = end;
        mailbox_end = std::max(mailbox_end, end);
    }

    std::uint32_t cursor = align_up(mailbox_end, 0x80);
    for (std::size_t n = 0; n < device.sms.size(); ++n) {
        SyncManager& sm = device.sms[n];
        const bool outputs = sm.type == "Outputs";
        if (!outputs && sm.type != "Inputs") continue;
        const auto number = static_cast<std::uint32_t>(n);
        const std::vector<Pdo>& pdos = outputs ? device.rx_pdos : device.tx_pdos;
        const std::uint64_t bytes = (assigned_bits(pdos, number) + 7) / 8;
        if (sm.default_size && *sm.default_size < bytes) {
            context.error(size_pos[n].known() ? size_pos[n] : sm.pos, "derive-sm-size",
                          "SM" + std::to_string(n) + " (" + sm.type + ") has size " + std::to_string(*sm.default_size) +
                              " bytes, smaller than the " + std::to_string(bytes) + " bytes of its default PDOs: " +
                              assigned_list(pdos, number));
        }
        if (!sm.default_size && bytes > 0) sm.default_size = static_cast<std::uint32_t>(std::min<std::uint64_t>(bytes, 0xFFFF));
        if (!sm.start_address) sm.start_address = cursor;
        if (!sm.control_byte) sm.control_byte = outputs ? 0x64u : 0x20u;
        // A modular device's process data comes from the modules plugged into its slots; the
        // master sizes the SM, so it stays enabled without a default size.
        if (!sm.enable) sm.enable = sm.default_size.value_or(0) > 0 || device.slots ? 1u : 0u;
        // Buffered SMs occupy three buffers of their size in ESC memory (ESC datasheet, SyncManager).
        const std::uint32_t footprint = std::max<std::uint32_t>(3u * sm.default_size.value_or(0), 1u);
        cursor = std::max(cursor, align_up(*sm.start_address + footprint, 0x80));
    }

    for (std::size_t n = 0; n < device.sms.size(); ++n) {
        const SyncManager& sm = device.sms[n];
        if (!sm.start_address) continue;
        const bool buffered = sm.control_byte && (*sm.control_byte & 0x03u) == 0;
        const std::uint64_t end = std::uint64_t{*sm.start_address} + (buffered ? 3u : 1u) * sm.default_size.value_or(0);
        if (end > 0x10000)
            context.error(size_pos[n].known() ? size_pos[n] : sm.pos, "derive-sm-address",
                          "SM" + std::to_string(n) + " ends at " + hex4(static_cast<std::uint32_t>(end)) +
                              ", beyond the 64 KiB ESC address space");
    }
}

void derive_fmmus(Device& device) {
    std::optional<std::uint32_t> mailbox_in;
    for (std::uint32_t n = 0; n < device.sms.size(); ++n) {
        const SyncManager& sm = device.sms[n];
        if (sm.type == "MBoxIn" && !mailbox_in) mailbox_in = n;
    }
    for (const char* type : {"Outputs", "Inputs"}) {
        for (std::uint32_t n = 0; n < device.sms.size(); ++n) {
            const SyncManager& sm = device.sms[n];
            if (sm.type != type || sm.enable.value_or(1) == 0 || (sm.default_size.value_or(0) == 0 && !device.slots)) continue;
            Fmmu f;
            f.type = type;
            f.sm = n;
            f.pos = sm.pos;
            device.fmmus.push_back(std::move(f));
            break;
        }
    }
    if (mailbox_in && device.mailbox) {
        Fmmu f;
        f.type = "MBoxState";
        f.sm = *mailbox_in;
        f.pos = device.sms[*mailbox_in].pos;
        device.fmmus.push_back(std::move(f));
    }
}

}  // namespace esi::derive
