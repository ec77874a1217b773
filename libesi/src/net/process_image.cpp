// The process image and the cyclic frames (docs/esi-net.md, "Process image").
//
// Slaves take max(input, output) bytes each, in bus order, from the logical base address; a
// slave's inputs and outputs share their logical start, as in both tools' exports. Frames hold
// 1,498 bytes of datagrams (a 1,514-byte Ethernet frame less its 14-byte header and the 2-byte
// EtherCAT header, ETG.1000.4); each datagram costs 10 header and 2 working-counter bytes. The
// first frame also carries the DC datagrams (NOP and ARMW on the reference clock's system
// time), the mailbox-state LRD and the BRD of the AL status that counts the slaves. A slave
// never straddles two frames: a new frame starts when the next slave does not fit.
//
// The expected working counter of a process-data LRW is, per slave it reaches, 1 for an input
// FMMU and 2 for an output FMMU (ETG.1000.4 logical read/write); BRD counts every slave.

#include <fmt/format.h>
#include <map>

#include "slave_context.hpp"

namespace esi::net {

namespace {

constexpr std::uint32_t frame_datagram_bytes = 1498;
constexpr std::uint32_t datagram_overhead = 12;

std::string variable_name(const NetworkSlave& s, const ConfiguredPdo& pdo, const ConfiguredEntry& e) {
    std::string name = s.name;
    if (pdo.module) {
        const ModuleInSlot& m = s.modules[*pdo.module];
        name += fmt::format(".Module {} ({})", m.slot + 1, m.module->type);
    }
    return name + "." + pdo.name + "." + (e.name.empty() ? fmt::format("{}:{:02X}", hex_index(e.index), e.subindex) : e.name);
}

}  // namespace

void layout_process_image(Network& n, Diagnostics& diagnostics, const std::string& path) {
    ProcessImage& img = n.image;

    // Mailbox-state bits, one per slave with an MBoxState FMMU, in bus order.
    std::uint32_t mailbox_slaves = 0;
    for (NetworkSlave& s : n.slaves)
        for (FmmuSetup& f : s.fmmus)
            if (f.kind == FmmuKind::mailbox_state) {
                const std::uint32_t bit = mailbox_slaves++;
                if (s.mailbox) s.mailbox->status_bit = bit;
                f.logical_start = img.mailbox_state_base + bit / 8;
                f.logical_start_bit = f.logical_stop_bit = static_cast<std::uint8_t>(bit % 8);
            }
    img.mailbox_state_bytes = (mailbox_slaves + 7) / 8;

    const bool dc = n.reference_clock.has_value();
    std::uint32_t first_overhead = datagram_overhead + 2;  // BRD AL status
    if (mailbox_slaves) first_overhead += datagram_overhead + img.mailbox_state_bytes;
    if (dc) first_overhead += 2 * (datagram_overhead + 4);

    // Slaves to frames.
    std::vector<std::vector<std::size_t>> frames(1);
    std::uint32_t offset = 0, in_frame = 0;
    auto capacity = [&](std::size_t frame) {
        return frame_datagram_bytes - datagram_overhead - (frame == 0 ? first_overhead : 0);
    };
    for (std::size_t i = 0; i < n.slaves.size(); ++i) {
        NetworkSlave& s = n.slaves[i];
        const std::uint32_t bytes = s.image_bytes();
        if (bytes > frame_datagram_bytes - datagram_overhead) {
            diagnostics.emplace(Severity::error, "net-frame-size",
                                fmt::format("slave '{}' has {} bytes of process data; one frame holds at most {}", s.name, bytes,
                                            frame_datagram_bytes - datagram_overhead),
                                path, {});
            continue;
        }
        if (bytes > 0 && in_frame + bytes > capacity(frames.size() - 1)) {
            frames.emplace_back();
            in_frame = 0;
        }
        s.frame = frames.size() - 1;
        s.image_offset = offset;
        frames.back().push_back(i);
        offset += bytes;
        in_frame += bytes;
    }
    img.process_data_bytes = offset;

    // FMMU logical addresses and variables.
    for (NetworkSlave& s : n.slaves) {
        std::uint32_t out_at = 0, in_at = 0;
        std::map<std::uint32_t, std::uint32_t> sm_offset;  // SM -> byte offset in the slave's image
        for (const SmSetup& sm : s.sms) {
            if (!sm.is_process_data()) continue;
            std::uint32_t& at = sm.kind == SmKind::outputs ? out_at : in_at;
            sm_offset[sm.number] = at;
            at += sm.length;
        }
        for (FmmuSetup& f : s.fmmus)
            if (f.kind != FmmuKind::mailbox_state && f.enable) f.logical_start = img.logical_base + s.image_offset + sm_offset[f.sm];
        std::map<std::string, int> seen;
        for (const SmSetup& sm : s.sms) {
            if (!sm.is_process_data()) continue;
            std::uint64_t bit = 8ull * (s.image_offset + sm_offset[sm.number]);
            for (std::size_t p : sm.pdos) {
                const ConfiguredPdo& pdo = s.pdos[p];
                for (const ConfiguredEntry& e : pdo.entries) {
                    if (!e.is_padding()) {
                        Variable v;
                        v.slave = s.position;
                        v.name = variable_name(s, pdo, e);
                        if (const int repeat = seen[v.name]++; repeat > 0) v.name += fmt::format(" ({}:{:02X})", hex_index(e.index), e.subindex);
                        v.pdo_name = pdo.name;
                        v.pdo_index = pdo.index;
                        v.index = e.index;
                        v.subindex = e.subindex;
                        v.data_type = e.data_type;
                        v.bit_size = e.bit_len;
                        v.bit_offset = bit;
                        v.direction = pdo.direction;
                        v.comment = e.comment;
                        (pdo.direction == PdoDirection::rx ? img.outputs : img.inputs).push_back(std::move(v));
                    }
                    bit += e.bit_len;
                }
            }
        }
    }

    // Datagrams. The image holds the process data first, then the other datagrams' data.
    std::uint32_t image_at = img.process_data_bytes;
    img.frames.clear();
    for (std::size_t f = 0; f < frames.size(); ++f) {
        Frame frame;
        if (f == 0 && dc) {
            Datagram nop;
            nop.command = Datagram::Command::nop;
            nop.ado = 0x0900;
            nop.length = 4;
            nop.preop = true;
            nop.comment = "DC receive times (placeholder for the propagation delay measurement)";
            Datagram armw;
            armw.command = Datagram::Command::armw;
            armw.adp = n.slaves[*n.reference_clock].auto_inc_addr;
            armw.ado = 0x0910;
            armw.length = 4;
            armw.preop = true;
            armw.comment = "DC system time of the reference clock";
            for (Datagram* d : {&nop, &armw}) {
                d->image_offset = image_at;
                image_at += d->length;
                frame.datagrams.push_back(*d);
            }
        }
        if (f == 0 && mailbox_slaves) {
            Datagram lrd;
            lrd.command = Datagram::Command::lrd;
            lrd.logical = img.mailbox_state_base;
            lrd.length = static_cast<std::uint16_t>(img.mailbox_state_bytes);
            lrd.preop = true;
            lrd.image_offset = image_at;
            lrd.comment = "mailbox state";
            image_at += lrd.length;
            frame.datagrams.push_back(lrd);
        }
        std::uint32_t bytes = 0, wkc = 0;
        for (std::size_t i : frames[f]) {
            const NetworkSlave& s = n.slaves[i];
            bytes += s.image_bytes();
            wkc += (s.output_bytes ? 2 : 0) + (s.input_bytes ? 1 : 0);
        }
        if (bytes > 0) {
            Datagram lrw;
            lrw.command = Datagram::Command::lrw;
            lrw.image_offset = n.slaves[frames[f].front()].image_offset;
            lrw.logical = img.logical_base + lrw.image_offset;
            lrw.length = static_cast<std::uint16_t>(bytes);
            lrw.working_counter = static_cast<std::uint16_t>(wkc);
            lrw.comment = "process data";
            frame.datagrams.push_back(lrw);
        }
        if (f == 0) {
            Datagram brd;
            brd.command = Datagram::Command::brd;
            brd.ado = 0x0130;
            brd.length = 2;
            brd.working_counter = static_cast<std::uint16_t>(n.slaves.size());
            brd.preop = true;
            brd.image_offset = image_at;
            brd.comment = "AL status (counts the slaves)";
            image_at += brd.length;
            frame.datagrams.push_back(brd);
        }
        img.frames.push_back(std::move(frame));
    }
    img.byte_size = image_at;
}

}  // namespace esi::net
