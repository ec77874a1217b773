#pragma once
// The tests' EtherCAT master for a line of virtual slaves, in process: it builds frames of
// datagrams (ETG.1000.4 §5), passes them through sim::Line as the wire would, and checks every
// answer (index, command, length, working counter). On top of that, what a master does to bring
// slaves from their EEPROMs to OP (ETG.1000.6 §6; ESC datasheet section II):
//  - counts the slaves (BRD), gives each a station address (APWR 0x0010), reads its SII through
//    the EEPROM interface (0x0502..0x050F) and decodes it with the sii layer;
//  - sets up the mailbox SyncManagers from the SII and requests AL states (0x0120/0x0130/0x0134);
//  - runs CoE SDO uploads (expedited, normal, segmented) and SDO Information (OD list, object
//    description) through the mailbox, with the mailbox counter;
//  - sizes the process data as SOEM does (CoE 0x1C00 and the assignment and mapping objects when
//    the device has CoE, else the SII's PDO categories), sets up the process-data SyncManagers
//    and one FMMU per direction (outputs of every slave first, then inputs), and cycles LRW.
// Every frame is kept with its simulated time, request and answer, so a test writes the whole
// exchange as a pcap file for Wireshark's dissectors (wireshark_check.hpp).
//
// Written for the tests: the esi-sim behaviour that a third-party master used to show is checked
// with it, frame by frame, without a socket. Every wait is a bounded number of frames.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "esi/esc/esc.hpp"
#include "esi/sii/decode.hpp"
#include "esi/sim/line.hpp"

namespace esi::test {

// One datagram's answer.
struct Answer {
    std::vector<std::uint8_t> data;
    std::uint16_t working_counter = 0;
};

// One frame on the wire, as a capture on the master's port sees it: the EtherCAT payload (from
// the EtherCAT header on) and when it passed.
struct CapturedFrame {
    std::uint64_t time_ns = 0;
    bool from_master = true;
    std::vector<std::uint8_t> payload;
};

// An SDO transfer's result: the data, or the abort code (ETG.1000.6 Table 41). `failure` names a
// protocol fault of the answer itself (no answer, a wrong service, a toggle bit out of step).
struct SdoUpload {
    std::vector<std::uint8_t> data;
    std::uint32_t abort_code = 0;
    std::string failure;
    [[nodiscard]] bool ok() const { return abort_code == 0 && failure.empty(); }
};

struct ObjectDescription {
    std::uint16_t index = 0;
    std::uint16_t data_type = 0;
    std::uint8_t max_subindex = 0;
    std::uint8_t object_code = 0;
    std::string name;
};

// What the master knows of one slave.
struct LineSlave {
    std::uint16_t station = 0;
    std::vector<std::uint8_t> sii;  // as read through the EEPROM interface
    sii::DecodedImage decoded;
    std::uint16_t eeprom_status = 0;  // 0x0502 after power-on
    std::uint16_t dl_status = 0;      // 0x0110
    bool mailbox = false;             // the SII gives a standard mailbox
    std::uint16_t mbx_out_start = 0, mbx_out_size = 0, mbx_in_start = 0, mbx_in_size = 0;
    std::uint8_t mailbox_counter = 0;
    bool coe = false;
    // Process data, per SyncManager: its type (3 outputs, 4 inputs) and size in bits.
    std::map<unsigned, std::uint8_t> sm_types;
    std::map<unsigned, std::uint32_t> sm_bits;
    std::uint32_t output_bits = 0, input_bits = 0;
    std::uint32_t output_offset = 0, input_offset = 0;  // in the logical image
    [[nodiscard]] std::uint32_t output_bytes() const { return (output_bits + 7) / 8; }
    [[nodiscard]] std::uint32_t input_bytes() const { return (input_bits + 7) / 8; }
};

struct StateResult {
    std::uint16_t al_status = 0;       // 0x0130 as last read
    std::uint16_t al_status_code = 0;  // 0x0134
    [[nodiscard]] std::uint8_t state() const { return al_status & 0x0F; }
    [[nodiscard]] bool error() const { return (al_status & 0x10) != 0; }
};

class LineMaster {
public:
    explicit LineMaster(sim::Line& line) : line_(line) {}

