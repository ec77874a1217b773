// Rules of the deprecated area: elements and attributes the ETG schema marks "obsolete". The
// conformance tool reports the first of them as test group 5 of TF-1300 (5-1 Vendor:Image16x14,
// 5-2 Vendor@UniqueName, 5-3 Group:Image16x14, 5-4 Device:Image16x14, 5-5 Type@TcCfgModeSafeOp,
// 5-6 Profile@Channel, 5-7 Fmmu@OpOnly, 5-8 Sm@OneByteMode, as posted in leducp/KickCAT PR #181);
// those get a rule each so that a project can keep one while removing the others. Everything
// else the schema 1.17 annotates as obsolete is reported, as information, by deprecated-obsolete.
#include <string>

#include "check/areas.hpp"
#include "check/rule_cache.hpp"
#include "check/queries.hpp"
#include "check/source_edit.hpp"

namespace esi::rules {

namespace {

std::string device_label(const Device& device) {
    return device.type.text.empty() ? std::string("Device") : "Device '" + device.type.text + "'";
}

// ---- deprecated-image16x14 ------------------------------------------------------------------

void report_image(const Images& images, const std::string& owner, SourcePos fallback, RuleContext& context) {
    if (!images.image16x14) return;
    const bool has_replacement = images.image_data16x14 || images.image_file16x14;
    context.report(images.image16x14_pos.known() ? images.image16x14_pos : fallback,
                   owner + " uses Image16x14 ('" + *images.image16x14 + "'), which is obsolete; " +
                       (has_replacement ? "it already has ImageData16x14/ImageFile16x14, so remove Image16x14"
                                        : "embed the bitmap as ImageData16x14 (hex) instead"));
}

void check_image(const EsiDocument& document, RuleContext& context) {
    for (const auto& info : document.infos) {
        if (info.vendor) report_image(info.vendor->images, "Vendor", info.vendor->pos, context);
        for (const auto& group : info.groups) report_image(group.images, "Group '" + group.type + "'", group.pos, context);
        for (const auto& device : info.devices) {
            report_image(device.images, device_label(device), device.pos, context);
            if (device.slots)
                for (const auto& slot : device.slots->slots) report_image(slot.images, "Slot", slot.pos, context);
        }
        for (const auto& module : info.modules) report_image(module.images, "Module '" + module.type + "'", module.pos, context);
    }
}

constexpr Rule deprecated_image16x14{
    .id = "deprecated-image16x14",
    .default_severity = Severity::warning,
    .summary = "Image16x14 on Vendor, Group, Device, Module or Slot",
    .rationale =
        "Image16x14 referred to a bitmap file by name; the schema marks it obsolete and the conformance tool reports "
        "it (CTT TF-1300 5-1 Vendor:Image16x14, 5-3 Group:Image16x14, 5-4 Device:Image16x14; ETG.2000 schema 1.17 "
        "'obsolete'). Tools ignore it; the icon belongs in ImageData16x14 (the bitmap as hex) or ImageFile16x14.",
    .bad_example = "<Group><Type>DigitalIO</Type><Name>Digital I/O</Name><Image16x14>DIO</Image16x14></Group>",
    .good_example =
        "<Group><Type>DigitalIO</Type><Name>Digital I/O</Name><ImageData16x14>424D...</ImageData16x14></Group>",
    .check = check_image,
};

// ---- deprecated-vendor-unique-name ----------------------------------------------------------

void check_unique_name(const EsiDocument& document, RuleContext& context) {
    for (const auto& info : document.infos)
        if (info.vendor && info.vendor->unique_name)
            context.report(info.vendor->pos,
                           "Vendor@UniqueName ('" + *info.vendor->unique_name + "') is obsolete; the vendor is identified by Vendor/Id",
                           remove_attribute(document, info.vendor->pos, "UniqueName", "remove Vendor@UniqueName"));
}

constexpr Rule deprecated_vendor_unique_name{
    .id = "deprecated-vendor-unique-name",
    .default_severity = Severity::warning,
    .summary = "Vendor@UniqueName",
    .rationale =
        "UniqueName is obsolete in the schema and reported by the conformance tool (CTT TF-1300 5-2 "
        "'Vendor@UniqueName'; ETG.2000 schema 1.17). A vendor is identified by its ETG vendor id.",
    .bad_example = "<Vendor UniqueName=\"ExampleGmbH\"><Id>#x00000E4A</Id>...</Vendor>",
    .good_example = "<Vendor><Id>#x00000E4A</Id>...</Vendor>",
    .check = check_unique_name,
    .fix = "removes the attribute (no tool reads it; the vendor is its Id)",
};

// ---- deprecated-tc-cfg-mode-safe-op ---------------------------------------------------------

void check_tc_cfg_mode_safe_op(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document))
        if (device->type.tc_cfg_mode_safe_op)
            context.report(device->type.pos,
                           device_label(*device) +
                               ": Type@TcCfgModeSafeOp is obsolete (a TwinCAT configuration hint that the schema no longer "
                               "defines); remove it",
                           remove_attribute(document, device->type.pos, "TcCfgModeSafeOp", "remove Type@TcCfgModeSafeOp"));
}

