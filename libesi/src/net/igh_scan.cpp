// `ethercat slaves -v` (IgH EtherCAT master tool) -> NETWORK.yaml.

#include "esi/net/igh_scan.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <fmt/format.h>

#include "esi/net/network_spec.hpp"
#include "esi/net/resolve.hpp"
#include "esi/number.hpp"
#include "esi/yaml/quote.hpp"

namespace esi::net {

namespace {

std::optional<std::uint32_t> hex_value(std::string_view text) {
    const ParsedNumber n = parse_number(trim(text));
    if (!n.ok() || n.value.negative || n.value.magnitude > 0xFFFFFFFFu) return std::nullopt;
    return static_cast<std::uint32_t>(n.value.magnitude);
}

// "  Key:   value" -> value, when the trimmed line starts with `key` and a colon.
std::optional<std::string_view> field(std::string_view line, std::string_view key) {
    const std::string_view t = trim(line);
    if (!t.starts_with(key) || t.size() <= key.size() || t[key.size()] != ':') return std::nullopt;
    return trim(t.substr(key.size() + 1));
}

// "=== Master m, Slave n ===": m and n decimal and within 32 bits (sscanf's %u would wrap
// 4294967296 to 0 and take "-1" for 4294967295).
bool block_header(std::string_view line, std::uint32_t& master, std::uint32_t& slave) {
    auto number = [](std::string_view& rest, std::uint32_t& out) {
        const auto [end, ec] = std::from_chars(rest.data(), rest.data() + rest.size(), out);
        if (ec != std::errc{} || end == rest.data()) return false;
        rest.remove_prefix(static_cast<std::size_t>(end - rest.data()));
        return true;
    };
    std::string_view rest = line.substr(std::string_view("=== Master ").size());
    if (!number(rest, master) || !rest.starts_with(", Slave ")) return false;
    rest.remove_prefix(std::string_view(", Slave ").size());
    if (!number(rest, slave)) return false;
    return trim(rest) == "===";
}

// Outside text (a device name from the bus, a Type text from an ESI) goes into a comment only
// as a quoted scalar in printable ASCII: nothing it holds can end the comment's line, whatever
// the reader takes for a line break (esi/yaml/quote.hpp).
std::string comment_text(std::string_view text) { return yaml::double_quoted(text, true).text; }

}  // namespace

IghScan parse_igh_slaves(std::string_view text, const std::string& path) {
    IghScan scan;
    scan.path = path;
    std::optional<ScannedSlave> current;
    std::optional<std::uint32_t> first_master;
    std::uint32_t line_number = 0;
    bool other_master = false;
    std::optional<std::uint32_t> last_position;
    // A last line without its newline was cut: its value may be cut too (0x00001002 read as 0x0010).
    if (!text.empty() && text.back() != '\n') {
        const std::size_t lines = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 1;
        scan.diagnostics.emplace(Severity::error, "net-scan", "the scan ends in the middle of a line; it was cut short", path,
                                 SourcePos{static_cast<std::uint32_t>(lines), 1});
    }
    auto finish = [&]() {
        if (!current) return;
        if (!current->vendor_id || !current->product_code)
            scan.diagnostics.emplace(Severity::error, "net-scan", "this slave's block has no 'Vendor Id' or 'Product code' line", path, current->pos);
        else if (!current->revision)
            // `ethercat slaves -v` always prints the revision: a block without it was cut.
            scan.diagnostics.emplace(Severity::error, "net-scan", "this slave's block has no 'Revision number' line; is the scan cut short?", path,
                                     current->pos);
        else if (current->master == *first_master) scan.slaves.push_back(*current);
        else other_master = true;
        current.reset();
    };
    while (!text.empty()) {
        const std::size_t nl = text.find('\n');
        std::string_view line = text.substr(0, nl);
        text.remove_prefix(nl == std::string_view::npos ? text.size() : nl + 1);
        ++line_number;
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        std::uint32_t master = 0, slave = 0;
        if (line.starts_with("=== Master ")) {
            if (!block_header(line, master, slave)) {
                // Taken for an ordinary line, its block's Identity lines would overwrite the
                // block before it.
                scan.diagnostics.emplace(Severity::error, "net-scan",
                                         fmt::format("'{}' is not a block header '=== Master m, Slave n ===' (m, n: 32-bit decimal)",
                                                     excerpt(line)),
                                         path, SourcePos{line_number, 1});
                finish();
                continue;
            }
            {
                finish();
                if (!first_master) first_master = master;
                if (master == *first_master) {
                    // The network is the bus in position order: a position twice or out of order
                    // is not one scan of one bus.
                    if (last_position && slave <= *last_position)
                        scan.diagnostics.emplace(Severity::error, "net-scan",
                                                 fmt::format("slave position {} after position {}: positions must rise, each once", slave,
                                                             *last_position),
                                                 path, SourcePos{line_number, 1});
                    last_position = slave;
                }
                current = ScannedSlave{};
                current->master = master;
                current->position = slave;
                current->pos = SourcePos{line_number, 1};
                continue;
            }
        }
        if (!current) continue;
        const SourcePos pos{line_number, 1};
        auto number = [&](std::string_view value, std::optional<std::uint32_t>& out, const char* what) {
            out = hex_value(value);
            if (!out) scan.diagnostics.emplace(Severity::error, "net-scan", fmt::format("'{}' is not a {} number", value, what), path, pos);
        };
        if (auto v = field(line, "Vendor Id")) number(*v, current->vendor_id, "vendor id");
        else if (auto v = field(line, "Product code")) number(*v, current->product_code, "product code");
        else if (auto v = field(line, "Revision number")) number(*v, current->revision, "revision");
        else if (auto v = field(line, "Serial number")) number(*v, current->serial, "serial");
        else if (auto v = field(line, "Device name")) current->device_name = std::string(*v);
        else if (auto v = field(line, "Order number")) current->order_number = std::string(*v);
        else if (auto v = field(line, "Alias")) {
            std::optional<std::uint32_t> alias;
            number(*v, alias, "alias");
            if (alias && *alias > 0xFFFF)
                scan.diagnostics.emplace(Severity::error, "net-scan", fmt::format("alias {} does not fit the 16-bit station alias", *alias), path, pos);
            else if (alias && *alias > 0) current->alias = static_cast<std::uint16_t>(*alias);
        }
    }
    finish();
    if (scan.slaves.size() > max_network_slaves)
        scan.diagnostics.emplace(Severity::error, "net-too-many-slaves",
                                 fmt::format("{} slaves; an EtherCAT segment addresses at most {} (station addresses 1001 to 65535)",
                                             scan.slaves.size(), max_network_slaves),
                                 path, {});
    if (scan.slaves.empty() && !scan.diagnostics.has_errors())
        scan.diagnostics.emplace(Severity::error, "net-scan", "no '=== Master m, Slave n ===' block: not the output of `ethercat slaves -v`", path, {});
    if (other_master)
        scan.diagnostics.emplace(Severity::warning, "net-scan",
                                 fmt::format("the scan shows several masters; the network takes master {}'s slaves", first_master.value_or(0)), path, {});
    return scan;
}

InitResult network_from_scan(const IghScan& scan, const LibraryIndex* index, const InitOptions& options) {
    InitResult result;
    std::string& y = result.yaml;
    y += fmt::format("# A network of {} slave{} from `ethercat slaves -v`; esi-net build NETWORK.yaml -o OUTDIR\n", scan.slaves.size(),
                     scan.slaves.size() == 1 ? "" : "s");
    if (!options.esi.empty()) {
        y += "esi:\n";
        for (const std::string& e : options.esi) {
            const yaml::QuotedText quoted = yaml::double_quoted(e);
            if (!quoted.ok)
                result.diagnostics.emplace(Severity::error, "net-path", "the ESI path is not UTF-8 text; YAML cannot hold it", e, {});
            y += "  - " + quoted.text + "\n";
        }
    } else {
        y += "esi: []  # ESI files or folders to build from (or --esi)\n";
    }
    y += fmt::format("master: {{ name: Master {}, cycle_time_us: {} }}\n", scan.slaves.empty() ? 0 : scan.slaves.front().master,
                     options.cycle_time_us);
    y += "slaves:\n";
    for (std::size_t i = 0; i < scan.slaves.size(); ++i) {
        const ScannedSlave& s = scan.slaves[i];
        y += fmt::format("  - name: D{}", i + 1);
        if (!s.device_name.empty()) y += "  # scanned as " + comment_text(s.device_name);
        y += "\n";
        y += fmt::format("    vendor_id: 0x{:08X}\n", s.vendor_id.value_or(0));
        y += fmt::format("    product_code: 0x{:08X}\n", s.product_code.value_or(0));
        if (s.revision) y += fmt::format("    revision: 0x{:08X}\n", *s.revision);
        if (s.alias) y += fmt::format("    alias: {}\n", *s.alias);
        if (!index) continue;
        const DeviceQuery query{std::nullopt, s.vendor_id, s.product_code, s.revision};
        const FindResult found = find_devices(*index, query);
        if (found.devices.empty()) {
            y += "    # no ESI file in the library describes this device\n";
            Diagnostic d{Severity::warning, "net-scan-unknown",
                         fmt::format("slave {} ({}): {}", s.position, s.device_name, found.diagnostics.items().front().message), scan.path, s.pos, {}};
            d.notes = found.diagnostics.items().front().notes;
            result.diagnostics.add(std::move(d));
        } else {
            const IndexedDevice& d = *found.devices.front();
            y += fmt::format("    # ESI: {} in {}\n", comment_text(d.type), comment_text(index->file_of(d).path));
        }
    }
    return result;
}

}  // namespace esi::net
