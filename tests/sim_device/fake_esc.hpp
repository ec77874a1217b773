#pragma once
// A minimal stand-in for the emulated ESC, enough to drive a slave stack from a test: the
// 64 KiB address space, the AL control event, and 1-buffer mailbox SyncManagers (full/empty on
// the last byte, the SM's status bit 3). Process-data SMs are plain memory. The master side
// is what a test calls directly (no frames).

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "esi/esc/pdi.hpp"

namespace esi::sim::test_bench {

class FakeEsc final : public esc::Pdi {
public:
    FakeEsc() : memory_(0x10000, 0) {}

    // --- PDI side (the slave stack) ---
    void read(std::uint16_t address, std::span<std::uint8_t> out) override {
        ++pdi_reads;
        for (std::size_t i = 0; i < out.size(); ++i) {
            const std::size_t a = address + i;
            if (a > 0xFFFF) {
                out[i] = 0;
                continue;
            }
            out[i] = a >= 0x0220 && a < 0x0224 ? static_cast<std::uint8_t>(event_ >> (8 * (a - 0x0220))) : memory_[a];
            if (a == 0x0120) event_ &= ~1u;
            if (a == 0x0440) event_ &= ~0x40u;  // reading the watchdog status acknowledges its expiry
            on_pdi_access(a, false);
        }
    }
    void write(std::uint16_t address, std::span<const std::uint8_t> in) override {
        for (std::size_t i = 0; i < in.size(); ++i) {
            const std::size_t a = address + i;
            if (a > 0xFFFF) break;
            // The PDI cannot write what only the EtherCAT side writes (SM configuration, AL
            // control); it may write AL status, status code and SM PDI control.
            if (a >= 0x0800 && a < 0x0880 && (a & 7) != 7) continue;
            if (a == 0x0120 || a == 0x0121) continue;
            memory_[a] = in[i];
            on_pdi_access(a, true);
        }
    }
    [[nodiscard]] std::uint32_t al_event() const override { return event_; }

    // The process-data watchdog as the ESC runs it: expired (0x0440 bit 0 clear, AL event bit 6)
    // or rewound by the master's outputs (bit 0 set).
    void expire_watchdog() {
        memory_[0x0440] &= 0xFE;
        event_ |= 0x40u;
    }
    void rewind_watchdog() { memory_[0x0440] |= 0x01; }

    // --- EtherCAT side (the test as master) ---
    void master_write(std::uint16_t address, std::span<const std::uint8_t> in) {
        for (std::size_t i = 0; i < in.size() && address + i <= 0xFFFF; ++i) {
            const std::size_t a = address + i;
            memory_[a] = in[i];
            if (a == 0x0120 || a == 0x0121) event_ |= 1u;
            // Writing the last byte of a write mailbox makes it full.
            for (unsigned n = 0; n < 16; ++n)
                if (is_mailbox(n, true) && a == sm_start(n) + sm_length(n) - 1u) memory_[sm_reg(n) + 5] |= 0x08;
        }
    }
    void master_write_u16(std::uint16_t address, std::uint16_t value) {
        const std::array<std::uint8_t, 2> b{static_cast<std::uint8_t>(value), static_cast<std::uint8_t>(value >> 8)};
        master_write(address, b);
    }
    // Reads as the master; reading the last byte of a full read mailbox empties it.
    std::vector<std::uint8_t> master_read(std::uint16_t address, std::size_t length) {
        std::vector<std::uint8_t> out;
        for (std::size_t i = 0; i < length && address + i <= 0xFFFF; ++i) {
            const std::size_t a = address + i;
            out.push_back(memory_[a]);
            for (unsigned n = 0; n < 16; ++n)
                if (is_mailbox(n, false) && a == sm_start(n) + sm_length(n) - 1u) memory_[sm_reg(n) + 5] &= 0xF7;
        }
        return out;
    }
    [[nodiscard]] std::uint16_t u16(std::uint16_t address) const {
        return static_cast<std::uint16_t>(memory_[address] | (memory_[address + 1u] << 8));
    }
    // SM n: start, length, control, activate (enable bit 0), as a master configures it.
    void configure_sm(unsigned n, std::uint16_t start, std::uint16_t length, std::uint8_t control, bool enable) {
        const std::array<std::uint8_t, 8> r{static_cast<std::uint8_t>(start), static_cast<std::uint8_t>(start >> 8),
                                            static_cast<std::uint8_t>(length), static_cast<std::uint8_t>(length >> 8),
                                            control, 0, static_cast<std::uint8_t>(enable ? 1 : 0), 0};
        master_write(sm_reg(n), r);
    }
    [[nodiscard]] bool mailbox_full(unsigned n) const { return (memory_[sm_reg(n) + 5] & 0x08) != 0; }
    std::size_t pdi_reads = 0;

private:
    static std::size_t sm_reg(unsigned n) { return 0x0800 + 8 * n; }
    [[nodiscard]] std::size_t sm_start(unsigned n) const { return u16(static_cast<std::uint16_t>(sm_reg(n))); }
    [[nodiscard]] std::size_t sm_length(unsigned n) const { return u16(static_cast<std::uint16_t>(sm_reg(n) + 2)); }
    // Mailbox mode (control bits 0–1 = 2); direction bits 2–3: 1 = ECAT writes, 0 = ECAT reads.
    [[nodiscard]] bool is_mailbox(unsigned n, bool master_writes) const {
        const std::uint8_t control = memory_[sm_reg(n) + 4];
        return (memory_[sm_reg(n) + 6] & 1) && (control & 0x03) == 0x02 && (((control >> 2) & 0x03) == 1) == master_writes &&
               sm_length(n) > 0;
    }
    void on_pdi_access(std::size_t a, bool write) {
        for (unsigned n = 0; n < 16; ++n) {
            if (a != sm_start(n) + sm_length(n) - 1u) continue;
            if (write && is_mailbox(n, false)) memory_[sm_reg(n) + 5] |= 0x08;    // read mailbox now full
            if (!write && is_mailbox(n, true)) memory_[sm_reg(n) + 5] &= 0xF7;   // write mailbox now empty
        }
    }

    std::vector<std::uint8_t> memory_;
    std::uint32_t event_ = 0;
};

}  // namespace esi::sim::test_bench
