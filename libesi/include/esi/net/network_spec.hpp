#pragma once
// NETWORK.yaml as written (docs/esi-net.md, schemas/esi-network.schema.json): where the ESI
// files are, the master, and the ordered slaves with what each configures. Every value keeps
// its position so that the network pass reports problems at the line that caused them.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "esi/diagnostic.hpp"
#include "esi/model/limits.hpp"
#include "esi/model/typed_value.hpp"

namespace esi::net {

// The linuxcnc-ethercat lcec.xml is written for. The two maintained forks read the same grammar
// but refuse each other's additions (docs/esi-net.md, "linuxcnc-ethercat").
enum class LcecFork {
    linuxcnc_ethercat,  // github.com/linuxcnc-ethercat/linuxcnc-ethercat (lcec_configgen's home)
    sittner,            // github.com/sittner/linuxcnc-ethercat
};

struct MasterSpec {
    std::string name = "Master";
    std::uint32_t cycle_time_us = 1000;
    bool dc = true;  // false: every slave runs without DC (free run or SM-synchronous)
    std::string source_mac = "000000000000";  // ENI Master/Info/Source (12 hex digits)
    LcecFork lcec_fork = LcecFork::linuxcnc_ethercat;
    SourcePos pos;
};

// One entry of a configurable PDO: index:subindex:bitlen; index 0 is padding.
struct PdoEntrySpec {
    std::uint32_t index = 0;
    std::uint32_t subindex = 0;
    std::uint32_t bit_len = 0;
    SourcePos pos;
};

struct PdoEntriesSpec {
    std::uint32_t pdo = 0;
    std::vector<PdoEntrySpec> entries;
    SourcePos pos;
};

struct PdoRef {
    std::uint32_t index = 0;
    SourcePos pos;
};

// A module in a slot: the module's Type text or its ModuleIdent; the slot by number (0-based)
// or by its Name, else the module's place in the list.
struct ModuleSpec {
    std::optional<std::string> type;
    std::optional<std::uint32_t> ident;
    std::optional<std::uint32_t> slot;
    std::optional<std::string> slot_name;
    bool empty = false;  // `-` / null: leave this slot empty
    SourcePos pos;
};

// An extra start-up SDO download.
struct SdoSpec {
    std::uint32_t index = 0;
    std::uint32_t subindex = 0;
    std::optional<SourceValue> value;   // typed by the object dictionary or by `type`
    std::optional<std::string> type;    // an ESI data type name (UINT, DINT, STRING(8) …)
    std::optional<std::vector<std::uint8_t>> data;  // raw bytes instead of a value
    std::vector<std::string> transitions;  // default PS
    bool complete_access = false;
    std::optional<std::string> comment;
    SourcePos pos;
    SourcePos transition_pos;
};

// ros2_interfaces: how the ethercat_driver_ros2 output names one mapped entry (docs/esi-net.md):
// its interface name (none: `~`), and the driver's factor, offset and default.
struct Ros2InterfaceSpec {
    std::uint32_t index = 0;
    std::uint32_t subindex = 0;
    std::optional<std::string> name;  // absent with no_interface or when only numbers are given
    bool no_interface = false;
    std::optional<double> factor, offset, default_value;  // default may be NaN (.nan)
    SourcePos pos;
};

// force_entries: an entry the ESI marks not mappable that the user knows the firmware maps.
struct ForcedEntry {
    std::uint32_t index = 0;
    std::uint32_t subindex = 0;
    SourcePos pos;
};

struct SlaveSpec {
    std::string name;
    SourcePos pos;
    // The device: by Type text or by identity.
    std::optional<std::string> device;
    std::optional<std::uint32_t> vendor_id;
    std::optional<std::uint32_t> product_code;
    std::optional<std::uint32_t> revision;
    SourcePos device_pos;
    // The ESI file to take the device from when several describe its identity (as written,
    // relative to the network file's folder).
    std::optional<std::string> esi_file;
    SourcePos esi_file_pos;
    std::optional<std::uint16_t> alias;  // station alias (second address), 0 = none
    // The PDOs to assign; absent: the ESI's default assignment.
    std::optional<std::vector<PdoRef>> pdos;
    SourcePos pdos_pos;
    // A named mapping (TwinCAT AlternativeSmMapping) instead of a list.
    std::optional<std::string> pdo_mapping;
    SourcePos pdo_mapping_pos;
    std::vector<PdoEntriesSpec> pdo_entries;
    std::optional<std::string> dc;  // DC op mode name; absent: the ESI's first op mode
    SourcePos dc_pos;
    std::optional<std::vector<ModuleSpec>> modules;
    SourcePos modules_pos;
    std::vector<SdoSpec> sdos;
    Limits limits;  // the device family's constraints (`limits:`, as in device sources)
    std::vector<Ros2InterfaceSpec> ros2_interfaces;
    std::vector<ForcedEntry> force_entries;
    // Topology (topology.cpp): the slave this one hangs off (default: the one listed before)
    // and that slave's port (B, C or D; default: its first free port of this one's physics).
    std::optional<std::string> previous_slave;
    SourcePos previous_slave_pos;
    std::optional<std::string> previous_port;
    SourcePos previous_port_pos;
};

// The most slaves one network holds: slave n gets station address 1001 + n, a 16-bit register
// (ESC 0x0010), so 64,535 is what an EtherCAT segment can address this way.
inline constexpr std::size_t max_network_slaves = 0xFFFF - 1000;

struct NetworkSpec {
    std::string path;  // the file, for diagnostics
    std::vector<std::string> esi;  // as written, relative to the file's folder
    SourcePos esi_pos;
    MasterSpec master;
    std::vector<SlaveSpec> slaves;
};

struct NetworkFileResult {
    std::optional<NetworkSpec> spec;  // absent when the file has errors
    Diagnostics diagnostics;
};

// Reads NETWORK.yaml with the project's YAML reader: duplicate keys, unknown keys with
// did-you-mean, and line:column on every problem.
[[nodiscard]] NetworkFileResult read_network_file(const std::string& path);
[[nodiscard]] NetworkFileResult read_network_text(std::string_view text, const std::string& path);

}  // namespace esi::net
