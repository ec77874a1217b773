// A slave whose ESI values cannot be written exactly into every output is refused, never
// configured with a guess (docs/esi-net.md, "Values the outputs cannot hold"):
//  - the reader's errors inside the device (a ProductCode "#x1002G" read as nothing, a BitLen
//    "-1" read as 0): the values esi-lint calls errors, with the reader's own messages as notes;
//  - values the outputs hold in fewer bits than the model: a PDO mapping entry has an 8-bit bit
//    length (CiA 301 mapping value; IgH `ec_pdo_entry_info_t::bit_length` is uint8_t), a PDO
//    or mapping object holds at most 255 entries and an SM at most 255 PDOs (8-bit counts),
//    object indices are 16 bits and sub-indices 8, SM registers 16 bits (start, length) and
//    an 8-bit control byte.

#include "esi/plural.hpp"
#include <fmt/format.h>

#include <algorithm>

#include "slave_context.hpp"

namespace esi::net {

namespace {

// The span of the document each device owns: from its element to the next device's (the last
// one to its catalogue's first module). A reader error outside every other device's span (in
// the vendor, the groups, the modules) may concern this device too, so it counts.
bool in_other_device(const std::vector<const Device*>& devices, const EtherCATInfo& info, const Device& device, SourcePos pos) {
    for (std::size_t i = 0; i < devices.size(); ++i) {
        const Device* d = devices[i];
        if (d == &device || !d->pos.known()) continue;
        SourcePos end{~0u, ~0u};
        for (const Device* other : devices)
            if (other->pos > d->pos && other->pos < end) end = other->pos;
        for (const Module& m : info.modules)
            if (m.pos.known() && m.pos > d->pos && m.pos < end) end = m.pos;
        if (pos >= d->pos && pos < end) return true;
    }
    return false;
}

}  // namespace

void check_reader_errors(SlaveContext& c, const std::vector<const Device*>& devices, const Diagnostics& reader) {
    std::vector<const Diagnostic*> errors;
    for (const Diagnostic& d : reader)
        if (d.severity == Severity::error && d.pos.known() && !in_other_device(devices, c.info, c.device, d.pos)) errors.push_back(&d);
    if (!c.info.vendor || !c.info.vendor->id) {
        c.error(c.spec.device_pos, "net-esi-value",
                fmt::format("{} has no vendor id in its ESI; a master checks it against the device", c.device.type.text));
    }
    if (errors.empty()) return;
    Diagnostic& d = c.error(c.spec.device_pos, "net-esi-value",
                            fmt::format("{}: {} value{} of the ESI cannot be read (esi-lint reports {}); the configuration would hold a "
                                        "guessed value, so this device is not configured",
                                        c.device.type.text, errors.size(), errors.size() == 1 ? "" : "s",
                                        errors.size() == 1 ? "it" : "them"));
    for (const Diagnostic* e : errors) {
        if (d.notes.size() == 8) break;
        d.notes.push_back({e->path, e->pos, e->message + " [" + e->rule + "]"});
    }
}

void check_representable(SlaveContext& c) {
    const NetworkSlave& s = c.slave;
    auto refuse = [&](SourcePos esi_pos, std::string message) {
        Diagnostic& d = c.error(c.spec.device_pos, "net-esi-value", std::move(message));
        if (esi_pos.known()) d.notes.push_back({s.esi_path, esi_pos, "the ESI's value"});
    };
    std::vector<std::uint32_t> pdos_per_sm(c.device.sms.size(), 0);
    for (const ConfiguredPdo& p : s.pdos) {
        if (p.index > 0xFFFF) refuse({}, fmt::format("PDO index {:#x} does not fit in 16 bits", p.index));
        if (p.entries.size() > 255)
            refuse({}, fmt::format("PDO {} has {}; a PDO mapping holds at most 255", hex_index(p.index), esi::counted(p.entries.size(), "entry", "entries")));
        if (p.sm < pdos_per_sm.size() && ++pdos_per_sm[p.sm] == 256)
            refuse({}, fmt::format("SM{} is assigned more than 255 PDOs; an assignment object holds at most 255", p.sm));
        for (const ConfiguredEntry& e : p.entries) {
            if (e.index > 0xFFFF || e.subindex > 0xFF)
                refuse({}, fmt::format("PDO {}: entry {:#x}:{:#x} is not a 16-bit index and 8-bit sub-index", hex_index(p.index), e.index,
                                       e.subindex));
            if (e.bit_len == 0 || e.bit_len > 255)
                refuse({}, fmt::format("PDO {}: entry {}:{:02X} is {} long; a PDO mapping entry has 1 to 255 bits",
                                       hex_index(p.index), hex_index(e.index), e.subindex, esi::counted(e.bit_len, "bit")));
        }
    }
    for (std::size_t i = 0; i < c.device.sms.size(); ++i) {
        const SyncManager& sm = c.device.sms[i];
        auto check16 = [&](const std::optional<std::uint32_t>& v, const char* what) {
            if (v && *v > 0xFFFF) refuse(sm.pos, fmt::format("SM{}: {} {:#x} does not fit the 16-bit SM register", i, what, *v));
        };
        check16(sm.start_address, "StartAddress");
        check16(sm.default_size, "DefaultSize");
        if (sm.control_byte && *sm.control_byte > 0xFF)
            refuse(sm.pos, fmt::format("SM{}: ControlByte {:#x} does not fit the 8-bit SM control register", i, *sm.control_byte));
    }
    if (c.device.sms.size() > 255) refuse({}, fmt::format("{} SyncManagers; an ESC has at most 255", c.device.sms.size()));
}

}  // namespace esi::net
