#pragma once
// An emulated EtherCAT Slave Controller (ESC datasheet section II; ETG.1000.4): the 64 KiB
// address space (registers below 0x1000, process RAM above), the datagram commands as one ESC
// executes them while a frame passes, SyncManagers (mailbox and 3-buffer), bit-granular FMMUs,
// the SII EEPROM interface and the DC registers a master sets up. The slave stack reaches it
// through esc::Pdi (pdi.hpp); a master reaches it through datagrams (frame.hpp walks a frame
// through a line of Escs).
//
// Idealised (docs/esi-sim.md): every access completes at once (the EEPROM is never busy); all
// ESCs share one clock (the local time is the time the frame reaches the ESC, given by the
// caller), so DC needs no drift compensation and SYNC pulses are one SYNC0 event per frame
// while SYNC0 is active; the physical read/write offset (0x0108) is not applied.

#include <cstdint>
#include <span>
#include <vector>

#include "esi/esc/pdi.hpp"

namespace esi::esc {

// What the ESC reports about itself in 0x0000..0x0009. The defaults describe an ET1100-class
// controller: 8 FMMUs, 8 SyncManagers, 8 KiB process RAM, ports 0 and 1 as MII, bit-granular
// FMMUs, 64-bit DC.
struct EscConfig {
    std::uint8_t type = 0x11;
    std::uint8_t revision = 0x00;
    std::uint16_t build = 0x0000;
    std::uint8_t fmmus = 8;           // at most 16
    std::uint8_t sync_managers = 8;   // at most 16
    std::uint8_t ram_kib = 8;         // at most 60 (0x1000..0xFFFF)
    std::uint8_t port_descriptor = 0x0F;
    std::uint16_t features = 0x000C;  // bit 2 DC, bit 3 64-bit DC
};

// Datagram command codes (ETG.1000.4 table "EtherCAT command types").
enum class Command : std::uint8_t {
    nop = 0, aprd = 1, apwr = 2, aprw = 3, fprd = 4, fpwr = 5, fprw = 6, brd = 7, bwr = 8, brw = 9,
    lrd = 10, lwr = 11, lrw = 12, armw = 13, frmw = 14,
};

// One datagram as an ESC sees it: the header fields it may change and its data in the frame.
struct Datagram {
    std::uint8_t command = 0;
    std::uint16_t adp = 0;  // position / station address; low half of a logical address
    std::uint16_t ado = 0;  // register / RAM offset; high half of a logical address
    std::span<std::uint8_t> data;
    std::uint16_t working_counter = 0;
    std::uint16_t irq = 0;
    [[nodiscard]] std::uint32_t logical_address() const { return adp | (static_cast<std::uint32_t>(ado) << 16); }
};

// When the frame passes this ESC and where it goes next: the caller (a line) knows the topology.
struct FramePass {
    std::uint64_t port0_time_ns = 0;  // the frame arrives at port 0 (the ESC's local time)
    std::uint64_t port1_time_ns = 0;  // it comes back through port 1 (when port 1 has a link)
    bool port1_link = false;          // a next slave is connected to port 1
};

class Esc final : public Pdi {
public:
    // `eeprom` is the SII image (an image shorter than the EEPROM reads as erased, 0xFF, past
    // its end). The ESC powers on: it loads its configuration from the image (load_eeprom()).
    explicit Esc(std::vector<std::uint8_t> eeprom, const EscConfig& config = {});

    // Power-on/reload: words 0..4 of the image into 0x0140/0x0141, 0x0150, 0x0982, 0x0152 and
    // 0x0012 when the checksum (word 7) is right; otherwise the registers stay 0, "PDI
    // operational" (0x0110 bit 0) stays clear and 0x0502 reports the checksum error.
    void load_eeprom();
    [[nodiscard]] bool eeprom_loaded() const { return eeprom_loaded_; }
    // A PDI is configured (0x0140 != 0) and the EEPROM loaded: the slave stack can run.
    [[nodiscard]] bool pdi_active() const;

    // The ECAT side. begin_pass() once per frame, before its datagrams; process() each one.
    void begin_pass(const FramePass& pass);
    void process(Datagram& datagram);
    // Whether a frame leaves through port 1 to the next slave (link and DL control loop bits).
    [[nodiscard]] bool forwards_to_port1() const;
    // Port 0 is closed by DL control: a frame processed here is circulating (ETG.1000.4).
    [[nodiscard]] bool port0_closed() const;

