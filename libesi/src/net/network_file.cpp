// NETWORK.yaml -> NetworkSpec, through the same YAML tree and typed reader as device sources.

#include <algorithm>
#include <set>

#include "esi/ethercat/al_state.hpp"
#include "esi/io/read_file.hpp"
#include "esi/net/network_keys.hpp"
#include "esi/net/network_spec.hpp"
#include "esi/number.hpp"
#include "esi/yaml/limits.hpp"
#include "esi/yaml/reader.hpp"
#include "esi/yaml/tree.hpp"
#include "ros2_interfaces_spec.hpp"

namespace esi::net {

namespace {

using yaml::Fields;
using yaml::Node;

// What an ENI InitCmd's Transition may hold (ETG.2100 schema): the state machine's transitions
// and the three "stay" transitions II, PP and SS.
const std::vector<std::string_view>& valid_transitions() {
    static const std::vector<std::string_view> names = [] {
        const std::span<const std::string_view> machine = ethercat::state_machine_transition_names();
        std::vector<std::string_view> out(machine.begin(), machine.end());
        out.insert(out.end(), {"II", "PP", "SS"});
        return out;
    }();
    return names;
}

class NetworkParser {
public:
    NetworkParser(const std::string& path, Diagnostics& diagnostics) : reader_(path, diagnostics) {}

    std::optional<Fields> mapping(const Node& node, NetworkContext context, std::string_view what) {
        return reader_.mapping(node, network_keys_of(context).keys, what);
    }

    void root(const Node& node, NetworkSpec& spec) {
        const auto fields = mapping(node, NetworkContext::root, "the network");
        if (!fields) return;
        if (const Node* n = fields->find("esi")) {
            spec.esi_pos = n->pos();
            for (const std::string& s : strings(*n, "esi")) spec.esi.push_back(s);
        }
        if (const Node* n = fields->find("master")) master(*n, spec.master);
        const Node* slaves_node = fields->find("slaves");
        if (!slaves_node) {
            reader_.error(fields->pos(), "yaml-missing-key", "the network has no 'slaves'");
            return;
        }
        const auto items = reader_.sequence(*slaves_node, "slaves");
        if (!items) return;
        if (items->size() > max_network_slaves) {
            reader_.error(*slaves_node, "net-too-many-slaves",
                          std::to_string(items->size()) + " slaves; an EtherCAT segment addresses at most " +
                              std::to_string(max_network_slaves) + " (station addresses 1001 to 65535)");
            return;
        }
        std::set<std::string> names;
        for (const Node& item : *items) {
            SlaveSpec s;
            slave(item, s);
            if (!s.name.empty() && !names.insert(s.name).second)
                reader_.error(s.pos, "net-duplicate-name", "two slaves are named '" + s.name + "'; names must be unique");
            spec.slaves.push_back(std::move(s));
        }
    }

private:
    std::vector<std::string> strings(const Node& node, std::string_view what) {
        std::vector<std::string> out;
        if (node.IsScalar()) {
            out.push_back(node.Scalar());
        } else if (const auto items = reader_.sequence(node, what)) {
            for (const Node& item : *items)
                if (const auto text = reader_.text(item, what)) out.push_back(*text);
        }
        return out;
    }

    void master(const Node& node, MasterSpec& m) {
        m.pos = node.pos();
        const auto f = mapping(node, NetworkContext::master, "master");
        if (!f) return;
        if (const Node* n = f->find("name"))
            if (auto t = reader_.text(*n, "name")) m.name = *t;
        if (const Node* n = f->find("cycle_time_us"))
            if (auto v = reader_.integer<std::uint32_t>(*n, "cycle_time_us", 1, 10'000'000)) m.cycle_time_us = *v;
        if (const Node* n = f->find("dc"))
            if (auto v = reader_.boolean(*n, "dc")) m.dc = *v;
        if (const Node* n = f->find("source_mac")) {
            if (auto v = reader_.hex(*n, "source_mac")) {
                if (v->byte_length() != 6) reader_.error(*n, "yaml-type", "'source_mac' must be 6 bytes (12 hex digits)");
                else m.source_mac = v->text;
            }
        }
        if (const Node* n = f->find("lcec_fork")) {
            if (auto t = reader_.text(*n, "lcec_fork")) {
                if (*t == "linuxcnc-ethercat") m.lcec_fork = LcecFork::linuxcnc_ethercat;
                else if (*t == "sittner") m.lcec_fork = LcecFork::sittner;
                else reader_.error(*n, "yaml-type", "'lcec_fork' must be 'linuxcnc-ethercat' or 'sittner'");
            }
        }
    }

