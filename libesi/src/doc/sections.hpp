#pragma once
// The sections of a device page, each built from the model into the page view. A section that
// the device does not have is null, so a template's {{#section}} leaves it out.

#include <string_view>
#include <vector>

#include "doc/page_context.hpp"
#include "esi/model/device.hpp"

namespace esi::doc {

// Mailbox protocols, mailbox sizes, CoE details, bootstrap mailbox; null without a mailbox.
[[nodiscard]] ViewValue mailbox_section(const Device& device, const PageContext& context);

// SyncManagers and FMMUs.
[[nodiscard]] ViewValue sync_managers_list(const Device& device, const PageContext& context);
[[nodiscard]] ViewValue fmmus_list(const Device& device, const PageContext& context);

// The default process image of each SyncManager, with its picture.
[[nodiscard]] ViewValue process_images_list(const Device& device, const PageContext& context);

// Every PDO of `rx` then `tx` with its entries and picture. `owner` prefixes the entries'
// data-entry keys ("dev", "m3") and the PDOs' element ids, so both are unique in the page.
[[nodiscard]] ViewValue pdos_list(const std::vector<Pdo>& rx, const std::vector<Pdo>& tx, std::string_view owner,
                                  const PageContext& context);

// The object dictionary (objects sorted by index); null without one.
[[nodiscard]] ViewValue dictionary_section(const Dictionary* dictionary, const PageContext& context);

// DC op modes; null without a Dc element.
[[nodiscard]] ViewValue dc_section(const Device& device, const PageContext& context);

// InitCmds of every mailbox protocol, grouped by transition; null without any.
[[nodiscard]] ViewValue init_cmds_section(const Mailbox* mailbox, const PageContext& context);

// Slots and the modules they accept, with the modules' PDOs; null without slots.
[[nodiscard]] ViewValue modules_section(const Device& device, const PageContext& context);
// Every module of a catalogue with its PDOs (a module description file has no slots).
[[nodiscard]] ViewValue all_modules_section(const EtherCATInfo& info, const PageContext& context);

}  // namespace esi::doc
