// Frame validation and the walk of a frame along a line of ESCs (ETG.1000.4 §5).

#include "esi/esc/frame.hpp"

#include "esi/ethercat/registers.hpp"

namespace esi::esc {

namespace reg = ethercat::reg;

namespace {

constexpr std::size_t datagram_header_bytes = 10;
constexpr std::size_t working_counter_bytes = 2;
constexpr std::uint16_t circulating_bit = 1u << 14;
constexpr std::uint16_t more_bit = 1u << 15;

[[nodiscard]] std::uint16_t load16(const std::uint8_t* p) { return static_cast<std::uint16_t>(p[0] | p[1] << 8); }
void save16(std::uint8_t* p, std::uint16_t v) {
    p[0] = static_cast<std::uint8_t>(v);
    p[1] = static_cast<std::uint8_t>(v >> 8);
}

}  // namespace

bool parse_frame(std::span<const std::uint8_t> payload, std::vector<DatagramSlot>& slots) {
    slots.clear();
    if (payload.size() < 2) return false;
    const std::uint16_t header = load16(payload.data());
    const std::size_t length = header & 0x07FF;
    if ((header >> 12) != 1) return false;  // type 1: EtherCAT commands (DLPDU)
    if (length + 2 > payload.size()) return false;
    const std::size_t end = 2 + length;
    std::size_t at = 2;
    for (;;) {
        if (at + datagram_header_bytes + working_counter_bytes > end) return false;
        const std::uint16_t word = load16(payload.data() + at + 6);
        const std::uint16_t data_length = word & 0x07FF;
        if (at + datagram_header_bytes + data_length + working_counter_bytes > end) return false;
        slots.push_back({at, data_length});
        at += datagram_header_bytes + data_length + working_counter_bytes;
        if (!(word & more_bit)) break;
    }
    return true;
}

FrameOutcome pass_frame(std::span<std::uint8_t> payload, std::span<Esc* const> line, const LineTiming& timing,
                        std::vector<DatagramSlot>& slots) {
    if (!parse_frame(payload, slots)) return FrameOutcome::malformed;
    if (line.empty()) return FrameOutcome::answered;  // nothing on the wire: the frame comes back as sent

    // How far the frame travels decides when it comes back through each port 1.
    std::size_t reached = 0;
    while (reached + 1 < line.size() && ((line[reached]->peek8(reg::dl_port) >> 2) & 0x03) != 0x03) ++reached;
    const std::uint64_t turn = timing.time_ns + 2ull * reached * timing.hop_ns;

    for (std::size_t i = 0; i < line.size(); ++i) {
        Esc& esc = *line[i];
        FramePass pass;
        pass.port0_time_ns = timing.time_ns + static_cast<std::uint64_t>(i) * timing.hop_ns;
        pass.port1_link = i + 1 < line.size();
        pass.port1_time_ns = turn - static_cast<std::uint64_t>(i) * timing.hop_ns;
        esc.begin_pass(pass);
        if (esc.port0_closed()) {
            // ETG.1000.4: an ESC whose port 0 is closed marks a frame as circulating the first
            // time and destroys it the second time, so a frame cannot circle a broken ring.
            std::uint8_t* word = payload.data() + slots.front().header + 6;
            const std::uint16_t value = load16(word);
            if (value & circulating_bit) return FrameOutcome::lost;
            save16(word, static_cast<std::uint16_t>(value | circulating_bit));
        }
        for (const DatagramSlot& slot : slots) {
            std::uint8_t* h = payload.data() + slot.header;
            Datagram d;
            d.command = h[0];
            d.adp = load16(h + 2);
            d.ado = load16(h + 4);
            d.irq = load16(h + 8);
            d.data = payload.subspan(slot.header + datagram_header_bytes, slot.length);
            std::uint8_t* wkc = h + datagram_header_bytes + slot.length;
            d.working_counter = load16(wkc);
            esc.process(d);
            save16(h + 2, d.adp);
            save16(h + 8, d.irq);
            save16(wkc, d.working_counter);
        }
        if (!esc.forwards_to_port1()) {
            // Loop forced open without a next slave: the frame leaves into nothing.
            const unsigned loop = (esc.peek8(reg::dl_port) >> 2) & 0x03;
            if (loop == 0x02 && !pass.port1_link) return FrameOutcome::lost;
            break;
        }
    }
    return FrameOutcome::answered;
}

}  // namespace esi::esc
