#pragma once
// The PDI side of an emulated EtherCAT Slave Controller: what the microcontroller's slave stack
// sees (ESC datasheet section II, "PDI" and the register descriptions). A slave stack — esi-sim's
// model slave, SOES through a HAL in the tests, or a user's own — reaches the ESC through this
// interface only, and every access has the side effects a real ESC gives a PDI access:
//  - reading AL control (0x0120) clears the AL control event (AL event request 0x0220 bit 0);
//  - reading an SM's activate register (0x0806 + 8n) clears the SM-activation-changed event
//    (0x0220 bit 4) once no SM has an unread change;
//  - mailbox SyncManagers: the PDI writing the last byte of a read mailbox (MBoxIn, the master
//    reads it) makes it full; the PDI reading the last byte of a full write mailbox (MBoxOut, the
//    master wrote it) empties it; the SM's AL event bit (0x0220 bit 8 + n) is set when the ECAT
//    side completes its access and cleared by the PDI's access to the buffer;
//  - buffered (3-buffer) SyncManagers: the PDI reads outputs from the newest complete buffer and
//    writes inputs into a free buffer, with the same first-byte/last-byte rules as the ECAT side;
//  - AL status (0x0130) and AL status code (0x0134) are written by the PDI (the ECAT side only
//    reads them); SM PDI control (0x0807 + 8n) bit 0 deactivates the SM, bit 1 acknowledges a
//    repeat request.
// Registers the emulator does not model read as 0; accesses past 0xFFFF are cut at the end of the
// address space.

#include <cstdint>
#include <span>

namespace esi::esc {

class Pdi {
public:
    virtual ~Pdi();
    virtual void read(std::uint16_t address, std::span<std::uint8_t> out) = 0;
    virtual void write(std::uint16_t address, std::span<const std::uint8_t> in) = 0;
    // The AL event request (0x0220) masked by the AL event mask (0x0204): what the ESC's PDI
    // interrupt line (IRQ) reports. Reading it has no side effect.
    [[nodiscard]] virtual std::uint32_t al_event() const = 0;
};

// A slave stack running on an emulated ESC: the firmware's main loop, one iteration per call.
// The emulator calls poll() after every frame it has processed, so a stack reacts before the
// master's next frame arrives (an idealisation: a real microcontroller runs beside the frames).
class SlaveStack {
public:
    virtual ~SlaveStack();
    virtual void poll(Pdi& pdi) = 0;
};

}  // namespace esi::esc
