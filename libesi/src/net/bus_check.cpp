// `esi-net check`: the bus as its master reports it against the ESI library and the network
// (bus_check.hpp). Without a network file each slave is compared with the configuration esi-net
// would build for its identity alone (the ESI's default PDO assignment), one slave at a time, so
// that one unknown device does not stop the check of the others.

#include "esi/net/bus_check.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>

#include "esi/io/read_file.hpp"
#include "esi/load/document.hpp"
#include "esi/net/resolve.hpp"
#include "esi/plural.hpp"
#include "esi/sii/check.hpp"
#include "esi/sii/decode.hpp"
#include "slave_context.hpp"

namespace esi::net {

namespace {

std::string identity_text(const std::optional<std::uint32_t>& v, const std::optional<std::uint32_t>& p, const std::optional<std::uint32_t>& r) {
    auto hex = [](const std::optional<std::uint32_t>& x) { return x ? fmt::format("0x{:08X}", *x) : std::string("?"); };
    return fmt::format("vendor {} product {} revision {}", hex(v), hex(p), hex(r));
}

std::string pdo_list(const std::vector<std::uint32_t>& pdos) {
    std::string out;
    for (std::uint32_t p : pdos) out += (out.empty() ? "" : ", ") + hex_index(p);
    return out.empty() ? "none" : out;
}

std::string entry_list(const std::vector<BusEntry>& entries) {
    std::string out;
    for (const BusEntry& e : entries) out += fmt::format("{}{}:{:02X}/{}", out.empty() ? "" : " ", hex_index(e.index), e.subindex, e.bit_len);
    return out.empty() ? "no entries" : out;
}

class SlaveChecker {
public:
    SlaveChecker(const BusSlave& bus, Severity configured, Diagnostics& findings, std::size_t& count)
        : bus_(bus), configured_(configured), findings_(findings), count_(count) {}

    Diagnostic& finding(Severity severity, const char* rule, SourcePos pos, std::string message) {
        ++count_;
        return findings_.emplace(severity, rule, fmt::format("slave {} ({}): {}", bus_.position, bus_.name.empty() ? "?" : bus_.name, message),
                                 bus_.source, pos.known() ? pos : bus_.pos);
    }

