// The parts of a file that belong to no single device: the vendor, the groups (matched by their
// Type, the key Device/GroupType refers to) and the modules of a modular catalogue (matched by
// ModuleIdent, the key a Slot refers to; by Type text when the ident is 0).

#include <map>

#include <fmt/format.h>

#include "diff/compare.hpp"

namespace esi::diff_detail {

void compare_vendors(Recorder& r, const Vendor* a, const Vendor* b, SourcePos old_parent, SourcePos new_parent, bool compare_id) {
    if (!a && !b) return;
    static const Vendor none;
    const Vendor& x = a ? *a : none;
    const Vendor& y = b ? *b : none;
    const SourcePos px = a ? a->pos : old_parent;
    const SourcePos py = b ? b->pos : new_parent;
    if (compare_id)
        r.value(ChangeKind::vendor_id_changed, "Vendor/Id", "vendor Id", hex(x.id, 8), hex(y.id, 8),
                x.id_pos.known() ? x.id_pos : px, y.id_pos.known() ? y.id_pos : py);
    compare_texts(r, ChangeKind::name_changed, "Vendor", "Name", x.names, y.names, px, py);
    compare_texts(r, ChangeKind::comment_changed, "Vendor", "Comment", x.comments, y.comments, px, py);
    compare_texts(r, ChangeKind::comment_changed, "Vendor", "URL", x.urls, y.urls, px, py);
    r.value(ChangeKind::vendor_changed, "Vendor/DescriptionURL", "DescriptionURL", x.description_url, y.description_url, px, py);
    r.value(ChangeKind::vendor_changed, "Vendor@UniqueName", "UniqueName", x.unique_name, y.unique_name, px, py);
    r.value(ChangeKind::vendor_changed, "Vendor@FileVersion", "FileVersion", x.file_version, y.file_version, px, py);
    compare_images(r, "Vendor", x.images, y.images, px, py);
    compare_extras(r, "Vendor", x.extras, y.extras, px, py);
}

void compare_groups(Recorder& r, const std::vector<const Group*>& a, const std::vector<const Group*>& b, SourcePos old_parent,
                    SourcePos new_parent) {
    std::map<std::string, std::vector<const Group*>> ga;
    std::map<std::string, std::vector<const Group*>> gb;
    for (const Group* g : a) ga[g->type].push_back(g);
    for (const Group* g : b) gb[g->type].push_back(g);
    std::map<std::string, bool> types;
    for (const auto& [k, v] : ga) types[k] = true;
    for (const auto& [k, v] : gb) types[k] = true;
    for (const auto& [type, unused] : types) {
        const auto& la = ga[type];
        const auto& lb = gb[type];
        const std::size_t n = std::max(la.size(), lb.size());
        for (std::size_t i = 0; i < n; ++i) {
            const Group* x = i < la.size() ? la[i] : nullptr;
            const Group* y = i < lb.size() ? lb[i] : nullptr;
            const std::string p = indexed("Group", n > 1 ? fmt::format("{}#{}", type, i + 1) : type);
            if (!x || !y) {
                const Group& g = x ? *x : *y;
                r.add(x ? ChangeKind::group_removed : ChangeKind::group_added, p,
                      x ? std::optional<std::string>(type) : std::nullopt, y ? std::optional<std::string>(type) : std::nullopt,
                      x ? x->pos : old_parent, y ? y->pos : new_parent,
                      fmt::format("group {} {} {}", quote(type), quote(primary_text(g.names)), x ? "removed" : "added"));
                continue;
            }
            compare_texts(r, ChangeKind::name_changed, p, "Name", x->names, y->names, x->pos, y->pos);
            compare_texts(r, ChangeKind::comment_changed, p, "Comment", x->comments, y->comments, x->pos, y->pos);
            r.value(ChangeKind::group_changed, attr(p, "SortOrder"), "SortOrder", dec(x->sort_order), dec(y->sort_order), x->pos,
                    y->pos);
            r.value(ChangeKind::group_changed, attr(p, "ParentGroup"), "ParentGroup", x->parent_group, y->parent_group, x->pos,
                    y->pos);
            compare_images(r, p, x->images, y->images, x->pos, y->pos);
            compare_extras(r, p, x->extras, y->extras, x->pos, y->pos);
        }
    }
}

namespace {

std::string module_key(const Module& m) { return m.module_ident != 0 ? hex(m.module_ident, 8) : "Type " + m.type; }

void compare_module(Recorder& r, const std::string& p, const Module& a, const Module& b) {
    r.value(ChangeKind::type_text_changed, child(p, "Type"), "module Type text", a.type, b.type, a.type_pos, b.type_pos);
    r.value(ChangeKind::module_attribute_changed, child(p, "Type@ModuleClass"), "ModuleClass", a.module_class, b.module_class,
            a.type_pos, b.type_pos);
    r.value(ChangeKind::module_attribute_changed, child(p, "Type@ModulePdoGroup"), "ModulePdoGroup", dec(a.module_pdo_group),
            dec(b.module_pdo_group), a.type_pos, b.type_pos);
    compare_extras(r, child(p, "Type"), a.type_extras, b.type_extras, a.type_pos, b.type_pos);
    compare_texts(r, ChangeKind::name_changed, p, "Name", a.names, b.names, a.pos, b.pos);
    compare_pdos(r, p, a.rx_pdos, b.rx_pdos, a.pos, b.pos);
    compare_pdos(r, p, a.tx_pdos, b.tx_pdos, a.pos, b.pos);
    compare_mailboxes(r, child(p, "Mailbox"), a.mailbox, b.mailbox, a.pos, b.pos);
    std::vector<const Profile*> pa;
    std::vector<const Profile*> pb;
    if (a.profile) pa.push_back(&*a.profile);
    if (b.profile) pb.push_back(&*b.profile);
    compare_profiles(r, p, pa, pb, a.pos, b.pos);
    r.value(ChangeKind::module_attribute_changed, child(p, "DcOpModeName"), "DcOpModeName", a.dc_op_mode_name, b.dc_op_mode_name,
            a.pos, b.pos);
    compare_images(r, p, a.images, b.images, a.pos, b.pos);
    compare_extras(r, p, a.extras, b.extras, a.pos, b.pos);
}

}  // namespace

bool BrokenModules::affect(const Device& device) const {
    if (!device.slots) return false;
    for (const auto& slot : device.slots->slots) {
        for (const auto& ident : slot.module_idents)
            if (idents.count(ident.value)) return true;
        for (const auto& c : slot.module_classes)
            if (classes.count(c.class_name)) return true;
    }
    return false;
}

BrokenModules compare_modules(Recorder& r, const std::string& path, const std::vector<const Module*>& a,
                              const std::vector<const Module*>& b, SourcePos old_parent, SourcePos new_parent) {
    BrokenModules broken;
    auto note = [&](const Module& m) {
        if (m.module_ident != 0) broken.idents.insert(m.module_ident);
        if (m.module_class) broken.classes.insert(*m.module_class);
    };
    std::map<std::string, std::vector<const Module*>> ma;
    std::map<std::string, std::vector<const Module*>> mb;
    for (const Module* m : a) ma[module_key(*m)].push_back(m);
    for (const Module* m : b) mb[module_key(*m)].push_back(m);
    std::map<std::string, bool> keys;
    for (const auto& [k, v] : ma) keys[k] = true;
    for (const auto& [k, v] : mb) keys[k] = true;
    for (const auto& [key, unused] : keys) {
        const auto& la = ma[key];
        const auto& lb = mb[key];
        const std::size_t n = std::max(la.size(), lb.size());
        for (std::size_t i = 0; i < n; ++i) {
            const Module* x = i < la.size() ? la[i] : nullptr;
            const Module* y = i < lb.size() ? lb[i] : nullptr;
            const std::string p = child(path, indexed("Module", n > 1 ? fmt::format("{}#{}", key, i + 1) : key));
            if (x && y) {
                const std::size_t mark = r.size();
                compare_module(r, p, *x, *y);
                if (r.breaking_since(mark)) {
                    note(*x);
                    note(*y);
                }
                continue;
            }
            const Module& m = x ? *x : *y;
            if (x) note(*x);
            const std::string value = fmt::format("{} {}", m.type, quote(primary_text(m.names)));
            r.add(x ? ChangeKind::module_removed : ChangeKind::module_added, p,
                  x ? std::optional<std::string>(value) : std::nullopt, y ? std::optional<std::string>(value) : std::nullopt,
                  x ? x->pos : old_parent, y ? y->pos : new_parent,
                  fmt::format("module {} ({}) {}", key, value, x ? "removed" : "added"));
        }
    }
    return broken;
}

}  // namespace esi::diff_detail
