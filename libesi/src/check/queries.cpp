#include "check/queries.hpp"

#include "check/od_values.hpp"

namespace esi::rules {

std::vector<const Device*> all_devices(const EsiDocument& document) {
    std::vector<const Device*> out;
    std::size_t count = 0;
    for (const auto& info : document.infos) count += info.devices.size();
    out.reserve(count);  // most rules start with this list: one allocation for it
    for (const auto& info : document.infos)
        for (const auto& device : info.devices) out.push_back(&device);
    return out;
}

SmRole role_from_text(std::string_view text) {
    // The length and the first letter tell the four names apart, so one comparison at most: the
    // rules ask for the role of every SyncManager many times.
    if (text.size() == 6 && text[0] == 'M') return text == "MBoxIn" ? SmRole::mailbox_in : SmRole::unknown;
    if (text.size() == 6) return text == "Inputs" ? SmRole::inputs : SmRole::unknown;
    if (text.size() == 7 && text[0] == 'M') return text == "MBoxOut" ? SmRole::mailbox_out : SmRole::unknown;
    if (text.size() == 7) return text == "Outputs" ? SmRole::outputs : SmRole::unknown;
    return SmRole::unknown;
}

bool control_byte_is_mailbox(std::uint32_t control_byte) { return (control_byte & 0x03) == 0x02; }
bool control_byte_is_write(std::uint32_t control_byte) { return ((control_byte >> 2) & 0x03) == 0x01; }

SmRole sm_role(const SyncManager& sm) {
    const SmRole from_text = role_from_text(sm.type);
    if (from_text != SmRole::unknown || !sm.control_byte) return from_text;
    const bool mailbox = control_byte_is_mailbox(*sm.control_byte);
    const bool write = control_byte_is_write(*sm.control_byte);
    if (mailbox) return write ? SmRole::mailbox_out : SmRole::mailbox_in;
    return write ? SmRole::outputs : SmRole::inputs;
}

std::string_view to_string(SmRole role) {
    switch (role) {
        case SmRole::mailbox_out: return "MBoxOut";
        case SmRole::mailbox_in: return "MBoxIn";
        case SmRole::outputs: return "Outputs";
        case SmRole::inputs: return "Inputs";
        case SmRole::unknown: return "unknown";
    }
    return "unknown";
}

std::optional<std::uint64_t> default_integer(const ObjectEntry& entry) {
    if (!entry.info) return std::nullopt;
    if (entry.info->default_value) return entry.info->default_value->bits();
    if (!entry.info->default_data) return std::nullopt;
    return little_endian_pattern(*entry.info->default_data);
}

SourcePos default_pos(const ObjectEntry& entry) {
    if (!entry.info) return {};
    if (!entry.info->default_value && entry.info->default_data) return entry.info->default_data->pos;
    return entry.info->pos;
}

}  // namespace esi::rules
