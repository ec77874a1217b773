// igh_config.h / igh_config.c for the IgH EtherLab master (ecrt.h, API 1.6).
//
// Per slave, the tables `ethercat cstruct` prints for a configured bus — ec_pdo_entry_info_t,
// ec_pdo_info_t and ec_sync_info_t, with every SyncManager of the device (mailbox SMs without
// PDOs), the direction and watchdog mode read from the SM's control byte — then one offset
// variable per mapped entry with an ec_pdo_entry_reg_t list for
// ecrt_domain_reg_pdo_entry_list(), and a function that creates the slave configurations and
// applies the PDOs, the start-up SDOs, the watchdog and DC. IgH downloads the PDO assignment and
// mapping itself from the sync tables, so the ENI's generated assignment/mapping commands are
// not repeated as SDOs. The files compile as C99 and as C++ with -Wall -Wextra -Werror.

#include <fmt/format.h>
#include <algorithm>
#include <map>
#include <set>

#include "esi/net/outputs.hpp"

namespace esi::net {

namespace {

std::string identifier(std::string_view text) {
    std::string out;
    bool underscore = false;
    for (char c : text) {
        const unsigned char u = static_cast<unsigned char>(c);
        if (std::isalnum(u) && u < 0x80) {
            out += static_cast<char>(std::tolower(u));
            underscore = false;
        } else if (!underscore && !out.empty()) {
            out += '_';
            underscore = true;
        }
    }
    while (!out.empty() && out.back() == '_') out.pop_back();
    if (out.empty() || std::isdigit(static_cast<unsigned char>(out.front()))) out = "s_" + out;
    return out;
}

// Text inside a C comment: printable ASCII and valid UTF-8 as it is; "/*" and "*/" split (a
// nested opener is -Wcomment under -Wall, a closer ends the comment), "??" split so that no
// trigraph (-trigraphs, C89) turns "??/" into a line splice; line breaks, controls, bidi
// controls (-Wbidi-chars) and invalid UTF-8 written as <U+XXXX> / <xNN>.
std::string comment(std::string_view text) {
    std::string out;
    for (std::size_t i = 0; i < text.size();) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if ((c == '/' && i + 1 < text.size() && text[i + 1] == '*') || (c == '*' && i + 1 < text.size() && text[i + 1] == '/') ||
            (c == '?' && i + 1 < text.size() && text[i + 1] == '?')) {
            out += static_cast<char>(c);
            out += ' ';
            ++i;
            continue;
        }
        if (c >= 0x20 && c < 0x7F) {
            out += static_cast<char>(c);
            ++i;
            continue;
        }
        std::uint32_t cp = 0;
        std::size_t len = c >= 0xC2 && c <= 0xDF ? 2 : c >= 0xE0 && c <= 0xEF ? 3 : c >= 0xF0 && c <= 0xF4 ? 4 : 0;
        if (len != 0 && i + len <= text.size()) {
            cp = len == 2 ? (c & 0x1Fu) : len == 3 ? (c & 0x0Fu) : (c & 0x07u);
            for (std::size_t k = 1; k < len && len != 0; ++k) {
                const unsigned char d = static_cast<unsigned char>(text[i + k]);
                if ((d & 0xC0) != 0x80) len = 0;
                else cp = (cp << 6) | (d & 0x3Fu);
            }
        } else {
            len = 0;
        }
        static constexpr std::uint32_t smallest[] = {0, 0, 0x80, 0x800, 0x10000};
        if (len != 0 && (cp < smallest[len] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF))) len = 0;
        const bool bidi = cp == 0x061C || cp == 0x200E || cp == 0x200F || (cp >= 0x202A && cp <= 0x202E) || (cp >= 0x2066 && cp <= 0x2069);
        if (len == 0) {
            out += fmt::format("<x{:02X}>", c);
            ++i;
        } else if (cp < 0xA0 || bidi || cp == 0x2028 || cp == 0x2029 || cp == 0xFEFF) {
            out += fmt::format("<U+{:04X}>", cp);
            i += len;
        } else {
            out.append(text.substr(i, len));
            i += len;
        }
    }
    return out;
}

// Unique C names for slaves and their entries.
struct Names {
    std::vector<std::string> slave;
    std::map<std::pair<std::size_t, std::size_t>, std::string> entry;  // (slave, entry number) -> offset variable
    std::map<std::pair<std::size_t, std::size_t>, bool> bit_entry;     // needs a bit position
    std::string network;
};

bool registered(const ConfiguredEntry& e) { return !e.is_padding(); }

