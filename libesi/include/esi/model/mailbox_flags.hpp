#pragma once
// The capability flags of each mailbox protocol, as one table per protocol: the reader, the
// writer, the YAML source parser and the differ walk these instead of naming every flag again.

#include <cstddef>
#include <optional>
#include <string_view>

#include "esi/model/mailbox.hpp"

namespace esi {

// An xs:boolean attribute of a protocol element (absent means false, ETG.2000 MailboxType).
template <class Protocol>
struct MailboxFlag {
    std::string_view attribute;  // in the ESI: "SdoInfo"
    std::string_view key;        // the model field's name, which the YAML device source uses: "sdo_info"
    std::optional<bool> Protocol::*field;
};

// In schema order. EdsFile and DS402Channels, which are not flags, come between CompleteAccess
// and SegmentedSdo in the schema (coe_flags_before_eds_file).
inline constexpr MailboxFlag<CoeProtocol> coe_flags[] = {
    {"SdoInfo", "sdo_info", &CoeProtocol::sdo_info},
    {"PdoAssign", "pdo_assign", &CoeProtocol::pdo_assign},
    {"PdoConfig", "pdo_config", &CoeProtocol::pdo_config},
    {"PdoUpload", "pdo_upload", &CoeProtocol::pdo_upload},
    {"CompleteAccess", "complete_access", &CoeProtocol::complete_access},
    {"SegmentedSdo", "segmented_sdo", &CoeProtocol::segmented_sdo},
    {"DiagHistory", "diag_history", &CoeProtocol::diag_history},
    {"SdoUploadWithMaxLength", "sdo_upload_with_max_length", &CoeProtocol::sdo_upload_with_max_length},
    {"TimeDistribution", "time_distribution", &CoeProtocol::time_distribution},
    {"ModuleOD", "module_od", &CoeProtocol::module_od},
};
inline constexpr std::size_t coe_flags_before_eds_file = 5;
static_assert(coe_flags[coe_flags_before_eds_file - 1].field == &CoeProtocol::complete_access);

inline constexpr MailboxFlag<EoeProtocol> eoe_flags[] = {
    {"IP", "ip", &EoeProtocol::ip},
    {"MAC", "mac", &EoeProtocol::mac},
    {"TimeStamp", "time_stamp", &EoeProtocol::time_stamp},
};

// After ChannelCount, a number.
inline constexpr MailboxFlag<SoeProtocol> soe_flags[] = {
    {"DriveFollowsBit3Support", "drive_follows_bit3_support", &SoeProtocol::drive_follows_bit3_support},
};

inline constexpr MailboxFlag<AoeProtocol> aoe_flags[] = {
    {"AdsRouter", "ads_router", &AoeProtocol::ads_router},
    {"GenerateOwnNetId", "generate_own_net_id", &AoeProtocol::generate_own_net_id},
    {"InitializeOwnNetId", "initialize_own_net_id", &AoeProtocol::initialize_own_net_id},
};

}  // namespace esi