    // esc::Pdi: the slave stack's side.
    void read(std::uint16_t address, std::span<std::uint8_t> out) override;
    void write(std::uint16_t address, std::span<const std::uint8_t> in) override;
    [[nodiscard]] std::uint32_t al_event() const override;

    // Inspection without side effects (tests, tools).
    void peek(std::uint16_t address, std::span<std::uint8_t> out) const;
    [[nodiscard]] std::uint8_t peek8(std::uint16_t address) const { return memory_[address]; }
    [[nodiscard]] std::uint16_t peek16(std::uint16_t address) const;
    [[nodiscard]] std::uint32_t peek32(std::uint16_t address) const;
    [[nodiscard]] const std::vector<std::uint8_t>& eeprom() const { return eeprom_; }
    [[nodiscard]] const EscConfig& config() const { return config_; }

private:
    enum class Side : std::uint8_t { ecat, pdi };
    struct SmState {
        bool full = false;        // mailbox: the buffer holds a complete message
        std::int8_t newest = -1;  // 3-buffer: the last completely written buffer
        std::int8_t reading = -1; // 3-buffer: the buffer the reader has open
        std::int8_t writing = -1; // 3-buffer: the buffer the writer has open
        std::uint8_t activate = 0;  // the activate register as last seen
    };

    // esc.cpp: registers
    bool access(Side side, bool is_write, std::uint16_t address, std::span<std::uint8_t> buffer);
    void plain_access(Side side, bool is_write, std::uint32_t address, std::span<std::uint8_t> buffer);
    void register_read(Side side, std::uint32_t address, std::span<std::uint8_t> out);
    void register_write(Side side, std::uint32_t address, std::span<const std::uint8_t> in);
    [[nodiscard]] std::uint8_t write_mask(Side side, std::uint32_t address) const;
    void after_ecat_write(std::uint32_t first, std::uint32_t end);
    void after_pdi_write(std::uint32_t first, std::uint32_t end);
    void refresh_dl_status();
    void refresh_system_time();
    void set_al_event(std::uint32_t bits);
    void clear_al_event(std::uint32_t bits);
    void set_ecat_event(std::uint16_t bits);
    void clear_ecat_event(std::uint16_t bits);
    void store16(std::uint32_t address, std::uint16_t value);
    void store32(std::uint32_t address, std::uint32_t value);
    void store64(std::uint32_t address, std::uint64_t value);
    [[nodiscard]] std::uint64_t peek64(std::uint32_t address) const;

    // esc_sync_manager.cpp
    [[nodiscard]] bool sm_enabled(unsigned n) const;
    [[nodiscard]] std::uint16_t sm_start(unsigned n) const;
    [[nodiscard]] std::uint16_t sm_length(unsigned n) const;
    [[nodiscard]] bool sm_accepts(Side side, bool is_write, unsigned n) const;
    void sm_transfer(Side side, bool is_write, unsigned n, std::uint32_t address, std::span<std::uint8_t> buffer);
    void sm_reset(unsigned n);
    void sm_refresh_status(unsigned n);
    void sm_activate_written(unsigned n);

    // esc_fmmu.cpp
    void process_logical(Datagram& datagram);

    // esc_eeprom.cpp
    void eeprom_command();

    // esc_watchdog.cpp
    void watchdog_triggered_by(std::uint32_t sm_hits);
    void watchdog_check();
    void watchdog_status_read_by_pdi();

    // esc_datagram.cpp
    [[nodiscard]] bool station_matches(std::uint16_t adp) const;
    void physical(Datagram& datagram, bool addressed, bool reads, bool writes, bool or_reads);

    EscConfig config_;
    std::vector<std::uint8_t> memory_;  // 64 KiB
    std::vector<std::uint8_t> eeprom_;
    bool eeprom_loaded_ = false;
    std::vector<SmState> sms_;
    std::uint32_t sm_activation_unread_ = 0;  // SMs whose activate changed since the PDI read it
    bool watchdog_armed_ = false;               // triggered at least once since power-on
    std::uint64_t watchdog_trigger_ns_ = 0;     // the last trigger (a write to a watched SM)
    FramePass pass_;
};

}  // namespace esi::esc
