#include "esi/net/resolve.hpp"

#include <algorithm>
#include <cctype>
#include <fmt/format.h>
#include <map>
#include <set>

#include "esi/number.hpp"
#include "esi/text_distance.hpp"

namespace esi::net {

namespace {

std::string hex32(std::optional<std::uint32_t> v) { return v ? fmt::format("0x{:08X}", *v) : std::string("?"); }

bool equal_ignoring_case(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
}

bool identity_matches(const IndexedDevice& d, const DeviceQuery& q) {
    if (q.vendor_id && d.vendor_id != q.vendor_id) return false;
    if (q.product_code && d.product_code != q.product_code) return false;
    if (q.revision_no && d.revision_no != q.revision_no) return false;
    return true;
}

// Exact Type text first; a name that matches only ignoring case still resolves.
std::vector<const IndexedDevice*> candidates(const LibraryIndex& index, const DeviceQuery& q) {
    std::vector<const IndexedDevice*> exact, folded;
    for (const IndexedDevice& d : index.devices) {
        if (!identity_matches(d, q)) continue;
        if (q.name) {
            const std::string_view type = trim(d.type), wanted = trim(*q.name);
            if (type == wanted) exact.push_back(&d);
            else if (equal_ignoring_case(type, wanted)) folded.push_back(&d);
        } else {
            exact.push_back(&d);
        }
    }
    return exact.empty() ? folded : exact;
}

DiagnosticNote note_for(const LibraryIndex& index, const IndexedDevice& d, std::string message = {}) {
    return DiagnosticNote{index.file_of(d).path, SourcePos{d.line, d.column}, message.empty() ? describe_identity(d) : message};
}

std::string where_looked(const LibraryIndex& index) {
    std::string roots;
    for (const std::string& r : index.roots) roots += (roots.empty() ? "" : ", ") + r;
    return fmt::format("looked in {} ({} files, {} devices)", roots.empty() ? "no ESI path" : roots, index.files.size(),
                       index.devices.size());
}

// Devices that come close to a query nothing matched: the same product code at other revisions
// or vendors, else the Type texts closest to the name.
std::vector<const IndexedDevice*> nearest(const LibraryIndex& index, const DeviceQuery& q) {
    std::vector<const IndexedDevice*> out;
    if (q.product_code) {
        for (const IndexedDevice& d : index.devices)
            if (d.product_code == q.product_code) out.push_back(&d);
        const std::uint64_t wanted = q.revision_no.value_or(0);
        std::stable_sort(out.begin(), out.end(), [&](const IndexedDevice* a, const IndexedDevice* b) {
            const auto distance = [&](const IndexedDevice* d) {
                const std::uint64_t r = d->revision_no.value_or(0);
                return r > wanted ? r - wanted : wanted - r;
            };
            return distance(a) < distance(b);
        });
    }
    if (out.empty() && q.name) {
        const std::string wanted(trim(*q.name));
        std::vector<std::pair<std::size_t, const IndexedDevice*>> scored;
        std::set<std::string> seen;
        const std::size_t limit = std::max<std::size_t>(2, wanted.size() / 3);
        for (const IndexedDevice& d : index.devices) {
            if (!seen.insert(d.type).second) continue;
            const std::size_t length_gap = d.type.size() > wanted.size() ? d.type.size() - wanted.size() : wanted.size() - d.type.size();
            if (length_gap > limit) continue;
            const std::size_t distance = edit_distance(wanted, d.type);
            if (distance <= limit) scored.emplace_back(distance, &d);
        }
        std::stable_sort(scored.begin(), scored.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        for (const auto& [distance, d] : scored) out.push_back(d);
    }
    if (out.size() > 8) out.resize(8);
    return out;
}

Diagnostic unknown_device(const LibraryIndex& index, const DeviceQuery& q, const std::string& path, SourcePos pos) {
    Diagnostic d{Severity::error, "net-device-unknown", "no ESI file describes " + describe_query(q) + "; " + where_looked(index), path,
                 pos, {}};
    const std::vector<const IndexedDevice*> near = nearest(index, q);
    if (near.empty()) {
        d.notes.push_back({path, pos, "nothing in the library comes close (same product code or a similar name)"});
    } else {
        for (const IndexedDevice* n : near) d.notes.push_back(note_for(index, *n, "nearest: " + describe_identity(*n)));
    }
    return d;
}

// Which of `found` (one product) a device of the library hides: its vendor's catalogue lists
// that device in place of the revision (ETG.2000 HideType), as TwinCAT's catalogue does. This is
// how a current catalogue retires a legacy one: Beckhoff's pre-ETG.2000 "EtherCAT Terminals"
// file numbers the EK1100 0x270B0000 (ProductRevision EK1100-0000-9995), above every current
// revision, and the current EK11xx file's revision-0 EK1100 carries
// <HideType RevisionNo="#x270b0000" ProductRevision="EK1100-0000-9995"/>. The value is the
// hiding device (the first in index order).
std::map<const IndexedDevice*, const IndexedDevice*> hidden_by(const LibraryIndex& index,
                                                               const std::vector<const IndexedDevice*>& found) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, const IndexedDevice*> hiders;  // (product, revision) -> hider
    const std::optional<std::uint32_t> vendor = found.front()->vendor_id;
    for (const IndexedDevice& d : index.devices) {
        if (d.hides.empty() || d.vendor_id != vendor) continue;
        for (const HiddenIdentity& h : d.hides) {
            if (!h.product_code || !h.revision_no) continue;
            if (h.product_code == d.product_code && h.revision_no == d.revision_no) continue;  // hides itself: no statement
            hiders.emplace(std::pair{*h.product_code, *h.revision_no}, &d);
        }
    }
    std::map<const IndexedDevice*, const IndexedDevice*> out;
    for (const IndexedDevice* d : found) {
        if (!d->product_code || !d->revision_no) continue;
        if (const auto it = hiders.find({*d->product_code, *d->revision_no}); it != hiders.end()) out.emplace(d, it->second);
    }
    return out;
}

// The info that says which revision was taken, from which file, and why: the highest, and the
// higher ones passed over because a catalogue hides them.
Diagnostic revision_choice(const LibraryIndex& index, const std::vector<const IndexedDevice*>& found, const IndexedDevice& best,
                           const std::map<const IndexedDevice*, const IndexedDevice*>& hidden, std::size_t revision_count,
                           const std::string& path, SourcePos pos) {
    std::vector<const IndexedDevice*> passed;  // hidden revisions above the one taken, one per revision
    std::set<std::uint32_t> seen;
    for (const IndexedDevice* d : found)
        if (hidden.contains(d) && d->revision_no.value_or(0) > best.revision_no.value_or(0) && seen.insert(d->revision_no.value_or(0)).second)
            passed.push_back(d);
    std::stable_sort(passed.begin(), passed.end(),
                     [](const IndexedDevice* a, const IndexedDevice* b) { return a->revision_no.value_or(0) > b->revision_no.value_or(0); });
    const std::string& file = index.file_of(best).path;
    Diagnostic d{Severity::info, "net-device-revision",
                 passed.empty()
                     ? fmt::format("no revision given: using the highest, {}, of {} found, from {}", hex32(best.revision_no), revision_count, file)
                     : fmt::format("no revision given: using {} from {}, the highest of {} found that no current catalogue hides "
                                   "({} higher {} passed over)",
                                   hex32(best.revision_no), file, revision_count, passed.size(), passed.size() == 1 ? "revision is" : "revisions are"),
                 path, pos, {}};
    d.notes.push_back(note_for(index, best, "chosen: " + describe_identity(best)));
    for (const IndexedDevice* p : passed) {
        const IndexedDevice& hider = *hidden.at(p);
        d.notes.push_back(note_for(index, *p,
                                   fmt::format("passed over: {} is a legacy revision: {} (revision {}) at {}:{} lists it as a HideType",
                                               hex32(p->revision_no), hider.type, hex32(hider.revision_no), index.file_of(hider).path,
                                               hider.line)));
    }
    return d;
}

}  // namespace

std::string describe_identity(const IndexedDevice& d) {
    return fmt::format("{} (vendor {}, product code {}, revision {})", d.type.empty() ? std::string("<no Type text>") : d.type,
                       hex32(d.vendor_id), hex32(d.product_code), hex32(d.revision_no));
}

std::string describe_query(const DeviceQuery& q) {
    std::vector<std::string> parts;
    if (q.name) parts.push_back("'" + *q.name + "'");
    if (q.vendor_id) parts.push_back("vendor " + hex32(q.vendor_id));
    if (q.product_code) parts.push_back("product code " + hex32(q.product_code));
    if (q.revision_no) parts.push_back("revision " + hex32(q.revision_no));
    std::string out;
    for (const std::string& p : parts) out += (out.empty() ? "" : ", ") + p;
    return out.empty() ? "a device" : out;
}

Resolution resolve_device(const LibraryIndex& index, const DeviceQuery& q, const std::string& path, SourcePos pos) {
    Resolution result;
    std::vector<const IndexedDevice*> found = candidates(index, q);
    if (found.empty()) {
        result.diagnostics.add(unknown_device(index, q, path, pos));
        return result;
    }
    // Distinct products among the matches: more than one is ambiguous.
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<const IndexedDevice*>> products;
    for (const IndexedDevice* d : found) products[{d->vendor_id.value_or(0), d->product_code.value_or(0)}].push_back(d);
    if (products.size() > 1) {
        Diagnostic d{Severity::error, "net-device-ambiguous",
                     describe_query(q) + " names " + std::to_string(products.size()) +
                         " products; give product_code (and vendor_id) to choose",
                     path, pos, {}};
        for (const auto& [key, devices] : products) d.notes.push_back(note_for(index, *devices.front(), "candidate: " + describe_identity(*devices.front())));
        result.diagnostics.add(std::move(d));
        return result;
    }
    // One product: the highest revision; when several files list it, the first in the order the
    // roots (`esi:`, then --esi) were given, then by path.
    const auto earlier = [&](const IndexedDevice* a, const IndexedDevice* b) {
        const std::size_t ra = index.file_of(*a).root, rb = index.file_of(*b).root;
        return ra != rb ? ra < rb : a->file != b->file ? a->file < b->file : a->ordinal < b->ordinal;
    };
    std::stable_sort(found.begin(), found.end(), earlier);
    std::set<std::uint32_t> revisions;
    for (const IndexedDevice* d : found) revisions.insert(d->revision_no.value_or(0));
    // Without a revision: the highest that no catalogue hides. A revision is only hidden when
    // several are found, so a lone one (or an explicit revision) never costs the scan.
    std::map<const IndexedDevice*, const IndexedDevice*> hidden;
    if (!q.revision_no && revisions.size() > 1) hidden = hidden_by(index, found);
    const IndexedDevice* best = nullptr;
    for (const IndexedDevice* d : found)
        if (!hidden.contains(d) && (!best || d->revision_no.value_or(0) > best->revision_no.value_or(0))) best = d;
    if (!best) {  // every revision hides another: the catalogues do not say which is current
        hidden.clear();
        for (const IndexedDevice* d : found)
            if (!best || d->revision_no.value_or(0) > best->revision_no.value_or(0)) best = d;
    }
    for (const IndexedDevice* d : found)
        if (d != best && d->revision_no == best->revision_no && d->vendor_id == best->vendor_id) result.duplicates.push_back(d);
    if (!q.revision_no && revisions.size() > 1) result.diagnostics.add(revision_choice(index, found, *best, hidden, revisions.size(), path, pos));
    result.device = best;
    return result;
}

FindResult find_devices(const LibraryIndex& index, const DeviceQuery& q) {
    FindResult result;
    result.devices = candidates(index, q);
    if (result.devices.empty()) result.diagnostics.add(unknown_device(index, q, "", {}));
    return result;
}

std::optional<DeviceQuery> parse_find_query(std::string_view text, std::string& error) {
    DeviceQuery q;
    const std::string_view t = trim(text);
    if (t.empty()) {
        error = "empty query";
        return std::nullopt;
    }
    std::vector<std::string_view> parts;
    std::size_t start = 0;
    for (;;) {
        const std::size_t colon = t.find(':', start);
        parts.push_back(t.substr(start, colon == std::string_view::npos ? std::string_view::npos : colon - start));
        if (colon == std::string_view::npos) break;
        start = colon + 1;
    }
    std::vector<std::uint32_t> numbers;
    bool all_numbers = parts.size() <= 3;
    for (std::string_view p : parts) {
        const ParsedNumber n = parse_number(p);
        const auto v = n.ok() && !n.value.negative ? n.value.as_uint64() : std::nullopt;
        if (!v || *v > 0xFFFFFFFFu) {
            all_numbers = false;
            break;
        }
        numbers.push_back(static_cast<std::uint32_t>(*v));
    }
    if (all_numbers && numbers.size() == 1) {
        q.product_code = numbers[0];
    } else if (all_numbers && numbers.size() >= 2) {
        q.vendor_id = numbers[0];
        q.product_code = numbers[1];
        if (numbers.size() == 3) q.revision_no = numbers[2];
    } else if (parts.size() > 1 && std::all_of(parts.begin(), parts.end(), [](std::string_view p) {
                   return !p.empty() && (std::isdigit(static_cast<unsigned char>(p.front())) || p.front() == '#');
               })) {
        error = "'" + std::string(t) + "' is not VENDOR:PRODUCT[:REVISION] (decimal, 0x… or #x… numbers)";
        return std::nullopt;
    } else {
        q.name = std::string(t);
    }
    return q;
}

}  // namespace esi::net
