// `init --from-eni`: the ENI's configuration as the few lines of NETWORK.yaml the ESI does not
// imply (eni_import.hpp). Each pass builds the network so far against the library and adds
// what still differs from the ENI: the PDO assignment, then the entries of remapped PDOs and the
// DC op mode, then the CoE start-up commands. The YAML written is read and built once more, so
// what the user gets is known to build.

#include "esi/net/eni_import.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "eni_facts.hpp"
#include "ros2_interfaces_spec.hpp"
#include "esi/net/network.hpp"
#include "esi/net/resolve.hpp"
#include "slave_context.hpp"
#include "yaml_scalar.hpp"

namespace esi::net {

namespace {

struct ImportedSlave {
    const EniSlaveFacts* eni = nullptr;
    bool known = false;
    SlaveSpec spec;
    std::vector<std::string> notes;  // comments written above the slave
};

// The same command on the bus: what it writes, where and when (not its comment or origin).
bool same_coe(const CoeCommand& e, const CoeCommand& c) {
    return e.transitions == c.transitions && e.index == c.index && e.subindex == c.subindex && e.data == c.data &&
           e.complete_access == c.complete_access;
}

std::vector<std::uint32_t> assigned_order(const NetworkSlave& s) {
    std::vector<std::uint32_t> out;
    for (const SmSetup& sm : s.sms)
        for (std::size_t pi : sm.pdos) out.push_back(s.pdos[pi].index);
    return out;
}

const ConfiguredPdo* find_pdo(const NetworkSlave& s, std::uint32_t index) {
    for (const ConfiguredPdo& p : s.pdos)
        if (p.index == index) return &p;
    return nullptr;
}

NetworkSpec spec_of(const std::string& path, const MasterSpec& master, const std::vector<ImportedSlave>& slaves) {
    NetworkSpec spec;
    spec.path = path;
    spec.master = master;
    for (const ImportedSlave& s : slaves)
        if (s.known) spec.slaves.push_back(s.spec);
    return spec;
}

// The ENI's PreviousPort as previous_slave/previous_port: the slave whose station address it
// names, when that is not the one listed before, and the port whenever it is not B (the line's
// usual port), so that a tree comes back as a tree (topology.cpp checks both on build).
void link_previous_ports(std::vector<ImportedSlave>& slaves) {
    for (std::size_t k = 1; k < slaves.size(); ++k) {
        const EniSlaveFacts& e = *slaves[k].eni;
        if (!e.previous_phys_addr || !e.previous_port) continue;
        std::optional<std::size_t> up;
        for (std::size_t j = 0; j < k; ++j)
            if (slaves[j].eni->phys_addr == e.previous_phys_addr) up = j;
        if (!up || !slaves[*up].known) continue;
        if (*up != k - 1) slaves[k].spec.previous_slave = slaves[*up].spec.name;
        if (*up != k - 1 || *e.previous_port != 'B') slaves[k].spec.previous_port = std::string(1, *e.previous_port);
    }
}

std::string hex(std::uint32_t v, int digits) { return fmt::format("0x{:0{}X}", v, digits); }

std::string render(const EniFacts& facts, const MasterSpec& master, const std::vector<ImportedSlave>& slaves, const std::string& path,
                   const EniImportOptions& options) {
    std::string y = "# A network imported from " + yaml_comment_text(path) + " (esi-net init --from-eni); esi-net build NETWORK.yaml -o OUTDIR\n";
    y += "# yaml-language-server: $schema=https://libesi.example/schemas/esi-network.schema.json\n";
    if (!options.esi.empty()) {
        y += "esi:\n";
        for (const std::string& e : options.esi) y += "  - " + yaml_quoted(e) + "\n";
    }
    y += fmt::format("master: {{ name: {}, cycle_time_us: {} }}\n", yaml_quoted(master.name), master.cycle_time_us);
    y += facts.slaves.empty() ? "slaves: []\n" : "slaves:\n";
    for (const ImportedSlave& s : slaves) {
        const SlaveSpec& ss = s.spec;
        for (const std::string& n : s.notes) y += "  # " + yaml_comment_text(n) + "\n";
        const std::string prefix = !s.known && options.omit_unknown ? "  # " : "  ";
        y += prefix + "- name: " + yaml_quoted(ss.name) + "\n";
        const std::string in = prefix + "  ";
        y += in + fmt::format("vendor_id: {}\n", hex(*ss.vendor_id, 8));
        y += in + fmt::format("product_code: {}\n", hex(*ss.product_code, 8));
        y += in + fmt::format("revision: {}\n", hex(*ss.revision, 8));
        if (ss.alias) y += in + fmt::format("alias: {}\n", *ss.alias);
        if (ss.previous_slave) y += in + "previous_slave: " + yaml_quoted(*ss.previous_slave) + "\n";
        if (ss.previous_port) y += in + "previous_port: " + *ss.previous_port + "\n";
        if (ss.pdos) {
            std::string list;
            for (const PdoRef& p : *ss.pdos) list += (list.empty() ? "" : ", ") + hex(p.index, 4);
            y += in + "pdos: [" + list + "]\n";
        }
        if (!ss.pdo_entries.empty()) {
            y += in + "pdo_entries:\n";
            for (const PdoEntriesSpec& p : ss.pdo_entries) {
                std::string list;
                for (const PdoEntrySpec& e : p.entries)
                    list += fmt::format("{}{}:0x{:02X}:{}", list.empty() ? "" : ", ", hex(e.index, 4), e.subindex, e.bit_len);
                y += in + "  " + hex(p.pdo, 4) + ": [" + list + "]\n";
            }
        }
        if (!ss.force_entries.empty()) {
            std::string list;
            for (const ForcedEntry& f : ss.force_entries) list += fmt::format("{}{}:0x{:02X}", list.empty() ? "" : ", ", hex(f.index, 4), f.subindex);
            y += in + "force_entries: [" + list + "]\n";
        }
        if (ss.dc) y += in + "dc: " + yaml_quoted(*ss.dc) + "\n";
        if (!ss.sdos.empty()) {
            y += in + "sdos:\n";
            for (const SdoSpec& c : ss.sdos) {
                std::string data;
                for (std::uint8_t b : *c.data) data += fmt::format("{:02x}", b);
                std::string transitions;
                for (const std::string& t : c.transitions) transitions += (transitions.empty() ? "" : ", ") + yaml_quoted(t);
                y += in + fmt::format("  - {{ index: {}, subindex: {}, data: \"{}\", transition: [{}]", hex(c.index, 4), c.subindex, data, transitions);
                if (c.complete_access) y += ", complete_access: true";
                if (c.comment) y += ", comment: " + yaml_quoted(*c.comment);
                y += " }\n";
            }
        }
    }
    return y;
}

}  // namespace

EniImport network_from_eni(std::string_view xml, const std::string& path, const LibraryIndex& index, const EniImportOptions& options) {
    EniImport result;
    const std::optional<EniFacts> facts = read_eni_facts(xml, path, result.diagnostics);
    if (!facts) return result;
    MasterSpec master;
    if (!facts->master_name.empty()) master.name = facts->master_name;
    if (facts->cycle_time_us) master.cycle_time_us = *facts->cycle_time_us;

    std::vector<ImportedSlave> slaves;
    for (const EniSlaveFacts& e : facts->slaves) {
        ImportedSlave s;
        s.eni = &e;
        s.spec.name = e.name.empty() ? fmt::format("Slave {}", slaves.size() + 1) : e.name;
        for (const ImportedSlave& other : slaves)
            if (other.spec.name == s.spec.name) s.spec.name += fmt::format(" ({})", slaves.size() + 1);
        s.spec.vendor_id = e.vendor_id;
        s.spec.product_code = e.product_code;
        s.spec.revision = e.revision;
        s.spec.alias = e.alias;
        const Resolution r = resolve_device(index, DeviceQuery{std::nullopt, e.vendor_id, e.product_code, e.revision}, path, SourcePos{e.line, 1});
        s.known = r.device != nullptr;
        if (!s.known) {
            s.notes.push_back(fmt::format("no ESI in the library describes vendor {} product {} revision {}", hex(e.vendor_id, 8),
                                          hex(e.product_code, 8), hex(e.revision, 8)));
            result.diagnostics.emplace(Severity::warning, "net-eni-unknown",
                                       fmt::format("slave '{}': {}{}", s.spec.name, s.notes.back(),
                                                   options.omit_unknown ? "; written as a comment" : "; `build` will stop here until one does"),
                                       path, SourcePos{e.line, 1});
        }
        slaves.push_back(std::move(s));
    }
    link_previous_ports(slaves);

    // Builds the known slaves as specified so far; nullopt (and the errors) when that fails.
    auto build = [&]() -> std::optional<Network> {
        BuildResult built = build_network(spec_of(path, master, slaves), index);
        if (built.network) return std::move(built.network);
        for (Diagnostic& d : built.diagnostics.items())
            if (d.severity == Severity::error) result.diagnostics.add(std::move(d));
        return std::nullopt;
    };
    auto for_each_known = [&](const Network& n, auto&& step) {
        std::size_t k = 0;
        for (ImportedSlave& s : slaves)
            if (s.known) step(s, n.slaves[k++]);
    };

    // 1. The PDO assignment.
    std::optional<Network> n = build();
    if (!n) return result;
    for_each_known(*n, [&](ImportedSlave& s, const NetworkSlave& built) {
        std::vector<std::uint32_t> wanted;
        for (const EniPdoFact& p : s.eni->assigned) wanted.push_back(p.index);
        if (wanted != assigned_order(built)) {
            std::vector<PdoRef> refs;
            for (std::uint32_t i : wanted) refs.push_back({i, {}});
            s.spec.pdos = std::move(refs);
        }
    });
    // 2. Remapped entries and the DC op mode.
    if (!(n = build())) return result;
    for_each_known(*n, [&](ImportedSlave& s, const NetworkSlave& built) {
        for (const EniPdoFact& p : s.eni->assigned) {
            const ConfiguredPdo* ours = find_pdo(built, p.index);
            if (!ours) continue;
            std::vector<EniEntryFact> have;
            for (const ConfiguredEntry& e : ours->entries) have.push_back({e.index, e.subindex, e.bit_len});
            if (have == p.entries) continue;
            PdoEntriesSpec spec;
            spec.pdo = p.index;
            for (const EniEntryFact& e : p.entries) spec.entries.push_back({e.index, e.subindex, e.bit_len, {}});
            s.spec.pdo_entries.push_back(std::move(spec));
        }
        const std::uint16_t have_dc = built.dc ? built.dc->assign_activate : 0;
        if (have_dc == s.eni->assign_activate) return;
        const DcOpMode* mode = nullptr;
        if (built.device->dc)
            for (const DcOpMode& m : built.device->dc->op_modes)
                if (!mode && m.assign_activate == s.eni->assign_activate) mode = &m;
        if (mode) s.spec.dc = mode->name;
        else
            result.diagnostics.emplace(Severity::warning, "net-eni-dc",
                                       fmt::format("slave '{}': the ENI activates DC with AssignActivate 0x{:04X}, which no op mode of its ESI has; "
                                                   "the network uses '{}'",
                                                   s.spec.name, s.eni->assign_activate, built.dc ? built.dc->op_mode : "no DC"),
                                       path, SourcePos{s.eni->line, 1});
    });
    // 2b. Entries the ENI maps although the ESI marks them not mappable: the tool that wrote it
    // mapped them (EC-Engineer maps an Elmo drive's 0x60FE:00), so the network forces them.
    for (int round = 0; round < 4; ++round) {
        const BuildResult trial = build_network(spec_of(path, master, slaves), index);
        if (trial.network) break;
        bool forced = false;
        for (const Diagnostic& d : trial.diagnostics) {
            std::uint32_t entry_index = 0, entry_sub = 0;
            if (d.rule != "net-entry-not-mappable" || !parse_entry_key(std::string_view(d.message).substr(0, d.message.find(' ')), entry_index, entry_sub))
                continue;
            for (ImportedSlave& s : slaves) {
                if (!s.known) continue;
                const bool maps = std::any_of(s.spec.pdo_entries.begin(), s.spec.pdo_entries.end(), [&](const PdoEntriesSpec& p) {
                    return std::any_of(p.entries.begin(), p.entries.end(), [&](const PdoEntrySpec& e) { return e.index == entry_index && e.subindex == entry_sub; });
                });
                const bool already = std::any_of(s.spec.force_entries.begin(), s.spec.force_entries.end(),
                                                 [&](const ForcedEntry& f) { return f.index == entry_index && f.subindex == entry_sub; });
                if (!maps || already) continue;
                s.spec.force_entries.push_back({entry_index, entry_sub, {}});
                forced = true;
                result.diagnostics.emplace(Severity::warning, "net-eni-forced",
                                           fmt::format("slave '{}': the ENI maps {}:{:02X}, which the ESI marks not mappable; the network "
                                                       "forces it (force_entries)",
                                                       s.spec.name, hex_index(entry_index), entry_sub),
                                           path, SourcePos{s.eni->line, 1});
            }
        }
        if (!forced) break;
    }
    // 3. The CoE start-up commands the ESI does not imply.
    if (!(n = build())) return result;
    for_each_known(*n, [&](ImportedSlave& s, const NetworkSlave& built) {
        // Each command the ESI implies accounts for one ENI command (the same one may be sent twice,
        // once from the ESI and once from the network); the same comment first.
        std::vector<bool> used(built.coe_init_cmds.size(), false);
        auto take = [&](const CoeCommand& e, bool with_comment) {
            for (std::size_t i = 0; i < built.coe_init_cmds.size(); ++i)
                if (!used[i] && same_coe(e, built.coe_init_cmds[i]) && (!with_comment || built.coe_init_cmds[i].comment == e.comment)) {
                    used[i] = true;
                    return true;
                }
            return false;
        };
        std::vector<const CoeCommand*> extra;
        for (const CoeCommand& e : s.eni->coe)
            if (!take(e, true)) extra.push_back(&e);
        std::erase_if(extra, [&](const CoeCommand* e) { return take(*e, false); });
        for (const CoeCommand* ep : extra) {
            const CoeCommand& e = *ep;
            SdoSpec sdo;
            sdo.index = e.index;
            sdo.subindex = e.subindex;
            sdo.data = e.data;
            sdo.transitions = e.transitions;
            sdo.complete_access = e.complete_access;
            if (!e.comment.empty()) sdo.comment = e.comment;
            s.spec.sdos.push_back(std::move(sdo));
        }
        for (std::size_t i = 0; i < built.coe_init_cmds.size(); ++i)
            if (const CoeCommand& c = built.coe_init_cmds[i]; !used[i])
                result.diagnostics.emplace(Severity::warning, "net-eni-coe",
                                           fmt::format("slave '{}': the ESI implies the start-up command {}:{:02X} ({}), which the ENI does not send; "
                                                       "a network file cannot leave it out",
                                                       s.spec.name, hex_index(c.index), c.subindex, c.comment),
                                           path, SourcePos{s.eni->line, 1});
    });

    result.yaml = render(*facts, master, slaves, path, options);
    for (std::size_t i = 0; i < slaves.size(); ++i)
        if (slaves[i].known || !options.omit_unknown) result.written.push_back(i);
    // What we write must build (but for the slaves without an ESI, which the user must add).
    const NetworkFileResult reread = read_network_text(result.yaml, path + " (imported)");
    if (!reread.spec) {
        for (const Diagnostic& d : reread.diagnostics) result.diagnostics.add(d);
        result.yaml.clear();
        result.written.clear();
        return result;
    }
    NetworkSpec check = *reread.spec;
    if (!options.omit_unknown) {
        std::vector<SlaveSpec> known;
        for (std::size_t i = 0; i < slaves.size(); ++i)
            if (slaves[i].known) known.push_back(check.slaves[i]);
        check.slaves = std::move(known);
    }
    const BuildResult final_build = build_network(check, index);
    if (!final_build.network) {
        for (const Diagnostic& d : final_build.diagnostics)
            if (d.severity == Severity::error) result.diagnostics.add(d);
        result.yaml.clear();
        result.written.clear();
    }
    return result;
}

}  // namespace esi::net