    // "0x607A:0x00:32": index, sub-index and bit length, each decimal, 0x… or #x….
    std::optional<PdoEntrySpec> entry(const Node& node) {
        const auto text = reader_.text(node, "pdo_entries");
        if (!text) return std::nullopt;
        std::vector<std::string_view> parts;
        std::string_view rest = *text;
        for (std::size_t colon; (colon = rest.find(':')) != std::string_view::npos; rest.remove_prefix(colon + 1))
            parts.push_back(rest.substr(0, colon));
        parts.push_back(rest);
        PdoEntrySpec e;
        e.pos = node.pos();
        std::uint64_t values[3] = {};
        // The mapping value (CiA 301) holds the bit length in 8 bits.
        const std::uint64_t maxima[3] = {0xFFFF, 0xFF, 0xFF};
        bool ok = parts.size() == 3;
        for (std::size_t i = 0; ok && i < 3; ++i) {
            const ParsedNumber n = parse_number(parts[i]);
            const auto v = n.ok() && !n.value.negative ? n.value.as_uint64() : std::nullopt;
            ok = v && *v <= maxima[i];
            if (ok) values[i] = *v;
        }
        if (!ok || values[2] == 0) {
            reader_.error(node, "yaml-type",
                          "a PDO entry is INDEX:SUBINDEX:BITLEN (e.g. 0x607A:0x00:32; index 0 is padding; at most 255 bits), not '" + *text + "'");
            return std::nullopt;
        }
        e.index = static_cast<std::uint32_t>(values[0]);
        e.subindex = static_cast<std::uint32_t>(values[1]);
        e.bit_len = static_cast<std::uint32_t>(values[2]);
        return e;
    }

    void pdo_entries(const Node& node, SlaveSpec& s) {
        if (!node.IsMap()) {
            reader_.error(node, "yaml-type", "'pdo_entries' must map PDO indices to lists of INDEX:SUBINDEX:BITLEN");
            return;
        }
        const Fields fields(node);
        std::set<std::uint32_t> seen;
        for (const auto& item : fields.items()) {
            const auto pdo = reader_.integer<std::uint32_t>(item.key_node, "a PDO index", 0x1600, 0x1BFF);
            if (!pdo) continue;
            PdoEntriesSpec p;
            p.pdo = *pdo;
            p.pos = item.key_node.pos();
            if (!seen.insert(*pdo).second) {
                reader_.error(item.key_node, "yaml-duplicate-key", "PDO " + format_hex(*pdo, 4).substr(2) + " is listed twice");
                continue;
            }
            if (item.value.IsNull()) {  // an empty PDO
                s.pdo_entries.push_back(std::move(p));
                continue;
            }
            const auto entries = reader_.sequence(item.value, "pdo_entries");
            if (!entries) continue;
            for (const Node& e : *entries)
                if (auto parsed = entry(e)) p.entries.push_back(*parsed);
            s.pdo_entries.push_back(std::move(p));
        }
    }

