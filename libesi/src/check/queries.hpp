#pragma once
// Questions many rules ask of the model, answered once here.

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "check/dictionary_index.hpp"
#include "esi/model/ethercat_info.hpp"
#include "esi/model/object_layout.hpp"

namespace esi::rules {

// Every device of a document (all infos of an EtherCATInfoList).
[[nodiscard]] std::vector<const Device*> all_devices(const EsiDocument& document);

// What a SyncManager is for, from its text (MBoxOut …) or, when the text is missing, its
// ControlByte (ETG.1000.4 register 0x0804: bits 1:0 mode, bits 3:2 direction).
enum class SmRole { mailbox_out, mailbox_in, outputs, inputs, unknown };
[[nodiscard]] SmRole sm_role(const SyncManager& sm);
[[nodiscard]] std::string_view to_string(SmRole role);
[[nodiscard]] SmRole role_from_text(std::string_view text);  // MBoxOut, MBoxIn, Outputs, Inputs
// ControlByte bits: 0b10 in bits 1:0 is mailbox, 0b00 buffered; bits 3:2 = 01 write (master -> slave).
[[nodiscard]] bool control_byte_is_mailbox(std::uint32_t control_byte);
[[nodiscard]] bool control_byte_is_write(std::uint32_t control_byte);

// The default of an object sub-entry as an integer bit pattern: DefaultValue, else DefaultData
// read little-endian (ETG.2000 ObjectInfoType: DefaultData holds the bytes in SDO order, so
// 0x1018:01 = 2 is written "02000000"). nullopt when there is no default, the data is not valid
// hex or longer than 8 bytes. Rules comparing identity, 0x1C00 or 0x1C12/0x1C13 defaults use it.
[[nodiscard]] std::optional<std::uint64_t> default_integer(const ObjectEntry& entry);
// Where that default was written: the DefaultData element, else the sub-entry's Info element.
[[nodiscard]] SourcePos default_pos(const ObjectEntry& entry);

}  // namespace esi::rules