    // --- frames ---
    // One frame of one datagram. The answer is absent when the frame came back malformed or was
    // lost, or its datagram does not match what was sent (index, command, length).
    std::optional<Answer> datagram(esc::Command command, std::uint16_t adp, std::uint16_t ado, std::vector<std::uint8_t> data);
    // Several datagrams in one frame, answered in order; absent as above.
    std::optional<std::vector<Answer>> frame(const std::vector<std::tuple<esc::Command, std::uint16_t, std::uint16_t, std::vector<std::uint8_t>>>& datagrams);
    // Configured-address read and write of one slave; false (or absent) unless the working counter is 1.
    std::optional<std::vector<std::uint8_t>> read(std::uint16_t station, std::uint16_t address, std::size_t length);
    bool write(std::uint16_t station, std::uint16_t address, std::vector<std::uint8_t> data);
    std::optional<std::uint16_t> read16(std::uint16_t station, std::uint16_t address);
    bool write16(std::uint16_t station, std::uint16_t address, std::uint16_t value);

    // --- bring-up ---
    // Counts the slaves, assigns station addresses 0x1001.., reads each SII. False when the
    // count differs from the line's or a slave does not answer.
    bool scan();
    // The SII words from `word` on, through the EEPROM interface (8-byte reads).
    std::optional<std::vector<std::uint8_t>> read_sii(std::uint16_t station, std::uint32_t word, std::size_t bytes);

    // --- AL state ---
    // Requests `state` (1 INIT, 2 PREOP, 4 SAFEOP, 8 OP) and polls AL status until the slave is
    // there or shows an error, for at most `polls` frames (each a cycle when cycling is set up).
    StateResult request_state(LineSlave& slave, std::uint8_t state, int polls = 200);
    StateResult acknowledge_error(LineSlave& slave, std::uint8_t state);
    StateResult state_of(const LineSlave& slave);

    // --- mailbox ---
    bool setup_mailbox(LineSlave& slave);
    // Writes one request (type 3 CoE) and waits for the answer (at most `polls` frames).
    std::optional<std::vector<std::uint8_t>> mailbox_exchange(LineSlave& slave, std::uint8_t type,
                                                              const std::vector<std::uint8_t>& payload, int polls = 50);
    std::optional<std::vector<std::uint8_t>> mailbox_receive(LineSlave& slave, int polls = 50);
    SdoUpload upload(LineSlave& slave, std::uint16_t index, std::uint8_t subindex, bool complete_access = false);
    std::uint32_t download(LineSlave& slave, std::uint16_t index, std::uint8_t subindex, const std::vector<std::uint8_t>& data,
                           bool complete_access = false);
    // SDO Information: every object's index (list type 1); absent with `failure` set.
    std::optional<std::vector<std::uint16_t>> od_list(LineSlave& slave, std::string& failure);
    std::optional<ObjectDescription> object_description(LineSlave& slave, std::uint16_t index, std::string& failure);

    // --- process data ---
    // Sizes every slave's process data, sets up its SyncManagers and FMMUs; returns the
    // expected working counter of the LRW cycle.
    std::uint16_t setup_process_data();
    // One LRW cycle with the outputs given (the whole output image), `ms` of simulated time
    // later than the last frame. The inputs image and the working counter come back.
    std::optional<Answer> cycle(const std::vector<std::uint8_t>& outputs, std::uint64_t ns = 1'000'000);
    [[nodiscard]] std::uint32_t output_image_bytes() const { return output_image_bytes_; }
    [[nodiscard]] std::uint32_t input_image_bytes() const { return input_image_bytes_; }

    // Brings every slave to OP: mailbox, PREOP, process data, SAFEOP, three cycles, OP. The
    // first refusal stops it; `refused` then names the slave.
    bool to_op(std::size_t* refused = nullptr, StateResult* refusal = nullptr);

    std::vector<LineSlave> slaves;
    std::vector<CapturedFrame> capture;
    std::uint64_t time_ns = 0;
    std::uint64_t frame_gap_ns = 20'000;  // between frames outside the cycle

private:
    std::uint32_t sm_bits_over_coe(LineSlave& slave, unsigned sm, bool& ok);
    [[nodiscard]] std::uint32_t sm_bits_from_sii(const LineSlave& slave, unsigned sm) const;

    sim::Line& line_;
    std::uint8_t next_index_ = 0;
    std::uint32_t output_image_bytes_ = 0, input_image_bytes_ = 0;
};

}  // namespace esi::test
