// Rules of the identity area: Vendor Id, Device Type (ProductCode, RevisionNo), GroupType,
// Names, duplicate identities and the identity object 0x1018. A master finds a device's
// description by (Vendor Id, ProductCode, RevisionNo) read from the SII EEPROM (words 0x08–0x0D)
// and the conformance tool compares all three with 0x1018 (CTT TF-1300 2-1..2-3, 4-1).
//
// The file stays whole although it is about 500 lines: it is the identity family's catalogue, each
// rule's Rule constant right below its check (areas.hpp), and the "missing" rules share the
// helpers below that tell an absent attribute from a malformed one (one fault, one finding).
#include <optional>
#include <string>
#include <unordered_map>

#include "check/areas.hpp"
#include "check/queries.hpp"
#include "check/rule_cache.hpp"
#include "esi/model/language.hpp"
#include "esi/number.hpp"
#include "esi/text_distance.hpp"

namespace esi::rules {

namespace {

// Identity values are 32-bit and written in hex throughout ESI files and tools.
std::string hex32(std::uint64_t value) { return format_hex(value, 8); }

std::string device_label(const Device& device) {
    std::string label = "Device";
    if (!device.type.text.empty()) label += " '" + device.type.text + "'";
    return label;
}

// A passive terminal (Beckhoff EL9xxx end and supply terminals, EK1200 placeholders) has no ESC: no
// SyncManager, FMMU, mailbox, PDO, DC or dictionary. Configuration tools insert it by hand, and it
// has no EtherCAT identity to match, so the identity rules do not ask it for one.
bool is_passive(const Device& device) {
    return device.sms.empty() && device.fmmus.empty() && !device.mailbox && device.rx_pdos.empty() &&
           device.tx_pdos.empty() && !device.dc && device.profiles.empty();
}

// Byte offsets of element positions, for positions that arrive in document order. Columns count
// code points, so reaching one means walking its line; keeping the walk's place makes a whole pass
// linear even for a single-line multi-megabyte file.
class OffsetCursor {
public:
    explicit OffsetCursor(const SourceText& source) : source_(source) {}

