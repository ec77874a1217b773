// Readers of the text IgH's `ethercat pdos` and SOEM's `slaveinfo -map` print (bus_dump.hpp).
// The formats are the tools' printf formats (IgH tool/CommandPdos.cpp, SOEM samples/slaveinfo):
//   SM2: PhysAddr 0x0f00, DefaultSize    0, ControlRegister 0x44, Enable 9
//     RxPDO 0x1600 "Channel 1"
//       PDO entry 0x7000:01,  1 bit, "Output"
// and
//   Slave:2 / Man: 00000002 ID: 07d23052 Rev: 00100000
//   SM0 A:0f00 L:   1 F:00090044 Type:3
//   FMMU0 Ls:00000000 Ll:   1 Lsb:0 Leb:1 Ps:0f00 Psb:0 Ty:02 Act:01
//   SM0 RXPDO 0x1600 Channel 1
//   [0x0000.0] 0x7000:0x01 0x01 BOOLEAN      Output

#include "esi/net/bus_dump.hpp"
#include "esi/net/igh_scan.hpp"

#include <cstdlib>
#include <cctype>

namespace esi::net {

namespace {

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r' || s.front() == '*')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

bool starts_with(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }

// The number after `key` in `line` ("PhysAddr 0x0f00," → 0xf00), in `base` unless it has 0x.
std::optional<std::uint64_t> number_after(std::string_view line, std::string_view key, int base = 10) {
    const std::size_t at = line.find(key);
    if (at == std::string_view::npos) return std::nullopt;
    std::string_view rest = line.substr(at + key.size());
    while (!rest.empty() && rest.front() == ' ') rest.remove_prefix(1);
    std::string text;
    for (char c : rest) {
        if (std::isxdigit(static_cast<unsigned char>(c)) || c == 'x' || c == 'X') text += c;
        else break;
    }
    if (text.empty()) return std::nullopt;
    char* end = nullptr;
    const bool hex = text.size() > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X');
    const unsigned long long v = std::strtoull(hex ? text.c_str() + 2 : text.c_str(), &end, hex ? 16 : base);
    if (*end) return std::nullopt;
    return v;
}

// "0x7000:01" (IgH: sub-index hex without 0x) or "0x7000:0x01" (SOEM).
bool entry_address(std::string_view text, std::uint32_t& index, std::uint32_t& subindex) {
    const std::size_t colon = text.find(':');
    if (colon == std::string_view::npos || !starts_with(text, "0x")) return false;
    char* end = nullptr;
    const std::string i(text.substr(2, colon - 2));
    std::string s(text.substr(colon + 1));
    if (starts_with(s, "0x")) s = s.substr(2);
    const std::size_t space = s.find_first_of(" ,");
    if (space != std::string::npos) s = s.substr(0, space);
    if (i.empty() || s.empty()) return false;
    index = static_cast<std::uint32_t>(std::strtoul(i.c_str(), &end, 16));
    if (*end) return false;
    subindex = static_cast<std::uint32_t>(std::strtoul(s.c_str(), &end, 16));
    return !*end && index <= 0xFFFF && subindex <= 0xFF;
}

template <class F>
void for_each_line(std::string_view text, F&& f) {
    std::uint32_t line = 0;
    while (!text.empty()) {
        const std::size_t nl = text.find('\n');
        ++line;
        f(text.substr(0, nl), SourcePos{line, 1});
        if (nl == std::string_view::npos) break;
        text.remove_prefix(nl + 1);
    }
}

}  // namespace

BusDump parse_igh_pdos(std::string_view text, const std::string& path) {
    BusDump dump;
    BusSlave* slave = nullptr;
    BusSm* sm = nullptr;
    BusPdo* pdo = nullptr;
    auto error = [&](SourcePos pos, std::string message) { dump.diagnostics.emplace(Severity::error, "net-dump", std::move(message), path, pos); };
    for_each_line(text, [&](std::string_view raw, SourcePos pos) {
        const std::string_view line = trim(raw);
        if (starts_with(line, "=== Master")) {
            dump.slaves.emplace_back();
            slave = &dump.slaves.back();
            slave->position = number_after(line, "Slave").value_or(dump.slaves.size() - 1);
            slave->source = path;
            slave->pos = pos;
            sm = nullptr;
            pdo = nullptr;
            return;
        }
        if (starts_with(line, "SM") && line.find("PhysAddr") != std::string_view::npos) {
            if (!slave) {  // `ethercat pdos -p N`: one slave, no header
                dump.slaves.emplace_back();
                slave = &dump.slaves.back();
                slave->source = path;
                slave->pos = pos;
            }
            const auto number = number_after(line, "SM");
            const auto start = number_after(line, "PhysAddr", 16);
            const auto control = number_after(line, "ControlRegister", 16);
            if (!number || !start || !control || *start > 0xFFFF || *control > 0xFF) {
                error(pos, "cannot read this SyncManager line");
                return;
            }
            slave->has_mapping = true;
            slave->sms.push_back({static_cast<std::uint32_t>(*number), static_cast<std::uint16_t>(*start), std::nullopt,
                                  static_cast<std::uint8_t>(*control), {}, pos});
            sm = &slave->sms.back();
            pdo = nullptr;
            return;
        }
        if (starts_with(line, "RxPDO") || starts_with(line, "TxPDO")) {
            const auto index = number_after(line, "PDO", 16);
            if (!sm || !index || *index > 0xFFFF) {
                error(pos, sm ? "cannot read this PDO line" : "a PDO outside a SyncManager block");
                return;
            }
            BusPdo p;
            p.direction = line[0] == 'R' ? PdoDirection::rx : PdoDirection::tx;
            p.index = static_cast<std::uint32_t>(*index);
            if (const std::size_t q = line.find('"'); q != std::string_view::npos) {
                const std::size_t q2 = line.rfind('"');
                if (q2 > q) p.name = std::string(line.substr(q + 1, q2 - q - 1));
            }
            sm->pdos.push_back(std::move(p));
            pdo = &sm->pdos.back();
            return;
        }
        if (starts_with(line, "PDO entry")) {
            BusEntry e;
            const std::string_view rest = trim(line.substr(9));
            const auto bits = number_after(rest, ",");
            if (!pdo || !entry_address(rest, e.index, e.subindex) || !bits) {
                error(pos, pdo ? "cannot read this PDO entry line" : "a PDO entry outside a PDO");
                return;
            }
            e.bit_len = static_cast<std::uint32_t>(*bits);
            pdo->entries.push_back(e);
        }
    });
    return dump;
}

BusDump parse_soem_slaveinfo(std::string_view text, const std::string& path) {
    BusDump dump;
    BusSlave* slave = nullptr;
    BusPdo* pdo = nullptr;
    BusSm* pdo_sm = nullptr;
    auto error = [&](SourcePos pos, std::string message) { dump.diagnostics.emplace(Severity::error, "net-dump", std::move(message), path, pos); };
    for_each_line(text, [&](std::string_view raw, SourcePos pos) {
        const std::string_view line = trim(raw);
        if (starts_with(line, "Slave:")) {
            const auto n = number_after(line, "Slave:");
            if (!n || *n == 0) {
                error(pos, "cannot read this slave number");
                return;
            }
            dump.slaves.emplace_back();
            slave = &dump.slaves.back();
            slave->position = static_cast<std::size_t>(*n - 1);  // SOEM counts from 1
            slave->source = path;
            slave->pos = pos;
            pdo = nullptr;
            return;
        }
        if (!slave) return;
        if (starts_with(line, "Name:")) slave->name = std::string(trim(line.substr(5)));
        else if (starts_with(line, "Man:")) {
            slave->vendor_id = static_cast<std::uint32_t>(number_after(line, "Man:", 16).value_or(0));
            slave->product_code = static_cast<std::uint32_t>(number_after(line, "ID:", 16).value_or(0));
            slave->revision = static_cast<std::uint32_t>(number_after(line, "Rev:", 16).value_or(0));
        } else if (starts_with(line, "SM") && line.find(" A:") != std::string_view::npos) {
            const auto number = number_after(line, "SM");
            const auto start = number_after(line, "A:", 16);
            const auto length = number_after(line, "L:");
            const auto flags = number_after(line, "F:", 16);
            if (!number || !start || !length || !flags) {
                error(pos, "cannot read this SyncManager line");
                return;
            }
            slave->sms.push_back({static_cast<std::uint32_t>(*number), static_cast<std::uint16_t>(*start),
                                  static_cast<std::uint16_t>(*length), static_cast<std::uint8_t>(*flags & 0xFF), {}, pos});
        } else if (starts_with(line, "FMMU") && line.find("Ls:") != std::string_view::npos) {
            const auto number = number_after(line, "FMMU");
            const auto length = number_after(line, "Ll:");
            const auto physical = number_after(line, "Ps:", 16);
            const auto type = number_after(line, "Ty:", 16);
            if (!number || !length || !physical || !type) {
                error(pos, "cannot read this FMMU line");
                return;
            }
            slave->fmmus.push_back({static_cast<std::uint32_t>(*number), static_cast<std::uint16_t>(*physical),
                                    static_cast<std::uint16_t>(*length), static_cast<std::uint8_t>(*type), pos});
        } else if (starts_with(line, "PDO mapping according to")) {
            slave->has_mapping = true;
        } else if (starts_with(line, "SM") && (line.find(" RXPDO ") != std::string_view::npos || line.find(" TXPDO ") != std::string_view::npos)) {
            // "SM2 RXPDO 0x1600 Channel 1": the PDO and its SM.
            const auto number = number_after(line, "SM");
            const auto index = number_after(line, "PDO ", 16);
            if (!number || !index) {
                error(pos, "cannot read this PDO line");
                return;
            }
            pdo_sm = nullptr;
            for (BusSm& s : slave->sms)
                if (s.number == *number) pdo_sm = &s;
            if (!pdo_sm) {
                error(pos, "a PDO on SM" + std::to_string(*number) + ", which this slave's SM lines do not list");
                return;
            }
            BusPdo p;
            p.direction = line.find(" RXPDO ") != std::string_view::npos ? PdoDirection::rx : PdoDirection::tx;
            p.index = static_cast<std::uint32_t>(*index);
            const std::size_t name_at = line.find(' ', line.find("PDO ") + 4);
            if (name_at != std::string_view::npos) p.name = std::string(trim(line.substr(name_at)));
            pdo_sm->pdos.push_back(std::move(p));
            pdo = &pdo_sm->pdos.back();
        } else if (starts_with(line, "[0x") && pdo) {
            // "[0x0000.0] 0x7000:0x01 0x01 BOOLEAN      Output"
            const std::size_t close = line.find(']');
            const std::string_view rest = trim(line.substr(close + 1));
            BusEntry e;
            const std::size_t space = rest.find(' ');
            const auto bits = number_after(rest.substr(space == std::string_view::npos ? rest.size() : space), "", 16);
            if (!entry_address(rest, e.index, e.subindex) || !bits) {
                error(pos, "cannot read this PDO entry line");
                return;
            }
            e.bit_len = static_cast<std::uint32_t>(*bits);
            pdo->entries.push_back(e);
        }
    });
    return dump;
}

BusDump parse_igh_slaves_dump(std::string_view text, const std::string& path) {
    IghScan scan = parse_igh_slaves(text, path);
    BusDump dump;
    dump.diagnostics = std::move(scan.diagnostics);
    for (const ScannedSlave& s : scan.slaves) {
        BusSlave b;
        b.position = s.position;
        b.vendor_id = s.vendor_id;
        b.product_code = s.product_code;
        b.revision = s.revision;
        b.name = s.device_name;
        b.source = path;
        b.pos = s.pos;
        dump.slaves.push_back(std::move(b));
    }
    return dump;
}

}  // namespace esi::net