constexpr Rule deprecated_tc_cfg_mode_safe_op{
    .id = "deprecated-tc-cfg-mode-safe-op",
    .default_severity = Severity::warning,
    .summary = "Device Type@TcCfgModeSafeOp",
    .rationale =
        "TcCfgModeSafeOp was a TwinCAT-specific hint on Device/Type; the schema marks it obsolete and the conformance "
        "tool reports it (CTT TF-1300 5-5 'Device:Type@TcCfgModeSafeOp'; ETG.2000 schema 1.17).",
    .bad_example = "<Type ProductCode=\"#x1001\" RevisionNo=\"#x10000\" TcCfgModeSafeOp=\"true\">EX-DIO-8</Type>",
    .good_example = "<Type ProductCode=\"#x1001\" RevisionNo=\"#x10000\">EX-DIO-8</Type>",
    .check = check_tc_cfg_mode_safe_op,
    .fix = "removes the attribute",
};

// ---- deprecated-profile-channel -------------------------------------------------------------

void check_profile_channel(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document))
        for (const auto& profile : device->profiles)
            if (profile.channel)
                context.report(profile.pos, device_label(*device) + ": Profile@Channel (" + std::to_string(*profile.channel) +
                                                ") is obsolete; describe channels with ChannelCount/ChannelInfo");
}

constexpr Rule deprecated_profile_channel{
    .id = "deprecated-profile-channel",
    .default_severity = Severity::warning,
    .summary = "Device Profile@Channel",
    .rationale =
        "Profile@Channel is obsolete and reported by the conformance tool (CTT TF-1300 5-6 'Device:Profile@Channel'; "
        "ETG.2000 schema 1.17); multi-channel profiles are described with ChannelCount and ChannelInfo.",
    .bad_example = "<Profile Channel=\"1\"><ProfileNo>402</ProfileNo>...</Profile>",
    .good_example = "<Profile><ProfileNo>402</ProfileNo>...</Profile>",
    .check = check_profile_channel,
};

// ---- deprecated-fmmu-op-only ----------------------------------------------------------------

void check_fmmu_op_only(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document))
        for (std::size_t n = 0; n < device->fmmus.size(); ++n)
            if (device->fmmus[n].op_only)
                context.report(device->fmmus[n].pos, "FMMU" + std::to_string(n) + " '" + device->fmmus[n].type +
                                                         "': Fmmu@OpOnly is obsolete; the OP-only behaviour belongs to the "
                                                         "SyncManager (Sm@OpOnly)");
}

constexpr Rule deprecated_fmmu_op_only{
    .id = "deprecated-fmmu-op-only",
    .default_severity = Severity::warning,
    .summary = "Fmmu@OpOnly",
    .rationale =
        "Fmmu@OpOnly is obsolete and reported by the conformance tool (CTT TF-1300 5-7 'Device:Fmmu@OpOnly'; ETG.2000 "
        "schema 1.17); enabling outputs only in OP is declared on the SyncManager (Sm@OpOnly), which the SII "
        "SyncM category carries (enable byte bit 3).",
    .bad_example = "<Fmmu OpOnly=\"true\">Outputs</Fmmu>",
    .good_example = "<Fmmu>Outputs</Fmmu> ... <Sm ... OpOnly=\"true\">Outputs</Sm>",
    .check = check_fmmu_op_only,
};

// ---- deprecated-sm-one-byte-mode ------------------------------------------------------------

void check_sm_one_byte_mode(const EsiDocument& document, RuleContext& context) {
    for (const Device* device : context.cache().devices(document))
        for (std::size_t n = 0; n < device->sms.size(); ++n)
            if (device->sms[n].one_byte_mode)
                context.report(device->sms[n].pos, "SM" + std::to_string(n) + ": Sm@OneByteMode is obsolete; remove it",
                               remove_attribute(document, device->sms[n].pos, "OneByteMode", "remove Sm@OneByteMode"));
}

constexpr Rule deprecated_sm_one_byte_mode{
    .id = "deprecated-sm-one-byte-mode",
    .default_severity = Severity::warning,
    .summary = "Sm@OneByteMode",
    .rationale =
        "Sm@OneByteMode is obsolete and reported by the conformance tool (CTT TF-1300 5-8 'Device:Sm@OneByteMode'; "
        "ETG.2000 schema 1.17).",
    .bad_example =
        "<Sm StartAddress=\"#x1000\" ControlByte=\"#x26\" DefaultSize=\"128\" Enable=\"1\" OneByteMode=\"false\">MBoxOut</Sm>",
    .good_example = "<Sm StartAddress=\"#x1000\" ControlByte=\"#x26\" DefaultSize=\"128\" Enable=\"1\">MBoxOut</Sm>",
    .check = check_sm_one_byte_mode,
    .fix = "removes the attribute",
};

// ---- deprecated-obsolete --------------------------------------------------------------------