    std::optional<std::size_t> offset_of(SourcePos pos) {
        if (!pos.known() || pos.line > source_.line_count()) return std::nullopt;
        if (pos.line != line_ || pos.column < column_) {
            line_ = pos.line;
            column_ = 1;
            offset_ = source_.line_start(pos.line);
        }
        const std::string_view text = source_.text();
        while (column_ < pos.column && offset_ < text.size()) {
            ++offset_;
            while (offset_ < text.size() && (static_cast<unsigned char>(text[offset_]) & 0xC0) == 0x80) ++offset_;
            ++column_;
        }
        return offset_;
    }

private:
    const SourceText& source_;
    std::uint32_t line_ = 0;
    std::uint32_t column_ = 1;
    std::size_t offset_ = 0;
};

// Whether the start tag at `offset` spells the attribute `name`. The reader drops an attribute whose
// value it cannot parse (and reports xml-number-format there); this lets the "missing" rules stay
// silent for a value that is present but malformed, so one fault gives one finding.
bool start_tag_has_attribute(std::string_view text, std::size_t at, std::string_view name) {
    if (at >= text.size() || text[at] != '<') return false;
    char quote = 0;
    for (std::size_t i = at + 1; i < text.size(); ++i) {
        const char c = text[i];
        if (quote) {
            if (c == quote) quote = 0;
            continue;
        }
        if (c == '"' || c == '\'') quote = c;
        else if (c == '>') return false;
        else if ((c == ' ' || c == '\t' || c == '\n' || c == '\r') && text.compare(i + 1, name.size(), name) == 0) {
            std::size_t j = i + 1 + name.size();
            while (j < text.size() && (text[j] == ' ' || text[j] == '\t' || text[j] == '\n' || text[j] == '\r')) ++j;
            if (j < text.size() && text[j] == '=') return true;
        }
    }
    return false;
}

// Type elements of devices that lack `attribute` (absent, not merely malformed), in document order.
template <class F>
void for_each_type_without(const EsiDocument& document, RuleContext& context, std::string_view attribute,
                           std::optional<std::uint32_t> DeviceIdentity::*field, F&& f) {
    std::optional<OffsetCursor> cursor;
    if (document.source) cursor.emplace(*document.source);
    for (const Device* device : context.cache().devices(document)) {
        if (!device->type.pos.known() || device->type.*field || is_passive(*device)) continue;
        if (cursor) {
            const std::optional<std::size_t> at = cursor->offset_of(device->type.pos);
            if (at && start_tag_has_attribute(document.source->text(), *at, attribute)) continue;  // xml-number-format
        }
        f(*device);
    }
}

bool has_name(const Names& names) {
    for (const auto& n : names)
        if (!n.text.empty()) return true;
    return false;
}

// ---- identity-vendor-id-missing -------------------------------------------------------------

void check_vendor_id_missing(const EsiDocument& document, RuleContext& context) {
    for (const auto& info : document.infos) {
        if (!info.vendor) {
            context.report(info.pos, "EtherCATInfo has no Vendor element; the vendor id identifies every device in the file");
        } else if (!info.vendor->id_pos.known()) {
            context.report(info.vendor->pos, "Vendor has no Id; masters match devices by vendor id, product code and revision");
        }
    }
}

constexpr Rule identity_vendor_id_missing{
    .id = "identity-vendor-id-missing",
    .default_severity = Severity::error,
    .summary = "The file has no Vendor or the Vendor has no Id",
    .rationale =
        "Every device is identified by the triple (Vendor Id, ProductCode, RevisionNo): the master reads it from SII "
        "words 0x08-0x0D and looks for the matching description. Without Vendor/Id no device of the file can be "
        "matched, and the SII words 0x08-0x09 cannot be generated (ETG.2000 VendorType: Id is required; ETG.2010 "
        "SII header; CTT TF-1300 2-1).",
    .bad_example = "<Vendor><Name>Example GmbH</Name></Vendor>",
    .good_example = "<Vendor><Id>#x00000E4A</Id><Name>Example GmbH</Name></Vendor>",
    .check = check_vendor_id_missing,
};

// ---- identity-vendor-id-zero ----------------------------------------------------------------

void check_vendor_id_zero(const EsiDocument& document, RuleContext& context) {
    for (const auto& info : document.infos) {
        if (info.vendor && info.vendor->id && *info.vendor->id == 0)
            context.report(info.vendor->id_pos,
                           "Vendor Id is 0, which is not an ETG-assigned vendor id; devices of every vendor that "
                           "leaves it at 0 look alike to a master");
    }
}

constexpr Rule identity_vendor_id_zero{
    .id = "identity-vendor-id-zero",
    .default_severity = Severity::warning,
    .summary = "Vendor Id 0 is not an assigned vendor id",
    .rationale =
        "Vendor ids are assigned by the EtherCAT Technology Group (1 is the ETG itself, 2 Beckhoff); 0 is not "
        "assigned to anybody. Generator templates and prototypes ship with 0 (the default project of "
        "kubabuda/EEPROM_generator, ref/gen.xml), and then every such device looks alike to a master that selects "
        "descriptions by (Vendor Id, ProductCode, RevisionNo) (ETG.2000 VendorType Id; ETG.2010 SII words 0x08-0x09).",
    .bad_example = "<Vendor><Id>0</Id><Name>Prototype</Name></Vendor>",
    .good_example = "<Vendor><Id>#x00000E4A</Id><Name>Example GmbH</Name></Vendor>",
    .check = check_vendor_id_zero,
};

// ---- identity-product-code-missing ----------------------------------------------------------

void check_product_code_missing(const EsiDocument& document, RuleContext& context) {
    for_each_type_without(document, context, "ProductCode", &DeviceIdentity::product_code, [&](const Device& device) {
        context.report(device.type.pos, device_label(device) +
                                            " has no ProductCode; masters identify the device by the product code in "
                                            "SII words 0x0A-0x0B and cannot match this description");
    });
}

constexpr Rule identity_product_code_missing{
    .id = "identity-product-code-missing",
    .default_severity = Severity::error,
    .summary = "Device Type without ProductCode",
    .rationale =
        "The product code goes into SII words 0x0A-0x0B and 0x1018:02, and masters select the device description by "
        "it (ETG.2000 Device/Type; ETG.2010 SII header; CTT TF-1300 2-2). The schema leaves the attribute optional, "
        "but a description without it cannot be matched to any device on the bus. Passive "
        "terminals without an ESC (no Sm, Fmmu, Mailbox, PDO, Dc or Profile, such as Beckhoff's EL9xxx end "
        "terminals) are exempt: they have no identity to read.",
    .bad_example = "<Type RevisionNo=\"#x00010000\">EX-DIO-8</Type>",
    .good_example = "<Type ProductCode=\"#x00001001\" RevisionNo=\"#x00010000\">EX-DIO-8</Type>",
    .check = check_product_code_missing,
};

// ---- identity-revision-missing --------------------------------------------------------------

void check_revision_missing(const EsiDocument& document, RuleContext& context) {
    for_each_type_without(document, context, "RevisionNo", &DeviceIdentity::revision_no, [&](const Device& device) {
        context.report(device.type.pos, device_label(device) +
                                            " has no RevisionNo; masters check the revision in SII words 0x0C-0x0D "
                                            "against it (CheckRevisionNo) and the conformance tool requires it");
    });
}

constexpr Rule identity_revision_missing{
    .id = "identity-revision-missing",
    .default_severity = Severity::error,
    .summary = "Device Type without RevisionNo",
    .rationale =
        "The revision number goes into SII words 0x0C-0x0D and 0x1018:03; masters compare it with the description "
        "(Type@CheckRevisionNo) and the conformance tool checks it (ETG.2000 Device/Type; CTT TF-1300 1-2, 2-3). "
        "Several revisions of one product usually live in one file, so a missing revision makes them "
        "indistinguishable. Passive terminals without an ESC are exempt, as for identity-product-code-missing.",
    .bad_example = "<Type ProductCode=\"#x00001001\">EX-DIO-8</Type>",
    .good_example = "<Type ProductCode=\"#x00001001\" RevisionNo=\"#x00010000\">EX-DIO-8</Type>",
    .check = check_revision_missing,
};

// ---- identity-group-type-unresolved, identity-group-type-missing ----------------------------

// Suggestions cost an edit distance per group; real files have a few dozen groups, and a hostile
// file with thousands of unresolved references must not turn the check quadratic.
constexpr std::size_t max_suggestion_candidates = 256;

void check_group_type(const EsiDocument& document, RuleContext& context) {
    for (const auto& info : document.infos) {
        std::vector<std::string_view> group_types;
        group_types.reserve(info.groups.size());
        for (const auto& g : info.groups) group_types.push_back(g.type);
        for (const auto& device : info.devices) {
            if (!device.group_type || info.find_group(*device.group_type)) continue;
            std::string message = device_label(device) + ": GroupType '" + *device.group_type + "' names no Group in this file";
            if (info.groups.empty()) {
                message += " (the file declares no Groups)";
            } else if (group_types.size() <= max_suggestion_candidates) {
                const std::string suggestion = closest_match(*device.group_type, group_types);
                if (!suggestion.empty()) message += "; did you mean '" + suggestion + "'?";
            }
            context.report(device.group_type_pos.known() ? device.group_type_pos : device.pos, std::move(message));
        }
    }
}

constexpr Rule identity_group_type_unresolved{
    .id = "identity-group-type-unresolved",
    .default_severity = Severity::warning,
    .summary = "Device GroupType naming no Group of the file",
    .rationale =
        "Device/GroupType refers to Descriptions/Groups/Group/Type; configuration tools sort the device into that "
        "group and take the group's name and image from it (ETG.2000 DeviceType; SOES doc/tutorial.txt: 'Reference "
        "to a group ... Groups:Group:Type'; CTT TF-1300 1-8). The schema declares no key/keyref for it, so only a "
        "semantic check finds a misspelt group. Only the device tree of a configuration tool is affected: the SII "
        "group string is the GroupType text either way, and no master uses it to configure the device (Synapticon's "
        "SOMANET files keep the GroupType ETG2001ModulesSlots of the ETG example they were made from). A warning; a "
        "missing GroupType is identity-group-type-missing.",
    .bad_example = "<Group><Type>DigitalIO</Type>...</Group> ... <GroupType>DigitalIo</GroupType>",
    .good_example = "<Group><Type>DigitalIO</Type>...</Group> ... <GroupType>DigitalIO</GroupType>",
    .check = check_group_type,
};

void check_group_type_missing(const EsiDocument& document, RuleContext& context) {
    for (const auto& info : document.infos)
        for (const auto& device : info.devices)
            if (!device.group_type)
                context.report(device.pos, device_label(device) + " has no GroupType; it must name a Groups/Group/Type of this file");
}

constexpr Rule identity_group_type_missing{
    .id = "identity-group-type-missing",
    .default_severity = Severity::error,
    .summary = "Device without GroupType",
    .rationale =
        "Device/GroupType is a required element of the ETG schema (EtherCATInfo.xsd DeviceType: GroupType without "
        "minOccurs=\"0\"), checked by the conformance tool (CTT TF-1300 1-8 'Device:GroupType'); the SII builder "
        "takes the SII group string from it (ETG.2010 General category). Files dumped from a live device by the "
        "IgH master's `ethercat xml` command lack it. A value the schema does not allow: an error.",
    .bad_example = "<Device Physics=\"YY\"><Type …>EX-DIO-8</Type><Name>EX-DIO-8</Name><Sm …",
    .good_example = "<Device Physics=\"YY\"><Type …>EX-DIO-8</Type><Name>EX-DIO-8</Name><GroupType>DigitalIO</GroupType><Sm …",
    .check = check_group_type_missing,
};

// ---- identity-name-missing ------------------------------------------------------------------

void check_name_missing(const EsiDocument& document, RuleContext& context) {
    for (const auto& info : document.infos) {
        if (info.vendor && !has_name(info.vendor->names))
            context.report(info.vendor->pos, "Vendor has no Name; configuration tools show it in their device catalogue");
        for (const auto& group : info.groups)
            if (!has_name(group.names))
                context.report(group.pos, "Group '" + group.type + "' has no Name; configuration tools show it as the catalogue folder");
        for (const auto& device : info.devices)
            if (!has_name(device.names))
                context.report(device.pos, device_label(device) +
                                               " has no Name; the device name goes into the SII strings and the "
                                               "conformance tool checks it (CTT TF-1300 1-6)");
    }
}

constexpr Rule identity_name_missing{
    .id = "identity-name-missing",
    .default_severity = Severity::error,
    .summary = "Vendor, Group or Device without a Name",
    .rationale =
        "Names are what users see in the device catalogue and what goes into the SII strings category (device name "
        "and group name indices of the General category, ETG.2010). The schema requires at least one Name for each "
        "of Vendor, Group and Device, and the conformance tool checks the device name (ETG.2000 VendorType, "
        "GroupType, DeviceType; CTT TF-1300 1-6). An empty Name element counts as missing.",
    .bad_example =
        "<Device Physics=\"YY\"><Type ProductCode=\"#x1001\" RevisionNo=\"1\">EX-DIO-8</Type><GroupType>DigitalIO</GroupType>",
    .good_example =
        "<Device Physics=\"YY\"><Type ProductCode=\"#x1001\" RevisionNo=\"1\">EX-DIO-8</Type><Name LcId=\"1033\">EX-DIO-8 "
        "8 inputs</Name><GroupType>DigitalIO</GroupType>",
    .check = check_name_missing,
};

// ---- identity-duplicate ---------------------------------------------------------------------

void check_duplicate(const EsiDocument& document, RuleContext& context) {
    // Per EtherCATInfo: an EtherCATInfoList (IgH bus dump) lists one info per slave on the bus, and
    // two identical terminals there are not a fault.
    for (const auto& info : document.infos) {
        std::unordered_map<std::uint64_t, const Device*> seen;
        seen.reserve(info.devices.size());
        for (const auto& device : info.devices) {
            if (!device.type.product_code || !device.type.revision_no) continue;
            const std::uint64_t key = (std::uint64_t{*device.type.product_code} << 32) | *device.type.revision_no;
            const auto [it, inserted] = seen.emplace(key, &device);
            if (inserted) continue;
            context.report(device.type.pos,
                           device_label(device) + " repeats ProductCode " + hex32(*device.type.product_code) + " RevisionNo " +
                               hex32(*device.type.revision_no) + " of " + device_label(*it->second) +
                               "; a master cannot tell which description applies",
                           {context.note(it->second->type.pos, "first defined here")});
        }
    }
}

constexpr Rule identity_duplicate{
    .id = "identity-duplicate",
    .default_severity = Severity::error,
    .summary = "Two devices of one file with the same ProductCode and RevisionNo",
    .rationale =
        "A master picks the description whose (ProductCode, RevisionNo) matches the SII; with two candidates it takes "
        "one of them, and which one differs between tools. Each variant needs its own identity (ETG.2010 SII words "
        "0x0A-0x0D hold exactly ProductCode and RevisionNo; leducp/KickCAT PR #386/#426 select the device in a "
        "multi-device file by product code and revision).",
    .bad_example =
        "<Type ProductCode=\"#x1001\" RevisionNo=\"#x10000\">EX-DIO-8</Type> ... <Type ProductCode=\"#x1001\" "
        "RevisionNo=\"#x10000\">EX-DIO-8-HD</Type>",
    .good_example =
        "<Type ProductCode=\"#x1001\" RevisionNo=\"#x10000\">EX-DIO-8</Type> ... <Type ProductCode=\"#x1002\" "
        "RevisionNo=\"#x10000\">EX-DIO-8-HD</Type>",
    .check = check_duplicate,
};

// ---- identity-1018-mismatch -----------------------------------------------------------------

// Sub-indices 1 and 2 name the device (vendor, product); sub-index 3 only its revision. A
// revision default left at an older revision is the common case in large catalogues (a
// dictionary shared across revisions; the firmware reports the real value at run time), so it
// is a rule of its own with a lower severity than a foreign vendor id or product code.
enum class IdentityPart { device, revision };

void check_1018(const EsiDocument& document, RuleContext& context, IdentityPart part) {
    for (const auto& info : document.infos) {
        const std::optional<std::uint32_t> vendor_id = info.vendor ? info.vendor->id : std::nullopt;
        for (const auto& device : info.devices) {
            const Dictionary* dictionary = device.dictionary();
            if (!dictionary) continue;
            const Object* identity = dictionary->find_object(0x1018);
            if (!identity) continue;
            const ObjectLayout& layout = context.cache().objects(dictionary).layout(*identity);
            struct Expected {
                std::uint32_t subindex;
                std::optional<std::uint32_t> value;
                const char* what;
                SourcePos where;
            };
            const Expected expected[] = {
                {1, vendor_id, "Vendor/Id", info.vendor ? info.vendor->id_pos : SourcePos{}},
                {2, device.type.product_code, "Type@ProductCode", device.type.pos},
                {3, device.type.revision_no, "Type@RevisionNo", device.type.pos},
            };
            for (const auto& e : expected) {
                if (!e.value || (e.subindex == 3) != (part == IdentityPart::revision)) continue;
                const ObjectEntry* entry = layout.entry(e.subindex);
                if (!entry || entry->bit_size > 32) continue;
                const std::optional<std::uint64_t> value = default_integer(*entry);
                if (!value || *value == *e.value) continue;
                const SourcePos at = default_pos(*entry).known() ? default_pos(*entry) : identity->pos;
                context.report(at,
                               device_label(device) + ": 0x1018:0" + std::to_string(e.subindex) + " (" + entry->name +
                                   ") defaults to " + hex32(*value) + " but " + e.what + " is " + hex32(*e.value) +
                                   (part == IdentityPart::revision
                                        ? "; a master or the conformance tool that compares the identity object with the "
                                          "description reports a mismatch"
                                        : std::string(*value == 0 ? " (a placeholder left 0)" : "") +
                                              "; the identity object must repeat the description's identity (masters identify "
                                              "the device by its SII, and the conformance tool warns)"),
                               {context.note(e.where, std::string(e.what) + " is written here")});
            }
        }
    }
}

void check_1018_device(const EsiDocument& document, RuleContext& context) { check_1018(document, context, IdentityPart::device); }

constexpr Rule identity_1018_mismatch{
    .id = "identity-1018-mismatch",
    .default_severity = Severity::warning,
    .summary = "0x1018 vendor id or product code defaults disagree with Vendor/Id or Device/Type",
    .rationale =
        "The identity object 0x1018 (sub 1 vendor id, 2 product code, 3 revision) must report the same identity as "
        "the description and the SII; the conformance tool compares them (CTT TF-1300 4-1 'ESI OD Identity Info', "
        "graded a warning in the CTT report posted in leducp/KickCAT#189; TF-2301 0x1018). Defaults are read from "
        "DefaultValue or from DefaultData, which holds the bytes little-endian (\"02000000\" is 2). A copied "
        "dictionary that still carries the template's product code, a vendor id written in the wrong byte order, or "
        "a default left 0 are the usual causes (ETG sample ModulesSlots_CiA402; generator templates). A warning, not "
        "an error: no master reads these offline defaults. Masters match a device by the identity in its SII against "
        "the description's Vendor/Id and Type (IgH EtherCAT master ec_slave_config_attach() compares "
        "slave->sii.vendor_id and product_code; SOEM reads the SII), and the device reports its own 0x1018 online. A "
        "stale revision is identity-1018-revision-stale.",
    .bad_example =
        "<Type ProductCode=\"#x1001\" ...> ... <SubItem><Name>Product code</Name><Info><DefaultData>02100000</DefaultData>",
    .good_example =
        "<Type ProductCode=\"#x1001\" ...> ... <SubItem><Name>Product code</Name><Info><DefaultData>01100000</DefaultData>",
    .check = check_1018_device,
};

// ---- identity-1018-revision-stale -----------------------------------------------------------

void check_1018_revision(const EsiDocument& document, RuleContext& context) {
    check_1018(document, context, IdentityPart::revision);
}

constexpr Rule identity_1018_revision_stale{
    .id = "identity-1018-revision-stale",
    .default_severity = Severity::warning,
    .summary = "0x1018:03 revision default differs from Device/Type@RevisionNo",
    .rationale =
        "0x1018:03 reports the revision the firmware runs; its default in the description should be the RevisionNo of "
        "the Type it belongs to (CTT TF-1300 4-1 compares them). Catalogues that share one dictionary across "
        "revisions often keep an older revision here: the master still matches the device by SII and Type, so this is "
        "a warning, unlike a wrong vendor id or product code (identity-1018-mismatch). Beckhoff's own catalogues do "
        "this for about 60 terminals (e.g. Beckhoff EL3xxx.xml and EL66xx.xml in DiamondLightSource/ethercat "
        "etc/xml/).",
    .bad_example =
        "<Type ProductCode=\"#x1001\" RevisionNo=\"#x10000\"> ... <SubItem><Name>Revision</Name><Info><DefaultValue>#x00020000</DefaultValue>",
    .good_example =
        "<Type ProductCode=\"#x1001\" RevisionNo=\"#x10000\"> ... <SubItem><Name>Revision</Name><Info><DefaultValue>#x00010000</DefaultValue>",
    .check = check_1018_revision,
};

// ---- identity-name-lcid-duplicate -----------------------------------------------------------

void check_names_lcid(const Names& names, std::string_view owner, RuleContext& context) {
    if (names.size() < 2) return;
    // Names are few (one per language); a quadratic look is linear in practice.
    for (std::size_t i = 1; i < names.size(); ++i) {
        const std::uint32_t lcid = names[i].lcid.value_or(default_lcid);
        for (std::size_t j = 0; j < i; ++j) {
            if (names[j].lcid.value_or(default_lcid) != lcid) continue;
            context.report(names[i].pos,
                           std::string(owner) + " has a second Name for LcId " + std::to_string(lcid) +
                               (names[i].lcid ? "" : " (a Name without LcId means 1033)") + ": '" + names[i].text +
                               "' after '" + names[j].text + "'; tools keep one of them at random",
                           {context.note(names[j].pos, "first Name for this LcId")});
            break;
        }
    }
}

void check_name_lcid_duplicate(const EsiDocument& document, RuleContext& context) {
    for (const auto& info : document.infos) {
        if (info.vendor) check_names_lcid(info.vendor->names, "Vendor", context);
        for (const auto& group : info.groups) check_names_lcid(group.names, "Group '" + group.type + "'", context);
        for (const auto& device : info.devices) {
            check_names_lcid(device.names, device_label(device), context);
            if (device.slots)
                for (const auto& slot : device.slots->slots) check_names_lcid(slot.names, "Slot", context);
        }
        for (const auto& module : info.modules) check_names_lcid(module.names, "Module '" + module.type + "'", context);
    }
}

constexpr Rule identity_name_lcid_duplicate{
    .id = "identity-name-lcid-duplicate",
    .default_severity = Severity::warning,
    .summary = "Two Names with the same LcId on one element",
    .rationale =
        "Names are localized by LcId (default 1033, English); a tool shows one Name per language, so a second Name "
        "with the same LcId is dropped or overrides the first depending on the tool, and SII writers emit only one "
        "(ETG.2000 NameType; ethercat-rs/ethercat-esi #1 broke on repeated Name elements).",
    .bad_example = "<Name LcId=\"1033\">EX-DIO-8</Name><Name>EX-DIO-8 8 inputs</Name>",
    .good_example = "<Name LcId=\"1033\">EX-DIO-8</Name><Name LcId=\"1031\">EX-DIO-8 8 Eingänge</Name>",
    .check = check_name_lcid_duplicate,
};

}  // namespace

void add_identity(std::vector<Rule>& out) {
    out.insert(out.end(), {
        identity_vendor_id_missing,
        identity_vendor_id_zero,
        identity_product_code_missing,
        identity_revision_missing,
        identity_group_type_unresolved,
        identity_group_type_missing,
        identity_name_missing,
        identity_duplicate,
        identity_1018_mismatch,
        identity_1018_revision_stale,
        identity_name_lcid_duplicate,
    });
}

}  // namespace esi::rules