    void compare(const NetworkSlave& expected) {
        for (const BusSm& sm : bus_.sms) {
            const auto it = std::find_if(expected.sms.begin(), expected.sms.end(), [&](const SmSetup& s) { return s.number == sm.number; });
            if (it == expected.sms.end()) {
                finding(Severity::error, "check-sm", sm.pos, fmt::format("SM{} is not a SyncManager of {}", sm.number, expected.device->type.text));
                continue;
            }
            if (sm.start != it->start_address)
                finding(Severity::error, "check-sm", sm.pos,
                        fmt::format("SM{} starts at 0x{:04X}; the ESI says 0x{:04X}", sm.number, sm.start, it->start_address));
            // The watchdog bit (0x40) is the configuration's choice for output SMs; the rest is the ESI's.
            if ((sm.control & ~0x40u) != (it->control_byte & ~0x40u) && !(it->is_virtual && sm.control == 0))
                finding(Severity::error, "check-sm", sm.pos,
                        fmt::format("SM{} has control byte 0x{:02X}; the ESI says 0x{:02X}", sm.number, sm.control, it->control_byte));
            if (sm.length && it->is_process_data() && *sm.length != it->length)
                finding(configured_, "check-sm", sm.pos,
                        fmt::format("SM{} is {} long; the configuration makes it {}", sm.number, esi::counted(*sm.length, "byte"), it->length));
            if (!bus_.has_mapping) continue;
            std::vector<std::uint32_t> bus_pdos, our_pdos;
            for (const BusPdo& p : sm.pdos) bus_pdos.push_back(p.index);
            for (std::size_t pi : it->pdos) our_pdos.push_back(expected.pdos[pi].index);
            if (bus_pdos != our_pdos)
                finding(configured_, "check-pdo-assign", sm.pos,
                        fmt::format("SM{} has PDOs {}; the configuration assigns {}", sm.number, pdo_list(bus_pdos), pdo_list(our_pdos)));
            for (const BusPdo& p : sm.pdos) {
                const auto ours = std::find_if(expected.pdos.begin(), expected.pdos.end(), [&](const ConfiguredPdo& c) { return c.index == p.index; });
                if (ours == expected.pdos.end()) continue;
                std::vector<BusEntry> want;
                for (const ConfiguredEntry& e : ours->entries) want.push_back({e.index, e.is_padding() ? 0 : e.subindex, e.bit_len});
                std::vector<BusEntry> have = p.entries;
                for (BusEntry& e : have)
                    if (e.index == 0) e.subindex = 0;
                if (have != want)
                    finding(configured_, "check-pdo-mapping", sm.pos,
                            fmt::format("PDO {} maps {}; the configuration maps {}", hex_index(p.index), entry_list(have), entry_list(want)));
            }
        }
        for (const BusFmmu& f : bus_.fmmus) {
            if (f.length == 0) continue;
            const auto it = std::find_if(expected.fmmus.begin(), expected.fmmus.end(), [&](const FmmuSetup& e) { return e.physical_start == f.physical_start; });
            if (it == expected.fmmus.end())
                finding(configured_, "check-fmmu", f.pos, fmt::format("FMMU{} maps 0x{:04X}, which no FMMU of the configuration maps", f.number, f.physical_start));
            else if (it->type() != f.type)
                finding(Severity::error, "check-fmmu", f.pos,
                        fmt::format("FMMU{} on 0x{:04X} is type {}; the configuration's is {}", f.number, f.physical_start, f.type, it->type()));
        }
    }

private:
    const BusSlave& bus_;
    Severity configured_;
    Diagnostics& findings_;
    std::size_t& count_;
};

}  // namespace

std::vector<BusSlave> merge_bus_dumps(const std::vector<std::vector<BusSlave>>& dumps) {
    std::vector<BusSlave> out;
    for (const std::vector<BusSlave>& dump : dumps)
        for (const BusSlave& s : dump) {
            auto it = std::find_if(out.begin(), out.end(), [&](const BusSlave& o) { return o.position == s.position; });
            if (it == out.end()) {
                out.push_back(s);
                continue;
            }
            if (!it->vendor_id) it->vendor_id = s.vendor_id;
            if (!it->product_code) it->product_code = s.product_code;
            if (!it->revision) it->revision = s.revision;
            if (it->name.empty()) it->name = s.name;
            if (it->sms.empty() && !s.sms.empty()) {
                it->sms = s.sms;
                it->has_mapping = s.has_mapping;
                it->source = s.source;
                it->pos = s.pos;
            }
            if (it->fmmus.empty()) it->fmmus = s.fmmus;
        }
    std::sort(out.begin(), out.end(), [](const BusSlave& a, const BusSlave& b) { return a.position < b.position; });
    return out;
}

CheckResult check_bus(const std::vector<BusSlave>& bus, const std::vector<SiiDump>& sii, const Network* network, const LibraryIndex& index) {
    CheckResult result;
    for (const BusSlave& b : bus) {
        CheckedSlave cs;
        cs.position = b.position;
        cs.vendor_id = b.vendor_id;
        cs.product_code = b.product_code;
        cs.revision = b.revision;
        cs.name = b.name;
        SlaveChecker checker(b, network ? Severity::error : Severity::warning, result.findings, cs.findings);
        const NetworkSlave* expected = nullptr;
        std::optional<Network> own;
        if (network) {
            if (b.position < network->slaves.size()) {
                expected = &network->slaves[b.position];
                const bool same = (!b.vendor_id || *b.vendor_id == expected->vendor_id) && (!b.product_code || *b.product_code == expected->product_code) &&
                                  (!b.revision || *b.revision == expected->revision);
                if (!same)
                    checker.finding(Severity::error, "check-identity", {},
                                    fmt::format("the bus has {}; the network has '{}' ({}) here", identity_text(b.vendor_id, b.product_code, b.revision),
                                                expected->name, identity_text(expected->vendor_id, expected->product_code, expected->revision)));
            } else {
                checker.finding(Severity::error, "check-identity", {}, fmt::format("the network has {}; this one is not in it", esi::counted(network->slaves.size(), "slave")));
            }
        }
        if (b.vendor_id && b.product_code) {
            Resolution r = resolve_device(index, DeviceQuery{std::nullopt, b.vendor_id, b.product_code, b.revision}, b.source, b.pos);
            if (r.device) {
                cs.esi = fmt::format("{}:{}", index.file_of(*r.device).path, r.device->line);
                if (!network) {
                    NetworkSpec spec;
                    spec.path = b.source;
                    SlaveSpec s;
                    s.name = b.name.empty() ? fmt::format("Slave {}", b.position) : b.name;
                    s.vendor_id = b.vendor_id;
                    s.product_code = b.product_code;
                    s.revision = b.revision;
                    spec.slaves.push_back(std::move(s));
                    BuildResult built = build_network(spec, index);
                    if (built.network) {
                        own = std::move(built.network);
                        expected = &own->slaves.front();
                    }
                }
            } else {
                Diagnostic& d = checker.finding(Severity::error, "check-unknown-device", {},
                                                fmt::format("no ESI of the library describes {}", identity_text(b.vendor_id, b.product_code, b.revision)));
                for (const Diagnostic& e : r.diagnostics)
                    for (const DiagnosticNote& n : e.notes) d.notes.push_back(n);
            }
        }
        if (expected) checker.compare(*expected);
        result.slaves.push_back(std::move(cs));
    }

    for (const SiiDump& dump : sii) {
        const sii::DecodedImage decoded = sii::decode_image(dump.bytes);
        const sii::Header& h = decoded.image.header;
        auto slave = std::find_if(result.slaves.begin(), result.slaves.end(), [&](const CheckedSlave& s) { return s.position == dump.position; });
        const Resolution r = resolve_device(index, DeviceQuery{std::nullopt, h.vendor_id, h.product_code, h.revision_no}, dump.path, {});
        std::size_t dummy = 0;
        std::size_t& count = slave != result.slaves.end() ? slave->findings : dummy;
        auto emit = [&](Severity s, std::string message) -> Diagnostic& {
            ++count;
            return result.findings.emplace(s, "check-sii", fmt::format("slave {}: {}", dump.position, message), dump.path, {});
        };
        if (!r.device) {
            emit(Severity::error, "its SII names " + identity_text(h.vendor_id, h.product_code, h.revision_no) + ", which no ESI of the library describes");
            continue;
        }
        const std::string& file = index.file_of(*r.device).path;
        std::string error;
        const std::optional<std::string> text = read_file_bytes(file, error);
        if (!text) {
            emit(Severity::error, file + ": " + error);
            continue;
        }
        const LoadedDocument loaded = load_document(*text, file);
        if (!loaded.usable()) {
            emit(Severity::error, "cannot read " + file);
            continue;
        }
        const sii::ImageDevice device = sii::find_device_for_image(*loaded.document, h);
        if (!device.device) continue;
        const Diagnostics differences = sii::check_image(*device.info, *device.device, decoded, file, dump.path);
        if (differences.empty()) continue;
        Diagnostic& d = emit(differences.has_errors() ? Severity::error : Severity::warning,
                             fmt::format("its SII differs from the ESI ({}) in {} place{}", device.device->type.text, differences.size(),
                                         differences.size() == 1 ? "" : "s"));
        for (const Diagnostic& e : differences) d.notes.push_back({e.path, e.pos, e.message + " [" + e.rule + "]"});
    }
    return result;
}

std::string check_result_json(const CheckResult& result) {
    nlohmann::ordered_json j;
    j["slaves"] = nlohmann::ordered_json::array();
    for (const CheckedSlave& s : result.slaves) {
        nlohmann::ordered_json o;
        o["position"] = s.position;
        o["name"] = s.name;
        o["vendor_id"] = s.vendor_id ? nlohmann::ordered_json(*s.vendor_id) : nlohmann::ordered_json();
        o["product_code"] = s.product_code ? nlohmann::ordered_json(*s.product_code) : nlohmann::ordered_json();
        o["revision"] = s.revision ? nlohmann::ordered_json(*s.revision) : nlohmann::ordered_json();
        o["esi"] = s.esi.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(s.esi);
        o["findings"] = s.findings;
        j["slaves"].push_back(std::move(o));
    }
    j["findings"] = nlohmann::ordered_json::array();
    Diagnostics sorted = result.findings;
    sorted.sort();
    for (const Diagnostic& d : sorted) {
        nlohmann::ordered_json o;
        o["rule"] = d.rule;
        o["severity"] = d.severity == Severity::error ? "error" : d.severity == Severity::warning ? "warning" : "info";
        o["path"] = d.path;
        o["line"] = d.pos.line;
        o["message"] = d.message;
        nlohmann::ordered_json notes = nlohmann::ordered_json::array();
        for (const DiagnosticNote& n : d.notes) notes.push_back({{"path", n.path}, {"line", n.pos.line}, {"message", n.message}});
        o["notes"] = std::move(notes);
        j["findings"].push_back(std::move(o));
    }
    return j.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

}  // namespace esi::net