    void modules(const Node& node, SlaveSpec& s) {
        s.modules_pos = node.pos();
        const auto items = reader_.sequence(node, "modules");
        if (!items) return;
        std::vector<ModuleSpec> out;
        for (const Node& item : *items) {
            ModuleSpec m;
            m.pos = item.pos();
            if (item.IsNull()) {
                m.empty = true;
            } else if (item.IsMap()) {
                const auto f = mapping(item, NetworkContext::module, "a module");
                if (!f) continue;
                if (const Node* slot = f->find("slot")) {
                    if (slot->IsScalar() && parse_number(slot->Scalar()).ok()) m.slot = reader_.integer<std::uint32_t>(*slot, "slot", 0, 4095);
                    else m.slot_name = reader_.text(*slot, "slot");
                }
                const Node* module = f->find("module");
                if (!module || module->IsNull()) m.empty = true;
                else module_ref(*module, m);
            } else {
                module_ref(item, m);
            }
            out.push_back(std::move(m));
        }
        s.modules = std::move(out);
    }

    void module_ref(const Node& node, ModuleSpec& m) {
        if (!node.IsScalar()) {
            reader_.error(node, "yaml-type", "a module is its Type text or its ModuleIdent");
            return;
        }
        const ParsedNumber n = parse_number(node.Scalar());
        if (!node.quoted() && n.ok()) m.ident = reader_.integer<std::uint32_t>(node, "module");
        else m.type = node.Scalar();
    }

    void sdo(const Node& node, SdoSpec& out) {
        out.pos = node.pos();
        const auto f = mapping(node, NetworkContext::sdo, "an SDO");
        if (!f) return;
        if (!reader_.require(*f, "index", "an SDO")) return;
        if (auto v = reader_.integer<std::uint32_t>(*f->find("index"), "index", 0, 0xFFFF)) out.index = *v;
        if (const Node* n = f->find("subindex"))
            if (auto v = reader_.integer<std::uint32_t>(*n, "subindex", 0, 0xFF)) out.subindex = *v;
        if (const Node* n = f->find("value")) out.value = reader_.scalar_value(*n, "value");
        if (const Node* n = f->find("type")) out.type = reader_.text(*n, "type");
        if (const Node* n = f->find("data")) {
            if (auto hex = reader_.hex(*n, "data")) {
                out.data = hex->bytes();
                if (out.data && out.data->empty())
                    reader_.error(*n, "net-sdo-value", "'data' holds no bytes; an SDO download writes at least one");
            }
        }
        if (f->has("value") == f->has("data"))
            reader_.error(node, "net-sdo-value", "an SDO needs either 'value' (typed) or 'data' (raw hex bytes)");
        if (const Node* n = f->find("transition")) {
            out.transition_pos = n->pos();
            const std::vector<std::string> given = strings(*n, "transition");
            for (const std::string& t : given) {
                if (std::find(valid_transitions().begin(), valid_transitions().end(), t) == valid_transitions().end()) {
                    reader_.error(*n, "net-transition", "'" + t + "' is not a state transition (IP, PS, SO, SP, OS, OP, SI, OI, PI …)" +
                                                            yaml::did_you_mean(t, valid_transitions()));
                    continue;
                }
                out.transitions.push_back(t);
            }
            if (given.empty())
                reader_.error(*n, "net-transition", "'transition' lists no state transition; the SDO would never be sent (default: PS)");
        } else {
            out.transitions = {"PS"};
        }
        if (const Node* n = f->find("complete_access"))
            if (auto v = reader_.boolean(*n, "complete_access")) out.complete_access = *v;
        if (const Node* n = f->find("comment")) out.comment = reader_.text(*n, "comment");
    }