// `removable`: the attribute of that name on the element at `pos` is one no tool reads and that
// carries nothing another element must take over, so removing it is a safe fix.
void report_obsolete(RuleContext& context, SourcePos pos, const std::string& what, std::string_view advice,
                     std::string_view removable = {}) {
    std::optional<Fix> fix;
    if (!removable.empty())
        fix = remove_attribute(context.document(), pos, removable, "remove the obsolete attribute " + std::string(removable));
    context.report(pos, what + " is marked obsolete in the ETG schema; " + std::string(advice), std::move(fix));
}

void check_coe_obsolete(const CoeProtocol& coe, const std::string& owner, RuleContext& context) {
    if (coe.ds402_channels)
        report_obsolete(context, coe.pos, owner + ": CoE@DS402Channels",
                        "the number of CiA 402 axes is described by the Profile (ProfileNo 402, ChannelCount)");
    for (const auto& e : coe.extras.elements)
        if (e.name == "Object")
            report_obsolete(context, e.pos, owner + ": CoE/Object", "write start-up values as CoE InitCmd elements");
    for (const auto& cmd : coe.init_cmds)
        if (cmd.fixed) report_obsolete(context, cmd.pos, owner + ": InitCmd@Fixed", "remove it", "Fixed");
}

void check_obsolete(const EsiDocument& document, RuleContext& context) {
    for (const auto& info : document.infos) {
        for (const auto& device : info.devices) {
            const std::string owner = device_label(device);
            for (const char* attribute : {"TcSmClass", "DownloadModuleList"})
                if (device.type.extras.attribute(attribute))
                    report_obsolete(context, device.type.pos, owner + ": Type@" + attribute, "remove it", attribute);
            for (std::size_t n = 0; n < device.sms.size(); ++n) {
                const SyncManager& sm = device.sms[n];
                if (sm.watchdog)
                    report_obsolete(context, sm.pos, "SM" + std::to_string(n) + ": Sm@Watchdog",
                                    *sm.watchdog ? "set the watchdog trigger with ControlByte bit 6 (#x64 instead of #x24)"
                                                 : "remove it; ControlByte bit 6 alone decides the watchdog trigger",
                                    *sm.watchdog ? "" : "Watchdog");
                if (sm.fixed_assignment)
                    report_obsolete(context, sm.pos, "SM" + std::to_string(n) + ": Sm@FixedAssignment", "remove it", "FixedAssignment");
            }
            if (device.mailbox && device.mailbox->coe) check_coe_obsolete(*device.mailbox->coe, owner, context);
            if (device.dc) {
                for (const auto& mode : device.dc->op_modes)
                    for (const auto& e : mode.extras.elements) {
                        if (e.name != "Sm") continue;
                        for (const auto& child : e.children)
                            if (child.name == "SyncType" || child.name == "CycleTime" || child.name == "ShiftTime")
                                report_obsolete(context, child.pos, owner + ": Dc/OpMode/Sm/" + child.name,
                                                "SM synchronisation is set through 0x1C32/0x1C33 and the OpMode's "
                                                "cycle and shift times");
                    }
            }
        }
        for (const auto& module : info.modules)
            if (module.mailbox && module.mailbox->coe)
                check_coe_obsolete(*module.mailbox->coe, "Module '" + module.type + "'", context);
    }
}

constexpr Rule deprecated_obsolete{
    .id = "deprecated-obsolete",
    .default_severity = Severity::info,
    .summary = "Other elements and attributes the schema marks obsolete",
    .rationale =
        "Schema 1.17 annotates further items as 'obsolete' that the published CTT TF-1300 group 5 list does not name "
        "(the posted list is truncated after 5-10): Type@TcSmClass, Type@DownloadModuleList, Sm@Watchdog (use "
        "ControlByte bit 6), Sm@FixedAssignment, CoE@DS402Channels (seen in the §7 example of the item C series and "
        "Afag SE-Power EtherCAT manuals), CoE/Object, CoE InitCmd@Fixed and Dc/OpMode/Sm/SyncType, CycleTime, "
        "ShiftTime. Tools ignore them; reported as information so that a file can be cleaned up before the next "
        "schema drops them.",
    .bad_example = "<CoE DS402Channels=\"1\" PdoAssign=\"true\"/>",
    .good_example = "<CoE PdoAssign=\"true\"/>",
    .check = check_obsolete,
    .fix = "removes Type@TcSmClass, Type@DownloadModuleList, Sm@FixedAssignment, Sm@Watchdog=\"false\" and InitCmd@Fixed "
           "(the other items carry something to move elsewhere)",
};

}  // namespace

void add_deprecated(std::vector<Rule>& out) {
    out.insert(out.end(), {
        deprecated_image16x14,
        deprecated_vendor_unique_name,
        deprecated_tc_cfg_mode_safe_op,
        deprecated_profile_channel,
        deprecated_fmmu_op_only,
        deprecated_sm_one_byte_mode,
        deprecated_obsolete,
    });
}

}  // namespace esi::rules
