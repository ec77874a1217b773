// SmKind from an ESI Sm text (sm_kind.hpp).

#include "sm_kind.hpp"

#include "esi/ethercat/sync_manager_type.hpp"

namespace esi::net {

SmKind sm_kind_of(std::string_view esi_type) {
    switch (ethercat::parse_sync_manager_type(esi_type).value_or(ethercat::SyncManagerType::unused)) {
        case ethercat::SyncManagerType::mailbox_out: return SmKind::mailbox_out;
        case ethercat::SyncManagerType::mailbox_in: return SmKind::mailbox_in;
        case ethercat::SyncManagerType::outputs: return SmKind::outputs;
        case ethercat::SyncManagerType::inputs: return SmKind::inputs;
        case ethercat::SyncManagerType::unused: break;
    }
    return SmKind::unused;
}

}  // namespace esi::net
