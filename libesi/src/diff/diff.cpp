// The differ's entry point: matches devices between the two files by identity, compares each
// pair, compares what belongs to the file as a whole, and orders the changes deterministically.

#include "esi/diff/diff.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <tuple>

#include <fmt/format.h>

#include "diff/compare.hpp"
#include "esi/diff/classification.hpp"
#include "esi/io/read_file.hpp"
#include "esi/load/document.hpp"
#include "esi/xml/reader.hpp"

namespace esi {

using namespace diff_detail;

namespace {

struct DeviceItem {
    const Device* device = nullptr;
    std::uint32_t vendor = 0;
};

// Devices of one product: same vendor and product code (or, without a product code, same Type
// text). Revisions of one family are what "a new revision of that device" refers to.
struct FamilyKey {
    std::uint32_t vendor = 0;
    bool has_product_code = false;
    std::uint32_t product_code = 0;
    std::string type_text;
    friend auto operator<=>(const FamilyKey&, const FamilyKey&) = default;
};

// Revision order; a missing RevisionNo sorts before every revision.
std::int64_t revision_rank(const Device& d) { return d.type.revision_no ? static_cast<std::int64_t>(*d.type.revision_no) : -1; }

DeviceRef ref_of(const Device& d) {
    DeviceRef ref;
    ref.name = primary_text(d.names);
    if (ref.name.empty()) ref.name = d.type.text;
    ref.type = d.type.text;
    ref.product_code = d.type.product_code;
    ref.revision = d.type.revision_no;
    return ref;
}

std::string describe_device(const Device& d) {
    std::string out = quote(primary_text(d.names).empty() ? d.type.text : primary_text(d.names));
    if (d.type.product_code) out += fmt::format(" product code {}", hex(*d.type.product_code, 8));
    if (d.type.revision_no) out += fmt::format(" revision {}", hex(*d.type.revision_no, 8));
    return out;
}

std::vector<DeviceItem> devices_of(const EsiDocument& doc) {
    std::vector<DeviceItem> out;
    for (const auto& info : doc.infos) {
        const std::uint32_t vendor = info.vendor && info.vendor->id ? *info.vendor->id : 0;
        for (const auto& d : info.devices) out.push_back({&d, vendor});
    }
    return out;
}

std::set<std::uint32_t> vendors_of(const std::vector<DeviceItem>& items) {
    std::set<std::uint32_t> out;
    for (const auto& i : items) out.insert(i.vendor);
    return out;
}

FamilyKey family_of(const DeviceItem& item, std::uint32_t vendor) {
    FamilyKey k;
    k.vendor = vendor;
    if (item.device->type.product_code) {
        k.has_product_code = true;
        k.product_code = *item.device->type.product_code;
    } else {
        k.type_text = item.device->type.text;
    }
    return k;
}

// One comparison to make: a device pair, or a device on one side only.
struct Match {
    const Device* old_device = nullptr;
    const Device* new_device = nullptr;
    RevisionContext context = RevisionContext::same_revision;
};

std::vector<Match> match_devices(const std::vector<DeviceItem>& old_items, const std::vector<DeviceItem>& new_items,
                                 const std::optional<std::pair<std::uint32_t, std::uint32_t>>& vendor_map) {
    std::map<FamilyKey, std::vector<const Device*>> old_families;
    std::map<FamilyKey, std::vector<const Device*>> new_families;
    for (const auto& i : old_items)
        old_families[family_of(i, vendor_map && i.vendor == vendor_map->first ? vendor_map->second : i.vendor)].push_back(
            i.device);
    for (const auto& i : new_items) new_families[family_of(i, i.vendor)].push_back(i.device);
    std::set<FamilyKey> keys;
    for (const auto& [k, v] : old_families) keys.insert(k);
    for (const auto& [k, v] : new_families) keys.insert(k);

    std::vector<Match> out;
    for (const auto& key : keys) {
        const auto& olds = old_families[key];
        const auto& news = new_families[key];
        std::vector<bool> old_matched(olds.size(), false);
        std::vector<bool> old_used(olds.size(), false);
        std::vector<bool> new_matched(news.size(), false);
        // Same identity: the k-th device with a revision pairs with the k-th in the other file.
        for (std::size_t j = 0; j < news.size(); ++j) {
            for (std::size_t i = 0; i < olds.size(); ++i) {
                if (old_matched[i] || olds[i]->type.revision_no != news[j]->type.revision_no) continue;
                old_matched[i] = true;
                new_matched[j] = true;
                out.push_back({olds[i], news[j], RevisionContext::same_revision});
                break;
            }
        }
        // A new revision is compared with its predecessor: the highest lower revision in the old file.
        std::vector<std::size_t> new_order;
        for (std::size_t j = 0; j < news.size(); ++j)
            if (!new_matched[j]) new_order.push_back(j);
        std::stable_sort(new_order.begin(), new_order.end(),
                         [&](std::size_t x, std::size_t y) { return revision_rank(*news[x]) < revision_rank(*news[y]); });
        for (std::size_t j : new_order) {
            std::optional<std::size_t> predecessor;
            for (std::size_t i = 0; i < olds.size(); ++i) {
                if (revision_rank(*olds[i]) >= revision_rank(*news[j])) continue;
                if (!predecessor || revision_rank(*olds[i]) > revision_rank(*olds[*predecessor])) predecessor = i;
            }
            if (!predecessor) {
                out.push_back({nullptr, news[j], RevisionContext::same_revision});
                continue;
            }
            old_used[*predecessor] = true;
            // Still described in the new file (matched by identity above): this revision is added next to it.
            out.push_back({olds[*predecessor], news[j],
                           old_matched[*predecessor] ? RevisionContext::added_revision : RevisionContext::replaced_revision});
        }
        for (std::size_t i = 0; i < olds.size(); ++i)
            if (!old_matched[i] && !old_used[i]) out.push_back({olds[i], nullptr, RevisionContext::same_revision});
    }
    return out;
}

// Where the devices of a document are listed (for a device on one side only).
SourcePos devices_pos(const EsiDocument& doc) {
    if (!doc.infos.empty() && doc.infos.front().descriptions_pos.known()) return doc.infos.front().descriptions_pos;
    return doc.root_pos;
}

void compare_match(Recorder& r, const Match& m, const BrokenModules& broken_modules, SourcePos old_devices,
                   SourcePos new_devices) {
    if (!m.old_device) {
        r.set_device(ref_of(*m.new_device), RevisionContext::same_revision);
        r.add(ChangeKind::device_added, "Device", std::nullopt, describe_device(*m.new_device), old_devices, m.new_device->pos,
              fmt::format("device {} added", describe_device(*m.new_device)));
        return;
    }
    if (!m.new_device) {
        r.set_device(ref_of(*m.old_device), RevisionContext::same_revision);
        r.add(ChangeKind::device_removed, "Device", describe_device(*m.old_device), std::nullopt, m.old_device->pos, new_devices,
              fmt::format("device {} removed", describe_device(*m.old_device)));
        return;
    }
    DeviceRef ref = ref_of(*m.new_device);
    if (m.context != RevisionContext::same_revision) ref.compared_revision = m.old_device->type.revision_no;
    r.set_device(ref, m.context);
    const auto old_revision = hex(m.old_device->type.revision_no, 8);
    const auto new_revision = hex(m.new_device->type.revision_no, 8);
    if (m.context == RevisionContext::added_revision)
        r.add(ChangeKind::device_revision_added, attr("Type", "RevisionNo"), old_revision, new_revision, m.old_device->type.pos,
              m.new_device->type.pos,
              fmt::format("new revision {} added next to revision {}, which is still described; compared with it",
                          new_revision.value_or("(none)"), old_revision.value_or("(none)")));
    else if (m.context == RevisionContext::replaced_revision)
        r.add(ChangeKind::revision_changed, attr("Type", "RevisionNo"), old_revision, new_revision, m.old_device->type.pos,
              m.new_device->type.pos,
              fmt::format("RevisionNo changed from {} to {}", old_revision.value_or("(none)"), new_revision.value_or("(none)")));
    const std::size_t mark = r.size();
    compare_device(r, *m.old_device, *m.new_device);
    if (m.context != RevisionContext::same_revision) return;
    const bool device_broken = r.breaking_since(mark);
    const bool modules_broken = broken_modules.affect(*m.new_device);
    if (device_broken || modules_broken)
        r.add(ChangeKind::revision_not_changed, attr("Type", "RevisionNo"), old_revision, new_revision, m.old_device->type.pos,
              m.new_device->type.pos,
              fmt::format(
                  "breaking changes {}without a RevisionNo change (still {}): masters match devices by vendor, product code "
                  "and revision, so configurations made from the old file accept the changed device",
                  device_broken ? (modules_broken ? "to the device and to modules its slots accept " : "")
                                : "to modules its slots accept ",
                  new_revision.value_or("absent")));
}

BrokenModules compare_file_level(Recorder& r, const EsiDocument& a, const EsiDocument& b) {
    r.set_device(std::nullopt, RevisionContext::same_revision);
    if (a.kind != b.kind)
        r.value(ChangeKind::document_kind_changed, "", "root element", std::string(root_element_name(a.kind)),
                std::string(root_element_name(b.kind)), a.root_pos, b.root_pos);
    const std::string root = std::string(root_element_name(b.kind));
    compare_extras(r, root, a.root_extras, b.root_extras, a.root_pos, b.root_pos);
    r.value(ChangeKind::info_version_changed, attr("EtherCATDict", "Version"), "EtherCATDict@Version", a.dict_version,
            b.dict_version, a.root_pos, b.root_pos);
    if (a.dictionary || b.dictionary)
        compare_dictionaries(r, "Dictionary", a.dictionary ? &*a.dictionary : nullptr, b.dictionary ? &*b.dictionary : nullptr,
                             a.root_pos, b.root_pos);

    // Infos pair up by position (an EtherCATInfoList lists them in a meaningful order for its tool).
    const std::size_t infos = std::min(a.infos.size(), b.infos.size());
    for (std::size_t i = 0; i < infos; ++i) {
        const EtherCATInfo& x = a.infos[i];
        const EtherCATInfo& y = b.infos[i];
        const std::string p = infos > 1 ? indexed("EtherCATInfo", std::to_string(i + 1)) : std::string("EtherCATInfo");
        r.value(ChangeKind::info_version_changed, attr(p, "Version"), "EtherCATInfo@Version", x.version, y.version, x.pos, y.pos);
        compare_extras(r, p, x.extras, y.extras, x.pos, y.pos);
        // An empty Descriptions or Modules element carries nothing, but it is written or not.
        const auto present = [](bool b) { return std::optional<std::string>(b ? "present" : "absent"); };
        r.value(ChangeKind::spelling_changed, child(p, "Descriptions"), "Descriptions element", present(x.has_descriptions),
                present(y.has_descriptions), x.pos, y.pos);
        if (x.modules.empty() && y.modules.empty())
            r.value(ChangeKind::spelling_changed, child(p, "Modules"), "empty Modules element", present(x.has_modules),
                    present(y.has_modules), x.pos, y.pos);
        compare_extras(r, child(p, "Descriptions"), x.descriptions_extras, y.descriptions_extras,
                       x.descriptions_pos.known() ? x.descriptions_pos : x.pos,
                       y.descriptions_pos.known() ? y.descriptions_pos : y.pos);
    }

    std::vector<const Group*> ga;
    std::vector<const Group*> gb;
    std::vector<const Module*> ma;
    std::vector<const Module*> mb;
    for (const auto& info : a.infos) {
        for (const auto& g : info.groups) ga.push_back(&g);
        for (const auto& m : info.modules) ma.push_back(&m);
    }
    for (const auto& info : b.infos) {
        for (const auto& g : info.groups) gb.push_back(&g);
        for (const auto& m : info.modules) mb.push_back(&m);
    }
    compare_groups(r, ga, gb, a.root_pos, b.root_pos);
    return compare_modules(r, "Modules", ma, mb, a.root_pos, b.root_pos);
}

// Vendors pair up by Id; a single vendor on each side pairs whatever its Id (the Id change is
// reported, and devices still match).
void compare_all_vendors(Recorder& r, const EsiDocument& a, const EsiDocument& b, bool only_id) {
    std::vector<const Vendor*> va;
    std::vector<const Vendor*> vb;
    for (const auto& info : a.infos)
        if (info.vendor) va.push_back(&*info.vendor);
    for (const auto& info : b.infos)
        if (info.vendor) vb.push_back(&*info.vendor);
    r.set_device(std::nullopt, RevisionContext::same_revision);
    auto compare_pair = [&](const Vendor* x, const Vendor* y) {
        if (only_id) {
            if (x && y)
                r.value(ChangeKind::vendor_id_changed, "Vendor/Id", "vendor Id", hex(x->id, 8), hex(y->id, 8), x->id_pos,
                        y->id_pos);
            return;
        }
        compare_vendors(r, x, y, a.root_pos, b.root_pos, true);
    };
    if (va.size() <= 1 && vb.size() <= 1) {
        compare_pair(va.empty() ? nullptr : va[0], vb.empty() ? nullptr : vb[0]);
        return;
    }
    std::map<std::uint32_t, std::vector<const Vendor*>> ia;
    std::map<std::uint32_t, std::vector<const Vendor*>> ib;
    for (const Vendor* v : va) ia[v->id.value_or(0)].push_back(v);
    for (const Vendor* v : vb) ib[v->id.value_or(0)].push_back(v);
    std::set<std::uint32_t> ids;
    for (const auto& [k, v] : ia) ids.insert(k);
    for (const auto& [k, v] : ib) ids.insert(k);
    for (std::uint32_t id : ids) {
        const auto& la = ia[id];
        const auto& lb = ib[id];
        for (std::size_t i = 0; i < std::max(la.size(), lb.size()); ++i)
            compare_pair(i < la.size() ? la[i] : nullptr, i < lb.size() ? lb[i] : nullptr);
    }
}

// Order of devices in the output: file-level changes first, then by product code, revision,
// compared revision, Type text and name.
bool device_less(const DeviceRef& x, const DeviceRef& y) {
    auto key = [](const DeviceRef& d) {
        return std::make_tuple(!d.product_code.has_value(), d.product_code.value_or(0),
                               d.revision ? static_cast<std::int64_t>(*d.revision) : -1,
                               d.compared_revision ? static_cast<std::int64_t>(*d.compared_revision) : -1);
    };
    const auto kx = key(x);
    const auto ky = key(y);
    if (kx != ky) return kx < ky;
    if (x.type != y.type) return x.type < y.type;
    return x.name < y.name;
}

int kind_rank(ChangeKind kind) {
    if (is_error(kind)) return 0;
    switch (kind) {
        case ChangeKind::device_added:
        case ChangeKind::device_removed:
        case ChangeKind::device_revision_added:
        case ChangeKind::revision_changed: return 1;
        default: return 2;
    }
}

// Paths compare as text, except that a decimal position in brackets ("Entry[10]", "Slot[2]")
// compares as a number, so that Entry[2] comes before Entry[10]. Hex keys ("#x1A00") have a fixed
// width and upper-case digits, so they already sort as text. The paths are compared as sequences
// of tokens (such a number, or one character), numbers before characters: a total order.
bool path_less(std::string_view a, std::string_view b) {
    // Length of the decimal number starting at k when it fills a bracket ("[12]"), else 0.
    auto number_at = [](std::string_view s, std::size_t k) -> std::size_t {
        if (k == 0 || s[k - 1] != '[') return 0;
        std::size_t e = k;
        while (e < s.size() && s[e] >= '0' && s[e] <= '9') ++e;
        return e > k && e < s.size() && s[e] == ']' ? e - k : 0;
    };
    std::size_t i = 0;
    std::size_t j = 0;
    while (i < a.size() && j < b.size()) {
        if (a[i] >= '0' && a[i] <= '9' && b[j] >= '0' && b[j] <= '9') {
            const std::size_t na = number_at(a, i);
            const std::size_t nb = number_at(b, j);
            if (na && nb) {
                std::string_view x = a.substr(i, na);
                std::string_view y = b.substr(j, nb);
                const std::string_view xs = x.substr(std::min(x.find_first_not_of('0'), x.size()));
                const std::string_view ys = y.substr(std::min(y.find_first_not_of('0'), y.size()));
                if (xs.size() != ys.size()) return xs.size() < ys.size();
                if (xs != ys) return xs < ys;
                if (x != y) return x < y;
                i += na;
                j += nb;
                continue;
            }
            if (na || nb) return na != 0;  // a bracketed number sorts before any character
        } else if ((a[i] >= '0' && a[i] <= '9' && number_at(a, i)) || (b[j] >= '0' && b[j] <= '9' && number_at(b, j))) {
            return a[i] >= '0' && a[i] <= '9';
        }
        if (a[i] != b[j]) return static_cast<unsigned char>(a[i]) < static_cast<unsigned char>(b[j]);
        ++i;
        ++j;
    }
    return a.size() - i < b.size() - j;
}

void sort_changes(std::vector<Change>& changes) {
    // Rank the devices once, then sort indices by small keys: comparing whole Changes (strings,
    // optional device descriptions) in every step of the sort would cost more than the diff.
    std::vector<const DeviceRef*> devices;
    for (const auto& c : changes)
        if (c.device) devices.push_back(&*c.device);
    std::sort(devices.begin(), devices.end(), [](const DeviceRef* x, const DeviceRef* y) { return device_less(*x, *y); });
    // Changes come device by device, so a run of changes of one device is ranked once.
    const DeviceRef* last = nullptr;
    std::size_t last_rank = 0;
    auto device_rank = [&](const Change& c) -> std::size_t {
        if (!c.device) return 0;
        if (last && *last == *c.device) return last_rank;
        const auto it = std::lower_bound(devices.begin(), devices.end(), &*c.device,
                                         [](const DeviceRef* x, const DeviceRef* y) { return device_less(*x, *y); });
        last = &*c.device;
        last_rank = 1 + static_cast<std::size_t>(it - devices.begin());
        return last_rank;
    };
    struct Key {
        std::size_t device;
        int kind;
        int change_class;
        std::size_t index;
    };
    std::vector<Key> keys;
    keys.reserve(changes.size());
    for (std::size_t i = 0; i < changes.size(); ++i)
        keys.push_back({device_rank(changes[i]), kind_rank(changes[i].kind), -static_cast<int>(changes[i].change_class), i});
    std::stable_sort(keys.begin(), keys.end(), [&](const Key& x, const Key& y) {
        if (x.device != y.device) return x.device < y.device;
        if (x.kind != y.kind) return x.kind < y.kind;
        if (x.change_class != y.change_class) return x.change_class < y.change_class;
        return path_less(changes[x.index].path, changes[y.index].path);
    });
    std::vector<Change> sorted;
    sorted.reserve(changes.size());
    for (const Key& k : keys) sorted.push_back(std::move(changes[k.index]));
    changes = std::move(sorted);
}

}  // namespace

std::size_t DiffResult::count(ChangeClass change_class) const {
    return static_cast<std::size_t>(
        std::count_if(changes.begin(), changes.end(), [&](const Change& c) { return c.change_class == change_class; }));
}

std::size_t DiffResult::error_count() const {
    return static_cast<std::size_t>(
        std::count_if(changes.begin(), changes.end(), [](const Change& c) { return is_error(c.kind); }));
}

DiffResult diff_documents(const EsiDocument& old_document, const EsiDocument& new_document, const DiffOptions& options) {
    DiffResult result;
    Recorder r(result.changes);

    std::vector<DeviceItem> old_items = devices_of(old_document);
    std::vector<DeviceItem> new_items = devices_of(new_document);
    // Selection: by product code first, so that a new revision still finds its predecessor.
    if (options.device) {
        const std::uint32_t code = options.device->product_code;
        auto other_product = [&](const DeviceItem& i) { return i.device->type.product_code != code; };
        old_items.erase(std::remove_if(old_items.begin(), old_items.end(), other_product), old_items.end());
        new_items.erase(std::remove_if(new_items.begin(), new_items.end(), other_product), new_items.end());
    }

    compare_all_vendors(r, old_document, new_document, options.device.has_value());
    BrokenModules broken_modules;
    if (!options.device) broken_modules = compare_file_level(r, old_document, new_document);

    // One vendor on each side with different Ids: the vendor Id change is reported once, and the
    // devices still pair up as if the Id had stayed.
    std::optional<std::pair<std::uint32_t, std::uint32_t>> vendor_map;
    const auto vendors_a = vendors_of(old_items);
    const auto vendors_b = vendors_of(new_items);
    if (vendors_a.size() == 1 && vendors_b.size() == 1 && *vendors_a.begin() != *vendors_b.begin())
        vendor_map = std::make_pair(*vendors_a.begin(), *vendors_b.begin());

    for (const Match& m : match_devices(old_items, new_items, vendor_map)) {
        if (options.device && options.device->revision) {
            const auto& wanted = options.device->revision;
            const bool old_selected = m.old_device && m.old_device->type.revision_no == wanted;
            const bool new_selected = m.new_device && m.new_device->type.revision_no == wanted;
            if (!old_selected && !new_selected) continue;
        }
        if (m.old_device) ++result.old_devices_compared;
        if (m.new_device) ++result.new_devices_compared;
        compare_match(r, m, broken_modules, devices_pos(old_document), devices_pos(new_document));
    }

    sort_changes(result.changes);
    for (const auto& c : result.changes)
        if (result.verdict < verdict_of(c.change_class)) result.verdict = verdict_of(c.change_class);
    return result;
}

FileDiff diff_files(const std::filesystem::path& old_path, const std::filesystem::path& new_path, const DiffOptions& options) {
    return diff_sources({old_path, std::nullopt}, {new_path, std::nullopt}, options);
}

FileDiff diff_sources(DiffSource old_source, DiffSource new_source, const DiffOptions& options) {
    FileDiff out;
    out.old_path = old_source.path.string();
    out.new_path = new_source.path.string();
    // Either side may be an ESI file or a YAML device source (two revisions of a source, or a
    // source against the ESI file generated from it); the load layer tells them apart.
    const auto read = [&](DiffSource& source) {
        const std::string ext = source.path.extension().string();
        if (!source.bytes && (ext == ".yaml" || ext == ".yml")) return load_document_file(source.path);
        LoadedDocument loaded;
        if (!source.bytes) {
            std::string error;
            source.bytes = read_file_bytes(source.path, error);
            if (!source.bytes) {
                loaded.diagnostics.emplace(Severity::error, "io-error", "cannot read file: " + error, source.path.string(), {});
                return loaded;
            }
        }
        if (document_format(*source.bytes, source.path) == DocumentFormat::yaml_source)
            return load_document(std::move(*source.bytes), source.path.string());
        // ESI files are read without keeping their text: a diff quotes no lines, and catalogues are big.
        ReadOptions read_options;
        read_options.keep_source = false;
        ReadResult r = read_esi_owned(std::move(*source.bytes), source.path.string(), read_options);
        loaded.document = std::move(r.document);
        loaded.diagnostics = std::move(r.diagnostics);
        return loaded;
    };
    LoadedDocument a = read(old_source);
    LoadedDocument b = read(new_source);
    bool ok = true;
    for (LoadedDocument* r : {&a, &b}) {
        const bool unusable = !r->usable() || r->document->kind == DocumentKind::unknown;
        if (!unusable) continue;
        ok = false;
        for (auto& d : r->diagnostics)
            if (d.severity == Severity::error) out.diagnostics.add(d);
    }
    if (!ok) return out;
    out.result = diff_documents(*a.document, *b.document, options);
    if (options.keep_documents) {
        out.old_document = std::move(a.document);
        out.new_document = std::move(b.document);
    }
    return out;
}

}  // namespace esi
