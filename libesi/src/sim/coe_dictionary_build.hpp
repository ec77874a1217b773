#pragma once
// The run-time dictionary of a device, from its model: the Dictionary's objects with their
// layouts and default values, completed by what follows from the rest of the device (0x1000,
// 0x1018, the PDO mapping and assignment objects, 0x1C00) through the derive layer, and for the
// objects PDO entries name that no Dictionary declares (an ESI without one), objects made from
// the entries themselves so the process data has somewhere to live.

#include "esi/diagnostic.hpp"
#include "esi/model/ethercat_info.hpp"
#include "sim/coe_dictionary.hpp"
#include "sim/sdo_access.hpp"

namespace esi::sim {

// The device as the stack runs it: `device` completed by derivation (its own copy).
struct DeviceModel {
    Device device;
    std::uint32_t vendor_id = 0;
    CoeDictionary dictionary;
    bool dictionary_from_model = false;  // the ESI/YAML declared a Dictionary
};

// 0x1C00 (SM communication types, ETG.1000.6 5.6.7.4.8) where the Dictionary declares it without
// values: a master (SOEM's ecx_readPDOmap) reads its PDO configuration only when 0x1C00 lists the
// SMs, and the device's SMs say what it holds (1 MBoxOut, 2 MBoxIn, 3 Outputs, 4 Inputs).
void fill_sm_types(CoeDictionary& dictionary, const std::vector<SmRole>& roles);

// The assignment object 0x1C10+n, with sub-index 0 = 0 (no PDO assigned), for every SM n that
// 0x1C00 lists as a process-data SM (outputs or inputs) and that has none: a master reads 0x1C12
// and 0x1C13 after 0x1C00 and stops mapping at an abort (issue 37, F14; SSC and SOES devices have
// the object), as docs/esi-sim.md promises. Objects a source declares are never replaced.
void add_missing_assignment_objects(CoeDictionary& dictionary);

[[nodiscard]] DeviceModel build_device_model(const EtherCATInfo& info, const Device& device, Diagnostics& diagnostics);

}  // namespace esi::sim
