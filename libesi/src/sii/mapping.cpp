#include "esi/sii/mapping.hpp"

#include "esi/data_types.hpp"
#include "esi/model/object_layout.hpp"
#include "esi/number.hpp"
#include "esi/sii/layout.hpp"

namespace esi::sii {

std::optional<std::uint8_t> sm_type_code(std::string_view text) {
    const std::string_view t = trim(text);
    if (t.empty()) return sm_type::unused;
    if (t == "MBoxOut") return sm_type::mailbox_out;
    if (t == "MBoxIn") return sm_type::mailbox_in;
    if (t == "Outputs" || t == "DynamicOutputs") return sm_type::outputs;
    if (t == "Inputs" || t == "DynamicInputs") return sm_type::inputs;
    return std::nullopt;
}

std::optional<std::uint8_t> fmmu_usage_code(std::string_view text) {
    const std::string_view t = trim(text);
    if (t.empty()) return fmmu_usage::unused;
    if (t == "Outputs" || t == "DynamicOutputs") return fmmu_usage::outputs;
    if (t == "Inputs" || t == "DynamicInputs") return fmmu_usage::inputs;
    if (t == "MBoxState") return fmmu_usage::sync_manager_status;
    return std::nullopt;
}

std::optional<std::uint8_t> port_code(char letter) {
    switch (letter) {
        case 'Y':
        case 'H': return port_type::mii;
        case 'K': return port_type::ebus;
        case ' ': return port_type::none;
        default: return std::nullopt;
    }
}

std::uint8_t sm_enable_byte(const SyncManager& sm) {
    auto byte = static_cast<std::uint8_t>(sm.enable.value_or(0) & 0xFFu);
    if (sm.fixed_assignment.value_or(false)) byte |= sm_enable::fixed_content;
    if (sm.is_virtual.value_or(false)) byte |= sm_enable::virtual_sm;
    if (sm.op_only.value_or(false)) byte |= sm_enable::op_only;
    return byte;
}

std::uint16_t sm_length(const SyncManager& sm) { return static_cast<std::uint16_t>(sm.default_size.value_or(0) & 0xFFFFu); }

std::uint8_t coe_details_byte(const Mailbox& mailbox) {
    if (!mailbox.coe) return 0;
    const CoeProtocol& coe = *mailbox.coe;
    std::uint8_t byte = coe_detail::sdo;
    if (coe.sdo_info.value_or(false)) byte |= coe_detail::sdo_info;
    if (coe.pdo_assign.value_or(false)) byte |= coe_detail::pdo_assign;
    if (coe.pdo_config.value_or(false)) byte |= coe_detail::pdo_configuration;
    if (coe.pdo_upload.value_or(false)) byte |= coe_detail::pdo_upload;
    if (coe.complete_access.value_or(false)) byte |= coe_detail::complete_access;
    return byte;
}

std::uint16_t pdo_flags(const Pdo& pdo) {
    std::uint16_t flags = 0;
    if (pdo.mandatory.value_or(false)) flags |= pdo_flag::mandatory;
    if (pdo.fixed.value_or(false)) flags |= pdo_flag::fixed_content;
    if (pdo.is_virtual.value_or(false)) flags |= pdo_flag::virtual_content;
    if (pdo.index_depend_on_slot.value_or(false)) flags |= pdo_flag::depend_on_slot;
    if (pdo.index_depend_on_slot_group.value_or(false)) flags |= pdo_flag::depend_on_slot_group;
    if (pdo.overwritten_by_module.value_or(false)) flags |= pdo_flag::overwritten_by_module;
    return flags;
}

namespace {

std::optional<std::uint8_t> code_of(const ResolvedType& t) {
    if (t.is_array) {
        const TypeName element = parse_type_name(t.element_type);
        if (element.kind == TypeName::Kind::basic && element.basic &&
            (element.basic->esi_name == "BYTE" || element.basic->esi_name == "USINT"))
            return 0x0A;  // OCTET_STRING
        return std::nullopt;
    }
    if (t.basic && t.basic->coe_code <= 0xFF) return static_cast<std::uint8_t>(t.basic->coe_code);
    return std::nullopt;
}

}  // namespace

std::optional<std::uint8_t> pdo_entry_data_type(const Device& device, const PdoEntry& entry) {
    if (entry.is_padding()) return std::nullopt;
    const Dictionary* dictionary = device.dictionary();
    if (entry.data_type && !trim(*entry.data_type).empty()) return code_of(resolve_type(dictionary, *entry.data_type));
    if (!dictionary) return std::nullopt;
    const Object* object = dictionary->find_object(entry.index);
    if (!object) return std::nullopt;
    const ObjectLayout layout = layout_of(dictionary, *object);
    const ObjectEntry* sub = layout.entry(entry.effective_subindex());
    if (!sub || !sub->basic || sub->basic->coe_code > 0xFF) return std::nullopt;
    return static_cast<std::uint8_t>(sub->basic->coe_code);
}

bool same_pdo_data_type(std::uint8_t esi_code, std::uint8_t image_code) {
    if (esi_code == image_code) return true;
    auto canonical = [](std::uint8_t code) -> std::uint8_t {
        switch (code) {
            case 0x1E: return 0x05;  // BYTE -> USINT
            case 0x1F: return 0x06;  // WORD -> UINT
            case 0x20: return 0x07;  // DWORD -> UDINT
            default: return code;
        }
    };
    return canonical(esi_code) == canonical(image_code);
}

bool is_legacy_op_mode(const DcOpMode& op_mode) {
    for (const auto& element : op_mode.extras.elements) {
        if (element.name != "VendorSpecific") continue;
        for (const auto& child : element.children)
            if (child.name == "TwinCAT" && child.attribute("IgnoreFromBuildNo")) return true;
    }
    return false;
}

std::optional<std::int64_t> ebus_current(const Device& device) {
    const XmlElement* e = device.extras.find("Info/Electrical/EBusCurrent");
    if (!e) return std::nullopt;
    const ParsedNumber n = parse_number(e->text);
    if (!n.ok()) return std::nullopt;
    return n.value.as_int64();
}

const SyncManager* find_sm(const Device& device, std::string_view type) {
    for (const auto& sm : device.sms)
        if (trim(sm.type) == type) return &sm;
    return nullptr;
}

}  // namespace esi::sii
