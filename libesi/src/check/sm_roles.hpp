#pragma once
// The role a SyncManager plays in its device, for the sm, fmmu and mailbox rules.

#include "check/queries.hpp"

namespace esi::rules {

// The text decides when it names a role (MBoxOut, MBoxIn, Outputs, Inputs, and Beckhoff's
// DynamicOutputs/DynamicInputs). Otherwise the ControlByte does: bits 3:2 give the direction, and
// mailbox (single-buffer) mode means a mailbox only when no PDO is assigned to the SM. Devices run
// process data in single-buffer mode too (Beckhoff inputs at #x22, IgH-written output SMs at #x46,
// vendor texts such as 'OrbitaState'); queries' sm_role would call those a mailbox.
// `sm` must be an element of `device.sms`.
[[nodiscard]] SmRole device_sm_role(const Device& device, const SyncManager& sm);

// Roles the text alone claims (empty or vendor-specific text: unknown).
[[nodiscard]] SmRole text_sm_role(const SyncManager& sm);

}  // namespace esi::rules