Names names_of(const Network& n) {
    Names names;
    names.network = identifier(n.name);
    std::set<std::string> used;
    for (const NetworkSlave& s : n.slaves) {
        std::string base = identifier(s.name);
        if (!used.insert(base).second) base += "_" + std::to_string(s.position);
        used.insert(base);
        names.slave.push_back(base);
    }
    std::set<std::string> vars;
    for (const NetworkSlave& s : n.slaves) {
        std::size_t number = 0;
        std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
        for (const SmSetup& sm : s.sms)
            for (std::size_t p : sm.pdos) {
                std::uint32_t bit = 0;
                for (const ConfiguredEntry& e : s.pdos[p].entries) {
                    const std::size_t k = number++;
                    const bool aligned = bit % 8 == 0 && e.bit_len % 8 == 0;
                    bit += e.bit_len;
                    // IgH registers an entry by index and sub-index: the first of a pair counts.
                    if (!registered(e) || !seen.insert({e.index, e.subindex}).second) continue;
                    std::string var = names.slave[s.position] + "_" + identifier(e.name.empty() ? fmt::format("{:04x}_{:02x}", e.index, e.subindex) : e.name);
                    if (vars.count(var)) var = names.slave[s.position] + "_" + identifier(s.pdos[p].name) + "_" + identifier(e.name);
                    while (vars.count(var)) var += "_";
                    vars.insert(var);
                    names.entry[{s.position, k}] = var;
                    names.bit_entry[{s.position, k}] = !aligned;
                }
            }
    }
    return names;
}

std::string position_of(const NetworkSlave& s) {
    return s.alias ? fmt::format("{}, 0", *s.alias) : fmt::format("0, {}", s.position);
}

std::string upper(std::string text) {
    for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return text;
}

}  // namespace

std::string write_igh_header(const Network& n) {
    const Names names = names_of(n);
    std::string h = fmt::format(
        "/* IgH EtherLab master configuration of network '{}', generated by esi-net from ESI files.\n"
        " * Use: create the domain, call {}_configure(), then\n"
        " * ecrt_domain_reg_pdo_entry_list(domain, {}_domain_regs) and read the process data at the\n"
        " * offsets below. */\n\n"
        "#ifndef IGH_CONFIG_H\n#define IGH_CONFIG_H\n\n#include \"ecrt.h\"\n\n#ifdef __cplusplus\nextern \"C\" {{\n#endif\n\n",
        comment(n.name), names.network, names.network);
    h += fmt::format("#define {}_SLAVE_COUNT {}\n\n", upper(names.network), n.slaves.size());
    for (const NetworkSlave& s : n.slaves) {
        const std::string u = upper(names.slave[s.position]);
        h += fmt::format("/* Slave {}: {} — {} */\n", s.position, comment(s.name), comment(s.device->type.text));
        h += fmt::format("#define {}_POS {}\n", u, position_of(s));
        h += fmt::format("#define {}_ID 0x{:08x}, 0x{:08x}\n", u, s.vendor_id, s.product_code);
        h += fmt::format("#define {}_REVISION 0x{:08x}\n", u, s.revision);
        h += fmt::format("extern ec_pdo_entry_info_t {}_pdo_entries[];\n", names.slave[s.position]);
        h += fmt::format("extern ec_pdo_info_t {}_pdos[];\n", names.slave[s.position]);
        h += fmt::format("extern ec_sync_info_t {}_syncs[];\n\n", names.slave[s.position]);
    }
    h += "/* Byte offsets (and bit positions of entries that do not start on a byte) in the domain. */\n";
    for (const auto& [key, var] : names.entry) {
        h += fmt::format("extern unsigned int {};\n", var);
        if (names.bit_entry.at(key)) h += fmt::format("extern unsigned int {}_bit;\n", var);
    }
    h += fmt::format("\nextern const ec_pdo_entry_reg_t {}_domain_regs[];\n\n", names.network);
    h += fmt::format(
        "/* Creates the slave configurations (stored in configs[0..{}_SLAVE_COUNT-1] when configs is not\n"
        " * NULL) and applies PDOs, start-up SDOs, watchdog and DC. Returns 0, or -1 when the master\n"
        " * refuses a setting. */\nint {}_configure(ec_master_t *master, ec_slave_config_t **configs);\n\n",
        upper(names.network), names.network);
    h += "#ifdef __cplusplus\n}\n#endif\n\n#endif /* IGH_CONFIG_H */\n";
    return h;
}

