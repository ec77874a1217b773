#pragma once
// Descriptions/Devices/Device.

#include "esi/model/dc.hpp"
#include "esi/model/dictionary.hpp"
#include "esi/model/eeprom.hpp"
#include "esi/model/mailbox.hpp"
#include "esi/model/module.hpp"
#include "esi/model/pdo.hpp"
#include "esi/model/sync_manager.hpp"

namespace esi {

// Device/Type: identity of the device.
struct DeviceIdentity {
    std::string text;
    std::optional<std::uint32_t> product_code;
    std::optional<std::uint32_t> revision_no;
    std::optional<std::uint32_t> serial_no;
    std::optional<bool> tc_cfg_mode_safe_op;  // deprecated (CTT 5-5)
    SourcePos pos;
    Extras extras;  // CheckProductCode, TcSmClass, UseLrdLwr … as written
};

struct Device {
    std::string physics;  // @Physics, one letter per port: Y/H = MII, K = E-Bus, space = none
    std::optional<bool> invisible;
    DeviceIdentity type;
    Names names;
    Names comments;
    Names urls;
    std::optional<std::string> group_type;
    SourcePos group_type_pos;
    std::vector<Profile> profiles;
    std::vector<Fmmu> fmmus;
    std::vector<SyncManager> sms;
    std::vector<SyncUnit> sus;
    std::vector<Pdo> rx_pdos;
    std::vector<Pdo> tx_pdos;
    std::optional<Mailbox> mailbox;
    std::optional<Dc> dc;
    std::optional<Slots> slots;
    std::optional<Eeprom> eeprom;
    Images images;
    SourcePos pos;
    Extras extras;  // Info, ESC, HideType, AlternativeType, SubDevice, Sci, VendorSpecific …

    // The first Profile/Dictionary, if any.
    [[nodiscard]] const Dictionary* dictionary() const;
    [[nodiscard]] const std::vector<Pdo>& pdos(PdoDirection direction) const {
        return direction == PdoDirection::rx ? rx_pdos : tx_pdos;
    }
    [[nodiscard]] const Pdo* find_pdo(std::uint32_t index) const;
};

}  // namespace esi
