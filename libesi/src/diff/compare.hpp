#pragma once
// Internal to the differ: the comparison of each part of the model. Each function walks one
// part of the old and the new model side by side and records what differs. `path` is the model
// path of the part; the positions are those of the enclosing elements, used when the part
// exists on one side only.

#include <optional>
#include <set>
#include <string>
#include <vector>

#include "diff/recorder.hpp"
#include "esi/model/device.hpp"
#include "esi/model/ethercat_info.hpp"

namespace esi::diff_detail {

// Everything below Device except identity matching (done by the caller).
void compare_device(Recorder& r, const Device& old_device, const Device& new_device);

// SyncManagers, FMMUs and sync units of a device.
void compare_sync_managers(Recorder& r, const Device& old_device, const Device& new_device);

// RxPdo/TxPdo lists of a device or module, their entries, and the default SM assignment order.
void compare_pdos(Recorder& r, const std::string& path, const std::vector<Pdo>& old_pdos, const std::vector<Pdo>& new_pdos,
                  SourcePos old_parent, SourcePos new_parent);

// A Profile's Dictionary (either may be absent: every object is then added or removed).
void compare_dictionaries(Recorder& r, const std::string& path, const Dictionary* old_dictionary,
                          const Dictionary* new_dictionary, SourcePos old_parent, SourcePos new_parent);

void compare_profiles(Recorder& r, const std::string& path, const std::vector<const Profile*>& old_profiles,
                      const std::vector<const Profile*>& new_profiles, SourcePos old_parent, SourcePos new_parent);

void compare_mailboxes(Recorder& r, const std::string& path, const std::optional<Mailbox>& old_mailbox,
                       const std::optional<Mailbox>& new_mailbox, SourcePos old_parent, SourcePos new_parent);

void compare_dc(Recorder& r, const std::string& path, const std::optional<Dc>& old_dc, const std::optional<Dc>& new_dc,
                SourcePos old_parent, SourcePos new_parent);

void compare_eeproms(Recorder& r, const std::string& path, const std::optional<Eeprom>& old_eeprom,
                     const std::optional<Eeprom>& new_eeprom, SourcePos old_parent, SourcePos new_parent);

void compare_slots(Recorder& r, const std::string& path, const std::optional<Slots>& old_slots,
                   const std::optional<Slots>& new_slots, SourcePos old_parent, SourcePos new_parent);

// Vendor, groups and modules: the parts of a file that belong to no single device.
void compare_vendors(Recorder& r, const Vendor* old_vendor, const Vendor* new_vendor, SourcePos old_parent, SourcePos new_parent,
                     bool compare_id);
void compare_groups(Recorder& r, const std::vector<const Group*>& old_groups, const std::vector<const Group*>& new_groups,
                    SourcePos old_parent, SourcePos new_parent);
// Modules with a breaking change (or removed), by ModuleIdent and by ModuleClass: a device whose
// slots accept one of them changed in a breaking way too.
struct BrokenModules {
    std::set<std::uint32_t> idents;
    std::set<std::string> classes;
    [[nodiscard]] bool affect(const Device& device) const;
};
BrokenModules compare_modules(Recorder& r, const std::string& path, const std::vector<const Module*>& old_modules,
                              const std::vector<const Module*>& new_modules, SourcePos old_parent, SourcePos new_parent);

}  // namespace esi::diff_detail
