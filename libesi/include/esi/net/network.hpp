#pragma once
// The network model: what a master needs to run an ordered list of devices, worked out from
// their ESI files and NETWORK.yaml. Every writer (ENI, IgH C, linuxcnc-ethercat, the process-
// image map) reads this model and nothing else.
//
// Addresses follow what TwinCAT and EC-Engineer write (docs/esi-net.md): slave n (0-based) has
// the configured station address 1001 + n and the auto-increment address -n (as 16 bits).
// The process image is one contiguous logical range from `logical_base`; inputs and outputs
// of a slave share their logical start, each slave takes max(input, output) bytes, and slaves
// follow each other in bus order. Frames are filled in that order and a new one starts when
// the next slave's data no longer fits (ETG.1000.4: 1,498 bytes of datagrams per frame).

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "esi/diagnostic.hpp"
#include "esi/model/ethercat_info.hpp"
#include "esi/net/library_index.hpp"
#include "esi/net/network_spec.hpp"

namespace esi::net {

struct ConfiguredEntry {
    std::uint32_t index = 0;  // 0: padding
    std::uint32_t subindex = 0;
    std::uint32_t bit_len = 0;
    std::string name;
    std::string data_type;  // ESI type name; empty for padding
    std::optional<std::string> comment;
    bool index_depend_on_slot = false;
    [[nodiscard]] bool is_padding() const { return index == 0; }
};

struct ConfiguredPdo {
    PdoDirection direction = PdoDirection::rx;
    std::uint32_t index = 0;  // after slot increments
    std::string name;
    std::vector<ConfiguredEntry> entries;
    std::uint32_t sm = 0;  // the SyncManager it is assigned to
    bool fixed = false;
    bool mandatory = false;
    bool index_depend_on_slot = false;
    bool entries_configured = false;  // NETWORK.yaml gave its entries (pdo_entries)
    std::vector<std::uint32_t> excludes;
    std::optional<std::size_t> module;  // into NetworkSlave::modules when a module brings it
    [[nodiscard]] std::uint32_t bit_size() const;
};

enum class SmKind { mailbox_out, mailbox_in, outputs, inputs, unused };

struct SmSetup {
    std::uint32_t number = 0;
    SmKind kind = SmKind::unused;
    std::string type;  // ESI text: MBoxOut, MBoxIn, Outputs, Inputs
    std::uint16_t start_address = 0;
    std::uint16_t length = 0;  // configured length in bytes
    std::uint8_t control_byte = 0;
    bool enable = false;
    bool op_only = false;  // ESI Sm@OpOnly: enabled at SO, cleared at OS
    bool is_virtual = false;  // ESI Sm@Virtual: no SyncManager; its FMMU maps ESC registers directly
    std::optional<std::uint32_t> min_size, max_size, default_size;  // ESI values, copied to the ENI
    std::vector<std::size_t> pdos;  // into NetworkSlave::pdos, in assignment order
    [[nodiscard]] bool is_process_data() const { return kind == SmKind::outputs || kind == SmKind::inputs; }
};

enum class FmmuKind { outputs, inputs, mailbox_state };

struct FmmuSetup {
    std::uint32_t number = 0;
    FmmuKind kind = FmmuKind::outputs;
    std::uint32_t sm = 0;
    std::uint32_t logical_start = 0;
    std::uint16_t length = 0;
    std::uint8_t logical_start_bit = 0;
    std::uint8_t logical_stop_bit = 7;
    std::uint16_t physical_start = 0;
    std::uint8_t physical_start_bit = 0;
    bool enable = true;
    // ETG.1000.4 FMMU type: 1 read (inputs), 2 write (outputs).
    [[nodiscard]] std::uint8_t type() const { return kind == FmmuKind::outputs ? 2 : 1; }
};

struct MailboxSetup {
    std::uint16_t out_start = 0, out_length = 0;  // SM0, master -> slave
    std::uint16_t in_start = 0, in_length = 0;    // SM1
    std::optional<std::uint16_t> boot_out_start, boot_out_length, boot_in_start, boot_in_length;
    bool coe = false, eoe = false, foe = false, soe = false, aoe = false, voe = false;
    std::optional<bool> data_link_layer;
    std::optional<std::uint32_t> status_bit;  // bit in the mailbox-state area, with an MBoxState FMMU
    std::vector<std::pair<std::int32_t, std::int32_t>> channel_info;  // CoE profile: ProfileNo, AddInfo
    bool complete_access = false;  // CoE@CompleteAccess
    bool pdo_assign = false;       // CoE@PdoAssign
    bool pdo_config = false;       // CoE@PdoConfig
};

enum class CoeOrigin { assignment, mapping, device, module, network };

struct CoeCommand {
    std::vector<std::string> transitions;
    std::string comment;
    std::uint16_t index = 0;
    std::uint8_t subindex = 0;
    std::vector<std::uint8_t> data;
    bool complete_access = false;
    CoeOrigin origin = CoeOrigin::network;
    [[nodiscard]] bool generated() const { return origin == CoeOrigin::assignment || origin == CoeOrigin::mapping; }
};

struct DcSetup {
    std::string op_mode;
    std::uint16_t assign_activate = 0;
    std::uint32_t cycle_time0 = 0;  // ns
    std::uint32_t cycle_time1 = 0;
    std::int32_t shift_time0 = 0;
    bool reference_clock = false;  // the first DC slave of the bus
};

// ESI Info/StateMachine/Timeout (ms), with the values TwinCAT uses when the ESI has none.
struct StateTimeouts {
    std::uint32_t preop = 3000;
    std::uint32_t safeop_op = 10000;
    std::uint32_t back_to_init = 5000;
    std::uint32_t back_to_safeop = 200;
};

enum class RevisionCheck { none, full, low_word };

struct ModuleInSlot {
    std::uint32_t slot = 0;
    std::string slot_name;
    const Module* module = nullptr;
};

struct NetworkSlave {
    std::string name;
    std::size_t position = 0;
    std::uint16_t phys_addr = 0;
    std::uint16_t auto_inc_addr = 0;
    std::optional<std::uint16_t> alias;
    const Device* device = nullptr;
    const EtherCATInfo* info = nullptr;
    std::string esi_path;
    std::uint32_t vendor_id = 0, product_code = 0, revision = 0;
    std::string physics;
    // Where it hangs off (topology.cpp): the slave before it in the tree and that slave's port
    // (1 = B, 2 = C, 3 = D); none for the first slave.
    std::optional<std::size_t> previous;
    std::size_t previous_port = 1;
    RevisionCheck revision_check = RevisionCheck::none;
    bool identification_reg134 = false;
    std::vector<ModuleInSlot> modules;
    std::vector<ConfiguredPdo> pdos;  // assigned PDOs, in SM and assignment order
    std::vector<SmSetup> sms;  // every SM of the ESI, by number
    std::vector<FmmuSetup> fmmus;
    std::optional<MailboxSetup> mailbox;
    std::vector<CoeCommand> coe_init_cmds;
    std::optional<DcSetup> dc;
    StateTimeouts timeouts;
    std::optional<std::uint16_t> watchdog_divider, pdi_watchdog, sm_watchdog;  // ESI ESC/Reg0400, 0410, 0420
    // Process data bytes per direction (sums of the process-data SMs) and where they sit.
    std::uint32_t output_bytes = 0;
    std::uint32_t input_bytes = 0;
    std::uint32_t image_offset = 0;  // byte offset in both images
    std::size_t frame = 0;
    std::vector<Ros2InterfaceSpec> ros2_interfaces;  // NETWORK.yaml's, for the ROS 2 output
    [[nodiscard]] std::uint32_t image_bytes() const { return output_bytes > input_bytes ? output_bytes : input_bytes; }
};

struct Variable {
    std::size_t slave = 0;
    std::string name;  // "<slave>.<module>.<PDO>.<entry>"
    std::string pdo_name;
    std::uint32_t pdo_index = 0;
    std::uint32_t index = 0;
    std::uint32_t subindex = 0;
    std::string data_type;
    std::uint32_t bit_size = 0;
    std::uint64_t bit_offset = 0;  // in the image of its direction
    PdoDirection direction = PdoDirection::rx;  // rx: an output of the master
    std::optional<std::string> comment;
};

// A cyclic datagram (ETG.1000.4 command codes).
struct Datagram {
    enum class Command : std::uint8_t { nop = 0, brd = 7, lrd = 10, lwr = 11, lrw = 12, armw = 13 };
    Command command = Command::lrw;
    std::uint16_t adp = 0, ado = 0;
    std::uint32_t logical = 0;  // LRD/LWR/LRW
    std::uint16_t length = 0;
    std::optional<std::uint16_t> working_counter;
    bool preop = false;  // also in PREOP (else SAFEOP and OP only)
    std::uint32_t image_offset = 0;  // where its data sit in the image
    std::string comment;
};

struct Frame {
    std::vector<Datagram> datagrams;
};

struct ProcessImage {
    std::uint32_t logical_base = 0x01000000;
    std::uint32_t mailbox_state_base = 0x09000000;
    std::uint32_t process_data_bytes = 0;  // the slaves' share of the image
    std::uint32_t byte_size = 0;           // with the other datagrams' data (BRD, DC, mailbox state)
    std::uint32_t mailbox_state_bytes = 0;
    std::vector<Variable> inputs;
    std::vector<Variable> outputs;
    std::vector<Frame> frames;
};

struct Network {
    std::string name;  // the network file's stem
    std::string path;  // the network file, for diagnostics of the writers that can refuse
    MasterSpec master;
    std::vector<NetworkSlave> slaves;
    ProcessImage image;
    std::optional<std::size_t> reference_clock;  // the first DC slave
    // The ESI documents the slaves point into.
    std::vector<std::shared_ptr<const EsiDocument>> documents;
};

struct BuildOptions {
    std::vector<std::filesystem::path> extra_esi;  // --esi
    IndexOptions index;
};

struct BuildResult {
    std::optional<Network> network;  // absent on error
    Diagnostics diagnostics;
    IndexStats index_stats;
};

// Resolves every slave, selects and checks its PDOs, sets up SMs, FMMUs, mailbox, DC and start-up
// commands, and lays out the process image. Paths in the spec are relative to its file's folder.
[[nodiscard]] BuildResult build_network(const NetworkSpec& spec, const BuildOptions& options);
// The same with an index built beforehand (benchmarks, tests).
[[nodiscard]] BuildResult build_network(const NetworkSpec& spec, const LibraryIndex& index);

}  // namespace esi::net