std::string write_igh_source(const Network& n) {
    const Names names = names_of(n);
    std::string c = fmt::format("/* IgH EtherLab master configuration of network '{}', generated by esi-net. */\n\n#include \"igh_config.h\"\n\n",
                                comment(n.name));
    for (const NetworkSlave& s : n.slaves) {
        const std::string& base = names.slave[s.position];
        c += fmt::format("/* Master 0, Slave {}, \"{}\"\n * Vendor ID:       0x{:08x}\n * Product code:    0x{:08x}\n * Revision number: 0x{:08x}\n */\n\n",
                         s.position, comment(s.device->type.text), s.vendor_id, s.product_code, s.revision);
        std::size_t entries = 0;
        for (const ConfiguredPdo& p : s.pdos) entries += p.entries.size();
        if (entries) {
            c += fmt::format("ec_pdo_entry_info_t {}_pdo_entries[] = {{\n", base);
            for (const SmSetup& sm : s.sms)
                for (std::size_t p : sm.pdos)
                    for (const ConfiguredEntry& e : s.pdos[p].entries)
                        c += fmt::format("    {{0x{:04x}, 0x{:02x}, {}}},{}\n", e.index, e.subindex, e.bit_len,
                                         e.is_padding() ? "" : " /* " + comment(e.name) + " */");
            c += "};\n\n";
        } else {
            c += fmt::format("ec_pdo_entry_info_t {}_pdo_entries[] = {{\n    {{0x0000, 0x00, 0}} /* no entries */\n}};\n\n", base);
        }
        std::size_t pdo_count = 0;
        for (const SmSetup& sm : s.sms) pdo_count += sm.pdos.size();
        std::map<std::size_t, std::size_t> pdo_at;  // pdo -> place in the pdos array
        if (pdo_count) {
            c += fmt::format("ec_pdo_info_t {}_pdos[] = {{\n", base);
            std::size_t at_entry = 0, at_pdo = 0;
            for (const SmSetup& sm : s.sms)
                for (std::size_t p : sm.pdos) {
                    const ConfiguredPdo& pdo = s.pdos[p];
                    pdo_at[p] = at_pdo++;
                    c += pdo.entries.empty() ? fmt::format("    {{0x{:04x}, 0, NULL}}, /* {} */\n", pdo.index, comment(pdo.name))
                                             : fmt::format("    {{0x{:04x}, {}, {}_pdo_entries + {}}}, /* {} */\n", pdo.index,
                                                           pdo.entries.size(), base, at_entry, comment(pdo.name));
                    at_entry += pdo.entries.size();
                }
            c += "};\n\n";
        } else {
            c += fmt::format("ec_pdo_info_t {}_pdos[] = {{\n    {{0x0000, 0, NULL}} /* no PDOs */\n}};\n\n", base);
        }
        c += fmt::format("ec_sync_info_t {}_syncs[] = {{\n", base);
        for (const SmSetup& sm : s.sms) {
            // Control byte bits 3:2 = 01: the master writes (ESC datasheet, SyncManager control).
            const char* direction = (sm.control_byte & 0x0C) == 0x04 ? "EC_DIR_OUTPUT" : "EC_DIR_INPUT";
            const char* watchdog = (sm.control_byte & 0x40) ? "EC_WD_ENABLE" : "EC_WD_DISABLE";
            if (sm.pdos.empty())
                c += fmt::format("    {{{}, {}, 0, NULL, {}}},\n", sm.number, direction, watchdog);
            else
                c += fmt::format("    {{{}, {}, {}, {}_pdos + {}, {}}},\n", sm.number, direction, sm.pdos.size(), base, pdo_at[sm.pdos.front()], watchdog);
        }
        c += "    {0xff, EC_DIR_INVALID, 0, NULL, EC_WD_DEFAULT}\n};\n\n";
    }

    for (const auto& [key, var] : names.entry) {
        c += fmt::format("unsigned int {};\n", var);
        if (names.bit_entry.at(key)) c += fmt::format("unsigned int {}_bit;\n", var);
    }
    c += fmt::format("\nconst ec_pdo_entry_reg_t {}_domain_regs[] = {{\n", names.network);
    for (const NetworkSlave& s : n.slaves) {
        std::size_t number = 0;
        for (const SmSetup& sm : s.sms)
            for (std::size_t p : sm.pdos)
                for (const ConfiguredEntry& e : s.pdos[p].entries) {
                    const std::size_t k = number++;
                    const auto it = names.entry.find({s.position, k});
                    if (it == names.entry.end()) continue;
                    const std::string& var = it->second;
                    c += fmt::format("    {{{}, 0x{:08x}, 0x{:08x}, 0x{:04x}, 0x{:02x}, &{}, {}}},\n", position_of(s), s.vendor_id, s.product_code,
                                     e.index, e.subindex, var, names.bit_entry.at(it->first) ? "&" + var + "_bit" : std::string("NULL"));
                }
    }
    c += "    {0, 0, 0, 0, 0, 0, NULL, NULL}\n};\n\n";

    c += fmt::format("int {}_configure(ec_master_t *master, ec_slave_config_t **configs)\n{{\n    ec_slave_config_t *sc;\n", names.network);
    std::size_t blob = 0;
    for (const NetworkSlave& s : n.slaves) {
        const std::string& base = names.slave[s.position];
        const std::string u = upper(base);
        c += fmt::format("\n    /* {} */\n    sc = ecrt_master_slave_config(master, {}_POS, {}_ID);\n    if (!sc) return -1;\n", comment(s.name), u, u);
        c += fmt::format("    if (configs) configs[{}] = sc;\n", s.position);
        c += fmt::format("    if (ecrt_slave_config_pdos(sc, EC_END, {}_syncs)) return -1;\n", base);
        if (s.watchdog_divider || s.sm_watchdog)
            c += fmt::format("    if (ecrt_slave_config_watchdog(sc, {}, {})) return -1;\n", s.watchdog_divider.value_or(0), s.sm_watchdog.value_or(0));
        for (const CoeCommand& cmd : s.coe_init_cmds) {
            if (cmd.generated()) continue;  // IgH downloads assignment and mapping from the sync tables
            const bool at_start = std::any_of(cmd.transitions.begin(), cmd.transitions.end(),
                                              [](const std::string& t) { return t == "IP" || t == "PS" || t == "SO"; });
            std::string note = cmd.comment.empty() ? fmt::format("0x{:04x}:{:02x}", cmd.index, cmd.subindex) : comment(cmd.comment);
            std::string when;
            for (const std::string& t : cmd.transitions) when += (when.empty() ? "" : ",") + t;
            if (!at_start) {
                c += fmt::format("    /* not applied: {} ({}), IgH sends start-up SDOs only on the way to OP */\n", note, when);
                continue;
            }
            if (when != "PS") note += " (ENI transition " + when + "; IgH sends it in PREOP)";
            const std::vector<std::uint8_t>& d = cmd.data;
            auto le = [&](std::size_t bytes) {
                std::uint32_t v = 0;
                for (std::size_t i = 0; i < bytes; ++i) v |= std::uint32_t{d[i]} << (8 * i);
                return v;
            };
            if (!cmd.complete_access && d.size() == 1) {
                c += fmt::format("    if (ecrt_slave_config_sdo8(sc, 0x{:04x}, 0x{:02x}, 0x{:02x})) return -1; /* {} */\n", cmd.index, cmd.subindex, le(1), note);
            } else if (!cmd.complete_access && d.size() == 2) {
                c += fmt::format("    if (ecrt_slave_config_sdo16(sc, 0x{:04x}, 0x{:02x}, 0x{:04x})) return -1; /* {} */\n", cmd.index, cmd.subindex, le(2), note);
            } else if (!cmd.complete_access && d.size() == 4) {
                c += fmt::format("    if (ecrt_slave_config_sdo32(sc, 0x{:04x}, 0x{:02x}, 0x{:08x}UL)) return -1; /* {} */\n", cmd.index, cmd.subindex, le(4), note);
            } else {
                std::string bytes;
                for (std::uint8_t b : d) bytes += fmt::format("{}0x{:02x}", bytes.empty() ? "" : ", ", b);
                c += fmt::format("    {{\n        static const uint8_t data_{}[] = {{{}}};\n", blob, bytes.empty() ? "0x00" : bytes);
                if (cmd.complete_access)
                    c += fmt::format("        if (ecrt_slave_config_complete_sdo(sc, 0x{:04x}, data_{}, {})) return -1; /* {} */\n", cmd.index, blob, d.size(), note);
                else
                    c += fmt::format("        if (ecrt_slave_config_sdo(sc, 0x{:04x}, 0x{:02x}, data_{}, {})) return -1; /* {} */\n", cmd.index, cmd.subindex, blob,
                                     d.size(), note);
                c += "    }\n";
                ++blob;
            }
        }
        if (s.dc)
            c += fmt::format("    if (ecrt_slave_config_dc(sc, 0x{:04x}, {}, {}, {}, 0)) return -1; /* {} */\n", s.dc->assign_activate, s.dc->cycle_time0,
                             s.dc->shift_time0, s.dc->cycle_time1, comment(s.dc->op_mode));
    }
    c += "    return 0;\n}\n";
    return c;
}

}  // namespace esi::net
