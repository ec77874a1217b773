// Logical addressing through the FMMUs (ESC datasheet section I "FMMU", section II 0x0600+):
// each active FMMU maps a bit range of the logical address space onto physical memory —
// process RAM behind a SyncManager, or registers (SOEM maps SM1's status 0x080D). Mapping is bit
// granular; a byte-aligned mapping is copied byte by byte.

#include <algorithm>
#include <vector>

#include "esi/esc/esc.hpp"
#include "esi/ethercat/registers.hpp"

namespace esi::esc {

namespace reg = ethercat::reg;

namespace {

struct Mapping {
    std::uint64_t logical_first_bit = 0;  // inclusive
    std::uint64_t logical_end_bit = 0;    // exclusive
    std::uint32_t physical_first_bit = 0;
    std::uint8_t type = 0;                // bit 0 read, bit 1 write
};

[[nodiscard]] bool get_bit(std::span<const std::uint8_t> bytes, std::uint64_t bit) {
    return (bytes[bit / 8] >> (bit % 8)) & 1;
}

void put_bit(std::span<std::uint8_t> bytes, std::uint64_t bit, bool value) {
    const auto mask = static_cast<std::uint8_t>(1u << (bit % 8));
    if (value)
        bytes[bit / 8] |= mask;
    else
        bytes[bit / 8] &= static_cast<std::uint8_t>(~mask);
}

}  // namespace

// LRD/LWR/LRW (ETG.1000.4): the working counter counts per ESC, not per FMMU: +1 when some
// read FMMU took part, +1 (LWR) or +2 (LRW) when some write FMMU did. Reads see memory as it was
// before this datagram's writes, which take the frame's data as the master sent it.
void Esc::process_logical(Datagram& d) {
    const auto command = static_cast<Command>(d.command);
    const bool reads = command == Command::lrd || command == Command::lrw;
    const bool writes = command == Command::lwr || command == Command::lrw;
    const std::uint64_t dg_first = static_cast<std::uint64_t>(d.logical_address()) * 8;
    const std::uint64_t dg_end = dg_first + static_cast<std::uint64_t>(d.data.size()) * 8;

    std::vector<Mapping> mappings;
    for (unsigned n = 0; n < config_.fmmus; ++n) {
        const std::uint16_t base = static_cast<std::uint16_t>(reg::fmmu0 + reg::fmmu_stride * n);
        if (!(memory_[base + reg::fmmu_activate] & 1)) continue;
        const std::uint16_t length = peek16(static_cast<std::uint16_t>(base + reg::fmmu_length));
        if (length == 0) continue;
        Mapping m;
        const std::uint64_t logical = peek32(static_cast<std::uint16_t>(base + reg::fmmu_logical_start));
        m.logical_first_bit = logical * 8 + (memory_[base + reg::fmmu_logical_start_bit] & 7);
        m.logical_end_bit = (logical + length - 1) * 8 + (memory_[base + reg::fmmu_logical_stop_bit] & 7) + 1;
        if (m.logical_end_bit <= m.logical_first_bit) continue;
        m.physical_first_bit = static_cast<std::uint32_t>(peek16(static_cast<std::uint16_t>(base + reg::fmmu_physical_start))) * 8 +
                               (memory_[base + reg::fmmu_physical_start_bit] & 7);
        m.type = memory_[base + reg::fmmu_type] & 3;
        if (std::max(m.logical_first_bit, dg_first) < std::min(m.logical_end_bit, dg_end)) mappings.push_back(m);
    }
    if (mappings.empty()) return;

    const std::vector<std::uint8_t> sent(d.data.begin(), d.data.end());
    bool read_done = false, write_done = false;
    std::vector<std::uint8_t> physical;
    for (int pass = 0; pass < 2; ++pass) {
        const bool is_write = pass == 1;
        if (is_write ? !writes : !reads) continue;
        for (const Mapping& m : mappings) {
            if (!(m.type & (is_write ? 2 : 1))) continue;
            const std::uint64_t first = std::max(m.logical_first_bit, dg_first);
            const std::uint64_t end = std::min(m.logical_end_bit, dg_end);
            const std::uint64_t phys_first = m.physical_first_bit + (first - m.logical_first_bit);
            const std::uint64_t phys_end = phys_first + (end - first);
            if (phys_end > 0x10000ull * 8) continue;
            const auto byte_first = static_cast<std::uint16_t>(phys_first / 8);
            const std::size_t byte_count = static_cast<std::size_t>((phys_end + 7) / 8 - phys_first / 8);
            physical.assign(byte_count, 0);
            const bool aligned = (first - dg_first) % 8 == 0 && phys_first % 8 == 0 && (end - first) % 8 == 0;
            if (!is_write) {
                if (!access(Side::ecat, false, byte_first, physical)) continue;
                if (aligned) {
                    std::copy(physical.begin(), physical.end(), d.data.begin() + static_cast<std::ptrdiff_t>((first - dg_first) / 8));
                } else {
                    for (std::uint64_t b = 0; b < end - first; ++b)
                        put_bit(d.data, first - dg_first + b, get_bit(physical, phys_first % 8 + b));
                }
                read_done = true;
            } else {
                if (aligned) {
                    std::copy_n(sent.begin() + static_cast<std::ptrdiff_t>((first - dg_first) / 8), byte_count, physical.begin());
                } else {
                    // Bits outside the mapping keep what the buffer holds now.
                    peek(byte_first, physical);
                    for (std::uint64_t b = 0; b < end - first; ++b)
                        put_bit(physical, phys_first % 8 + b, get_bit(sent, first - dg_first + b));
                }
                if (access(Side::ecat, true, byte_first, physical)) write_done = true;
            }
        }
    }
    if (read_done) d.working_counter = static_cast<std::uint16_t>(d.working_counter + 1);
    if (write_done) d.working_counter = static_cast<std::uint16_t>(d.working_counter + (command == Command::lrw ? 2 : 1));
}

}  // namespace esi::esc