    void slave(const Node& node, SlaveSpec& s) {
        s.pos = node.pos();
        const auto f = mapping(node, NetworkContext::slave, "a slave");
        if (!f) return;
        if (const Node* n = f->find("name"))
            if (auto t = reader_.text(*n, "name")) s.name = *t;
        s.device_pos = s.pos;
        if (const Node* n = f->find("device")) {
            s.device = reader_.text(*n, "device");
            s.device_pos = n->pos();
        }
        if (const Node* n = f->find("vendor_id")) s.vendor_id = reader_.integer<std::uint32_t>(*n, "vendor_id");
        if (const Node* n = f->find("product_code")) {
            s.product_code = reader_.integer<std::uint32_t>(*n, "product_code");
            if (!s.device) s.device_pos = n->pos();
        }
        if (const Node* n = f->find("revision")) s.revision = reader_.integer<std::uint32_t>(*n, "revision");
        if (!f->has("device") && !f->has("product_code"))
            reader_.error(node, "yaml-missing-key", "a slave needs 'device' (its Type text) or 'product_code'");
        if (const Node* n = f->find("esi_file")) {
            s.esi_file = reader_.text(*n, "esi_file");
            s.esi_file_pos = n->pos();
        }
        if (const Node* n = f->find("alias")) s.alias = reader_.integer<std::uint16_t>(*n, "alias");
        if (const Node* n = f->find("pdos")) {
            s.pdos_pos = n->pos();
            if (const auto items = reader_.sequence(*n, "pdos")) {
                std::vector<PdoRef> refs;
                for (const Node& item : *items)
                    if (auto v = reader_.integer<std::uint32_t>(item, "a PDO index", 0x1600, 0x1BFF)) refs.push_back({*v, item.pos()});
                s.pdos = std::move(refs);
            }
        }
        if (const Node* n = f->find("pdo_mapping")) {
            s.pdo_mapping = reader_.text(*n, "pdo_mapping");
            s.pdo_mapping_pos = n->pos();
            if (f->has("pdos")) reader_.error(*n, "net-pdo-selection", "give either 'pdos' or 'pdo_mapping', not both");
        }
        if (const Node* n = f->find("pdo_entries")) pdo_entries(*n, s);
        if (const Node* n = f->find("dc")) {
            s.dc = reader_.text(*n, "dc");
            s.dc_pos = n->pos();
        }
        if (const Node* n = f->find("modules")) modules(*n, s);
        if (const Node* n = f->find("sdos")) {
            if (const auto items = reader_.sequence(*n, "sdos")) {
                for (const Node& item : *items) {
                    SdoSpec sdo_spec;
                    sdo(item, sdo_spec);
                    s.sdos.push_back(std::move(sdo_spec));
                }
            }
        }
        if (const Node* n = f->find("limits")) s.limits = yaml::read_limits(reader_, *n);
        if (const Node* n = f->find("ros2_interfaces")) s.ros2_interfaces = read_ros2_interfaces(reader_, *n);
        if (const Node* n = f->find("force_entries")) s.force_entries = read_forced_entries(reader_, *n);
        if (const Node* n = f->find("previous_slave")) {
            s.previous_slave = reader_.text(*n, "previous_slave");
            s.previous_slave_pos = n->pos();
        }
        if (const Node* n = f->find("previous_port")) {
            s.previous_port = reader_.text(*n, "previous_port");
            s.previous_port_pos = n->pos();
        }
    }

    yaml::Reader reader_;
};

}  // namespace

NetworkFileResult read_network_text(std::string_view text, const std::string& path) {
    NetworkFileResult result;
    bool empty = false;
    const std::unique_ptr<yaml::Tree> tree = yaml::Tree::parse(text, path, yaml::TreeLimits{}, result.diagnostics, empty);
    if (!tree) {
        if (empty) result.diagnostics.emplace(Severity::error, "yaml-empty", "the network file is empty", path, {});
        return result;
    }
    NetworkSpec spec;
    spec.path = path;
    NetworkParser parser(path, result.diagnostics);
    parser.root(yaml::Node(tree->root()), spec);
    if (!result.diagnostics.has_errors()) result.spec = std::move(spec);
    return result;
}

NetworkFileResult read_network_file(const std::string& path) {
    std::string error;
    const std::optional<std::string> bytes = read_file_bytes(path, error);
    if (!bytes) {
        NetworkFileResult result;
        result.diagnostics.emplace(Severity::error, "io-error", "cannot read the network file: " + error, path, {});
        return result;
    }
    return read_network_text(*bytes, path);
}

}  // namespace esi::net
