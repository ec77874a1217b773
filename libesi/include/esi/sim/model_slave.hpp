#pragma once
// The firmware a device built from the model would run, as a slave stack on the emulated ESC's
// PDI (esi/esc/pdi.hpp): the AL state machine with the checks a real device makes on each
// transition (ETG.1000.6 6.4), a mailbox with a CoE server (SDO upload and download, expedited,
// normal and segmented, complete access, SDO Information), the PDO assignment and mapping
// objects a master may rewrite in PREOP, and the process data copied between the SyncManager
// buffers and the dictionary's objects. docs/esi-sim.md says what is emulated and what is not.

#include <memory>

#include "esi/diagnostic.hpp"
#include "esi/esc/pdi.hpp"
#include "esi/model/ethercat_info.hpp"

namespace esi::sim {

struct ModelSlaveOptions {
    // Copy the output process data into the input image where the bytes line up (a loopback
    // for tests); otherwise the inputs hold their objects' values (the defaults).
    bool echo = false;
};

// A slave stack for `device` (one of info.devices). The stack keeps its own copy of what it
// needs from the model, so `info` need not outlive it. Diagnostics get errors where the device
// cannot be emulated (then the result is null) and notes on what was derived.
[[nodiscard]] std::unique_ptr<esc::SlaveStack> make_model_slave(const EtherCATInfo& info, const Device& device,
                                                                const ModelSlaveOptions& options, Diagnostics& diagnostics);

}  // namespace esi::sim
