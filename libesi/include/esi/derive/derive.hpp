#pragma once
// Derivation: completes a device from what its source states, so that what follows from the
// rest is never written twice and cannot disagree. Explicit values always win; a contradiction
// (an explicit SM size smaller than its PDOs, a PDO entry naming a missing or non-mappable
// object, an InitCmd value that does not fit its object) is a diagnostic at the source position.
//
// What is derived (each part can be switched off, e.g. for an imported ESI that must stay as
// it was):
//   mailbox             Mailbox@DataLinkLayer = true (ETG CTT 1-9)
//   pdo_entries         Entry BitLen, DataType and Name from the object the entry names
//   pdo_assignment      RxPdo/TxPdo@Sm for PDOs assigned by default (the first Outputs/Inputs SM)
//   sync_managers       SM0/SM1 mailbox SMs (addresses, sizes from the mailbox settings),
//                       SM2/SM3 process-data SMs (sizes from the default PDOs), control bytes
//   fmmus               Fmmu Outputs/Inputs/MBoxState for the SMs in use
//   device_type_object  0x1000 from the profile number (CiA 301 7.5.2.1)
//   identity_object     0x1018 from vendor id, product code, revision (CiA 301 7.5.2.20)
//   mapping_objects     0x16xx/0x1Axx from the PDOs (ETG.1000.6 5.6.7.4.7)
//   assignment_objects  0x1C12/0x1C13 (0x1C10+SM) from the default assignment (ETG.1000.6 5.6.7.4.9)
//   sm_types_object     0x1C00 from the SM list (ETG.1000.6 5.6.7.4.8)
//   data_types          a DataType for every type an Object, SubItem or BaseType names: the
//                       ETG schema's keyrefs (DataTypesKey) require it, basic types included
//   groups              a Group for a GroupType that no group declares

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "esi/model/limits.hpp"
#include "esi/model/typed_value.hpp"
#include "esi/diagnostic.hpp"
#include "esi/model/ethercat_info.hpp"

namespace esi {

struct DeriveOptions {
    bool groups = true;
    bool mailbox = true;
    bool sync_managers = true;
    bool fmmus = true;
    bool pdo_assignment = true;
    bool pdo_entries = true;
    bool mapping_objects = true;
    bool assignment_objects = true;
    bool sm_types_object = true;
    bool identity_object = true;
    bool device_type_object = true;
    bool data_types = true;

    [[nodiscard]] static DeriveOptions none();
};

// The mailbox SM geometry a source states before any SM exists (`mailbox: {size: 128}`).
struct MailboxLayout {
    std::optional<std::uint32_t> out_address;
    std::optional<std::uint32_t> out_size;
    std::optional<std::uint32_t> in_address;
    std::optional<std::uint32_t> in_size;
    SourcePos pos;
};

// An InitCmd value that gets its bytes once the dictionary is complete (`value: 8`).
struct InitCmdValue {
    std::size_t cmd = 0;  // index into the CoE InitCmds
    SourceValue value;
};

// What a source intends that the model cannot hold.
struct DeviceIntent {
    DeriveOptions options;
    MailboxLayout mailbox;
    std::vector<InitCmdValue> init_values;
    // Parallel to Device::rx_pdos / tx_pdos: assign the PDO to its SM by default.
    std::vector<bool> rx_assign;
    std::vector<bool> tx_assign;
    // Parallel to Device::sms: where an explicit size was written (for contradiction messages).
    std::vector<SourcePos> sm_size_pos;
    std::optional<std::uint32_t> vendor_id;
    // Sizes flexible mapping and assignment objects (max_entries_per_pdo, max_pdos).
    Limits limits;
};

struct ModuleIntent {
    DeriveOptions options;
    std::vector<InitCmdValue> init_values;
    std::vector<bool> rx_assign;  // parallel to Module::rx_pdos
    std::vector<bool> tx_assign;
};

// Completes one device. `path` is the source file the positions refer to.
void derive_device(Device& device, const DeviceIntent& intent, const std::string& path, Diagnostics& diagnostics);

// Completes one module: PDO entries from its own dictionary, else from the dictionary of `host`
// (a device whose slots take the module, as in ETG.2001 files where module PDOs map the device's
// slot-relative objects); the default PDO assignment to the host's Outputs/Inputs SMs; InitCmd
// values; data types.
void derive_module(Module& module, const ModuleIntent& intent, const Device* host, const std::string& path,
                   Diagnostics& diagnostics);

// Adds a Group for every GroupType that names no declared group (name = type). `devices`, when
// not empty, says per device whether its group may be derived.
void derive_groups(EtherCATInfo& info, const std::vector<bool>& devices = {});

}  // namespace esi
