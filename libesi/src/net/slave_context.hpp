#pragma once
// What the steps that configure one slave share: its spec, the device and catalogue it
// resolved to, the slave being filled in and the diagnostics. Each step lives in its own file:
//
//   modules.cpp        modules in slots (ETG.2001 modular devices)
//   pdo_selection.cpp  which PDOs are assigned to which SM (default, mapping name or list)
//   pdo_entries.cpp    the entries of configurable PDOs, checked against the dictionary
//   sync_setup.cpp     SyncManagers, FMMUs, mailbox, state timeouts, ESC registers
//   dc_setup.cpp       the DC op mode
//   coe_init_cmds.cpp  the CoE start-up commands
//
// and run in that order (network_build.cpp).

#include <optional>
#include <string>
#include <vector>

#include "esi/model/limits.hpp"
#include "esi/net/network.hpp"

namespace esi::net {

struct SlaveContext {
    const NetworkSpec& network;
    const SlaveSpec& spec;
    NetworkSlave& slave;
    const Device& device;
    const EtherCATInfo& info;
    Limits limits;  // the device source's `limits:` merged with the slave's
    Diagnostics& diagnostics;

    Diagnostic& error(SourcePos pos, std::string rule, std::string message) {
        return diagnostics.emplace(Severity::error, std::move(rule), std::move(message), network.path, pos);
    }
    Diagnostic& warning(SourcePos pos, std::string rule, std::string message) {
        return diagnostics.emplace(Severity::warning, std::move(rule), std::move(message), network.path, pos);
    }
    [[nodiscard]] bool coe() const { return device.mailbox && device.mailbox->coe; }
};

// A PDO a slave can assign: one of the device's, or one a module in a slot brings (with its
// index moved by the slot's PDO increment).
struct AvailablePdo {
    const Pdo* pdo = nullptr;
    std::uint32_t index = 0;
    std::optional<std::size_t> module;  // into NetworkSlave::modules
    std::uint32_t slot = 0;
};

void configure_modules(SlaveContext& context);
[[nodiscard]] std::vector<AvailablePdo> available_pdos(const SlaveContext& context);
// The entry indices of a module's PDO entry or InitCmd after the slot's index increment.
[[nodiscard]] std::uint32_t slot_index(const SlaveContext& context, std::size_t module, std::uint32_t index, bool depend_on_slot);

// An object of the slave's dictionary: the device's, else one a module brings (its index
// moved by the slot's index increment when it depends on the slot).
struct FoundObject {
    const Dictionary* dictionary = nullptr;
    const Object* object = nullptr;
};
[[nodiscard]] FoundObject find_object(const SlaveContext& context, std::uint32_t index);
// True when the slave has any object dictionary to check against.
[[nodiscard]] bool has_dictionary(const SlaveContext& context);

void select_pdos(SlaveContext& context);
void configure_pdo_entries(SlaveContext& context);
void setup_sync_managers(SlaveContext& context);
void setup_dc(SlaveContext& context, const MasterSpec& master);
void build_coe_init_cmds(SlaveContext& context, const MasterSpec& master);
// ros2_interfaces name entries the slave maps (ros2_channels.cpp).
void check_ros2_interfaces(SlaveContext& context);

// Which slave and port each slave hangs off (previous_slave/previous_port, else the slave listed
// before), checked against the devices' ports and the order the frame visits them (topology.cpp).
void resolve_topology(Network& network, const NetworkSpec& spec, Diagnostics& diagnostics);

// representable.cpp: refuse the slave when the reader could not read a value of its device
// (`devices`: the file's devices, to tell whose an error is) or when a value does not fit the
// outputs' fields.
void check_reader_errors(SlaveContext& context, const std::vector<const Device*>& devices, const Diagnostics& reader);
void check_representable(SlaveContext& context);

// slave_fingerprint.cpp: what a master configures for the slave, names and comments left out.
[[nodiscard]] std::string configuration_fingerprint(const NetworkSlave& slave);

// The process image: slave offsets, frames, FMMU logical addresses, variables.
void layout_process_image(Network& network, Diagnostics& diagnostics, const std::string& path);

// "0x1A00" (upper-case hex, at least 4 digits).
[[nodiscard]] std::string hex_index(std::uint32_t value);

}  // namespace esi::net
