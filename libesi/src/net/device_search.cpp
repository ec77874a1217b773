#include "esi/net/device_search.hpp"

#include <algorithm>
#include <cctype>
#include <functional>
#include <map>
#include <tuple>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "esi/number.hpp"
#include "esi/plural.hpp"
#include "esi/text_distance.hpp"

namespace esi::net {

namespace {

std::string folded(std::string_view text) {
    std::string out(trim(text));
    std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return out;
}

std::optional<MatchRank> rank_by_name(const IndexedDevice& d, const std::string& wanted) {
    const std::string type = folded(d.type);
    if (type == wanted) return MatchRank::exact;
    if (type.starts_with(wanted)) return MatchRank::prefix;
    if (type.find(wanted) != std::string::npos || folded(d.name).find(wanted) != std::string::npos) return MatchRank::substring;
    return std::nullopt;
}

// A typo's worth of edits: one per four characters, at least one.
bool close_by_edits(const IndexedDevice& d, const std::string& wanted) {
    const std::string type = folded(d.type);
    const std::size_t limit = std::max<std::size_t>(1, wanted.size() / 4);
    const std::size_t gap = type.size() > wanted.size() ? type.size() - wanted.size() : wanted.size() - type.size();
    return gap <= limit && edit_distance(wanted, type) <= limit;
}

bool identity_matches(const IndexedDevice& d, const DeviceQuery& q) {
    if (q.vendor_id && d.vendor_id != q.vendor_id) return false;
    if (q.product_code && d.product_code != q.product_code) return false;
    if (q.revision_no && d.revision_no != q.revision_no) return false;
    return true;
}

// A vendor given as a number is an id; as text, part of the Vendor/Name.
std::function<bool(const IndexedDevice&)> vendor_filter(const std::optional<std::string>& vendor) {
    if (!vendor) return [](const IndexedDevice&) { return true; };
    const ParsedNumber n = parse_number(*vendor);
    const auto id = n.ok() && !n.value.negative ? n.value.as_uint64() : std::nullopt;
    if (id && *id <= 0xFFFFFFFFu) {
        const std::uint32_t wanted = static_cast<std::uint32_t>(*id);
        return [wanted](const IndexedDevice& d) { return d.vendor_id == wanted; };
    }
    const std::string wanted = folded(*vendor);
    return [wanted](const IndexedDevice& d) { return folded(d.vendor_name).find(wanted) != std::string::npos; };
}

// Which matches some device of the same vendor hides (HideType): the first such device in index order.
void mark_hidden(const LibraryIndex& index, std::vector<DeviceMatch>& matches) {
    std::map<std::tuple<std::optional<std::uint32_t>, std::uint32_t, std::uint32_t>, const IndexedDevice*> hiders;
    for (const IndexedDevice& d : index.devices)
        for (const HiddenIdentity& h : d.hides)
            if (h.product_code && h.revision_no && !(h.product_code == d.product_code && h.revision_no == d.revision_no))
                hiders.emplace(std::tuple{d.vendor_id, *h.product_code, *h.revision_no}, &d);
    if (hiders.empty()) return;
    for (DeviceMatch& m : matches) {
        if (!m.device->product_code || !m.device->revision_no) continue;
        if (const auto it = hiders.find({m.device->vendor_id, *m.device->product_code, *m.device->revision_no}); it != hiders.end())
            m.hidden_by = it->second;
    }
}

std::string hex32(std::optional<std::uint32_t> v) { return v ? fmt::format("0x{:08X}", *v) : std::string(); }

}  // namespace

const char* match_rank_name(MatchRank rank) {
    switch (rank) {
        case MatchRank::exact: return "exact";
        case MatchRank::prefix: return "prefix";
        case MatchRank::substring: return "substring";
        case MatchRank::fuzzy: return "fuzzy";
        case MatchRank::vendor: return "vendor";
    }
    return "exact";
}

DeviceSearch search_devices(const LibraryIndex& index, const std::optional<DeviceQuery>& query, const std::optional<std::string>& vendor) {
    DeviceSearch result;
    const auto of_vendor = vendor_filter(vendor);
    const std::string wanted = query && query->name ? folded(*query->name) : std::string();
    for (const IndexedDevice& d : index.devices) {
        if (!of_vendor(d)) continue;
        if (!query) {
            result.matches.push_back({&d, MatchRank::vendor});
            continue;
        }
        if (!identity_matches(d, *query)) continue;
        if (!query->name) {
            result.matches.push_back({&d, MatchRank::exact});
        } else if (const auto rank = rank_by_name(d, wanted)) {
            result.matches.push_back({&d, *rank});
        }
    }
    if (result.matches.empty() && query && query->name) {
        for (const IndexedDevice& d : index.devices)
            if (of_vendor(d) && identity_matches(d, *query) && close_by_edits(d, wanted)) result.matches.push_back({&d, MatchRank::fuzzy});
    }
    mark_hidden(index, result.matches);
    std::stable_sort(result.matches.begin(), result.matches.end(), [](const DeviceMatch& a, const DeviceMatch& b) {
        if (a.rank != b.rank) return a.rank < b.rank;
        if (a.device->type != b.device->type) return a.device->type < b.device->type;
        if ((a.hidden_by == nullptr) != (b.hidden_by == nullptr)) return a.hidden_by == nullptr;
        return a.device->revision_no.value_or(0) > b.device->revision_no.value_or(0);
    });
    if (result.matches.empty()) {
        if (query) {
            // The resolver's error: the nearest identities and where it looked.
            result.diagnostics = find_devices(index, *query).diagnostics;
            if (vendor && !result.diagnostics.has_errors())
                result.diagnostics.emplace(Severity::error, "net-device-unknown",
                                           describe_query(*query) + " matches no device of a vendor '" + *vendor + "'", "", SourcePos{});
        } else {
            result.diagnostics.emplace(Severity::error, "net-device-unknown",
                                       fmt::format("no device of a vendor '{}' in the library ({}, {})", vendor.value_or(""),
                                                   esi::counted(index.files.size(), "file"), esi::counted(index.devices.size(), "device")),
                                       "", SourcePos{});
        }
    }
    return result;
}

std::string device_search_text(const LibraryIndex& index, const DeviceSearch& search) {
    std::string out;
    for (const DeviceMatch& m : search.matches) {
        const IndexedDevice& d = *m.device;
        const std::string legacy =
            m.hidden_by ? fmt::format("; hidden by {} revision {}", m.hidden_by->type, hex32(m.hidden_by->revision_no)) : "";
        out += fmt::format("{}:{}:{}: {}{} [{}{}]\n", index.file_of(d).path, d.line, d.column, describe_identity(d),
                           d.name.empty() || d.name == d.type ? "" : " — " + d.name, match_rank_name(m.rank), legacy);
    }
    return out;
}

std::string device_search_json(const LibraryIndex& index, const DeviceSearch& search) {
    nlohmann::ordered_json devices = nlohmann::ordered_json::array();
    for (const DeviceMatch& m : search.matches) {
        const IndexedDevice& d = *m.device;
        nlohmann::ordered_json o;
        o["match"] = match_rank_name(m.rank);
        o["type"] = d.type;
        o["name"] = d.name;
        o["vendor"] = d.vendor_name;
        o["vendor_id"] = hex32(d.vendor_id);
        o["product_code"] = hex32(d.product_code);
        o["revision"] = hex32(d.revision_no);
        o["file"] = index.file_of(d).path;
        o["line"] = d.line;
        o["column"] = d.column;
        if (m.hidden_by) {
            nlohmann::ordered_json h;
            h["type"] = m.hidden_by->type;
            h["revision"] = hex32(m.hidden_by->revision_no);
            h["file"] = index.file_of(*m.hidden_by).path;
            h["line"] = m.hidden_by->line;
            o["hidden_by"] = std::move(h);
        }
        devices.push_back(std::move(o));
    }
    nlohmann::ordered_json j;
    j["devices"] = std::move(devices);
    return j.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

}  // namespace esi::net
