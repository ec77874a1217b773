// Device-level comparison: description, identity details, profiles, and the dispatch to the
// comparisons of SyncManagers, PDOs, mailbox, DC, EEPROM and slots.

#include <fmt/format.h>

#include "diff/compare.hpp"

namespace esi::diff_detail {

namespace {

std::vector<const Profile*> profiles_of(const Device& d) {
    std::vector<const Profile*> out;
    for (const auto& p : d.profiles) out.push_back(&p);
    return out;
}

}  // namespace

void compare_device(Recorder& r, const Device& a, const Device& b) {
    // Identity: ProductCode and RevisionNo were matched by the caller.
    r.value(ChangeKind::type_text_changed, "Type", "Type text", a.type.text, b.type.text, a.type.pos, b.type.pos);
    r.value(ChangeKind::device_flag_changed, attr("Type", "SerialNo"), "SerialNo", hex(a.type.serial_no, 8),
            hex(b.type.serial_no, 8), a.type.pos, b.type.pos);
    r.value(ChangeKind::device_flag_changed, attr("Type", "TcCfgModeSafeOp"), "TcCfgModeSafeOp", flag(a.type.tc_cfg_mode_safe_op),
            flag(b.type.tc_cfg_mode_safe_op), a.type.pos, b.type.pos);
    compare_extras(r, "Type", a.type.extras, b.type.extras, a.type.pos, b.type.pos);

    // Physics has one letter per port; a trailing space is a port that is not there.
    const std::string_view ports_a = std::string_view(a.physics).substr(0, a.physics.find_last_not_of(' ') + 1);
    const std::string_view ports_b = std::string_view(b.physics).substr(0, b.physics.find_last_not_of(' ') + 1);
    ChangeKind physics = ChangeKind::physics_changed;
    if (ports_a == ports_b)
        physics = ChangeKind::spelling_changed;
    else if (ports_b.size() > ports_a.size() && ports_b.substr(0, ports_a.size()) == ports_a)
        physics = ChangeKind::physics_ports_added;
    r.value(physics, "@Physics", "Physics", quote(a.physics), quote(b.physics), a.pos, b.pos);
    r.value(ChangeKind::device_flag_changed, "@Invisible", "Invisible", flag(a.invisible), flag(b.invisible), a.pos, b.pos);
    compare_texts(r, ChangeKind::name_changed, "", "Name", a.names, b.names, a.pos, b.pos);
    compare_texts(r, ChangeKind::comment_changed, "", "Comment", a.comments, b.comments, a.pos, b.pos);
    compare_texts(r, ChangeKind::comment_changed, "", "URL", a.urls, b.urls, a.pos, b.pos);
    r.value(ChangeKind::group_type_changed, "GroupType", "GroupType", a.group_type, b.group_type,
            a.group_type_pos.known() ? a.group_type_pos : a.pos, b.group_type_pos.known() ? b.group_type_pos : b.pos);

    compare_profiles(r, "", profiles_of(a), profiles_of(b), a.pos, b.pos);
    compare_sync_managers(r, a, b);
    compare_pdos(r, "", a.rx_pdos, b.rx_pdos, a.pos, b.pos);
    compare_pdos(r, "", a.tx_pdos, b.tx_pdos, a.pos, b.pos);
    compare_mailboxes(r, "Mailbox", a.mailbox, b.mailbox, a.pos, b.pos);
    compare_dc(r, "Dc", a.dc, b.dc, a.pos, b.pos);
    compare_slots(r, "Slots", a.slots, b.slots, a.pos, b.pos);
    compare_eeproms(r, "Eeprom", a.eeprom, b.eeprom, a.pos, b.pos);
    compare_images(r, "", a.images, b.images, a.pos, b.pos);
    compare_extras(r, "", a.extras, b.extras, a.pos, b.pos);
}

void compare_profiles(Recorder& r, const std::string& path, const std::vector<const Profile*>& a,
                      const std::vector<const Profile*>& b, SourcePos old_parent, SourcePos new_parent) {
    // Profiles pair up by position; a device has one in all but a few multi-channel files.
    const std::size_t n = std::max(a.size(), b.size());
    for (std::size_t i = 0; i < n; ++i) {
        const Profile* x = i < a.size() ? a[i] : nullptr;
        const Profile* y = i < b.size() ? b[i] : nullptr;
        const std::string p = child(path, n > 1 ? fmt::format("Profile[{}]", i + 1) : std::string("Profile"));
        const SourcePos px = x ? x->pos : old_parent;
        const SourcePos py = y ? y->pos : new_parent;
        if (!x || !y) {
            r.add(ChangeKind::profile_changed, p, x ? std::optional<std::string>("Profile") : std::nullopt,
                  y ? std::optional<std::string>("Profile") : std::nullopt, px, py,
                  fmt::format("{} {}", p, x ? "removed" : "added"));
        } else {
            r.value(ChangeKind::profile_number_changed, child(p, "ProfileNo"), "ProfileNo", dec(x->profile_no),
                    dec(y->profile_no), px, py);
            r.value(ChangeKind::profile_changed, child(p, "AddInfo"), "AddInfo", dec(x->add_info), dec(y->add_info), px, py);
            r.value(ChangeKind::profile_changed, attr(p, "Channel"), "Channel", dec(x->channel), dec(y->channel), px, py);
            r.value(ChangeKind::profile_changed, child(p, "DictionaryFile"), "DictionaryFile", x->dictionary_file,
                    y->dictionary_file, px, py);
            compare_extras(r, p, x->extras, y->extras, px, py);
        }
        // The dictionary path leaves out "Profile" for the usual single profile: "Dictionary/Object[#x6040]".
        const std::string dictionary_path = n > 1 ? child(p, "Dictionary") : child(path, "Dictionary");
        const Dictionary* dx = x && x->dictionary ? &*x->dictionary : nullptr;
        const Dictionary* dy = y && y->dictionary ? &*y->dictionary : nullptr;
        compare_dictionaries(r, dictionary_path, dx, dy, dx ? dx->pos : px, dy ? dy->pos : py);
    }
}

}  // namespace esi::diff_detail
