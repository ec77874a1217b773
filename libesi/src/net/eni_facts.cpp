// ENI -> the facts `init --from-eni` needs (eni_facts.hpp), with pugixml.

#include "eni_facts.hpp"

#include <pugixml.hpp>

#include <cstdlib>
#include <cstring>
#include <map>

namespace esi::net {

namespace {

// "#x1A00", "6656", "-2147483648" (xs:int of 0x80000000): the 32-bit value.
std::optional<std::uint32_t> number(std::string_view text) {
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t' || text.front() == '\n' || text.front() == '\r')) text.remove_prefix(1);
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\n' || text.back() == '\r')) text.remove_suffix(1);
    if (text.empty()) return std::nullopt;
    const std::string t(text);
    char* end = nullptr;
    if (t.size() > 2 && (t[0] == '#' || t[0] == '0') && (t[1] == 'x' || t[1] == 'X')) {
        const unsigned long long v = std::strtoull(t.c_str() + 2, &end, 16);
        if (*end || v > 0xFFFFFFFFull) return std::nullopt;
        return static_cast<std::uint32_t>(v);
    }
    const long long v = std::strtoll(t.c_str(), &end, 10);
    if (*end || v < INT32_MIN || v > 0xFFFFFFFFll) return std::nullopt;
    return static_cast<std::uint32_t>(v);
}

std::vector<std::uint8_t> hex_bytes(std::string_view text) {
    std::vector<std::uint8_t> out;
    int high = -1;
    for (char c : text) {
        int v = -1;
        if (c >= '0' && c <= '9') v = c - '0';
        else if (c >= 'a' && c <= 'f') v = c - 'a' + 10;
        else if (c >= 'A' && c <= 'F') v = c - 'A' + 10;
        if (v < 0) continue;
        if (high < 0) high = v;
        else {
            out.push_back(static_cast<std::uint8_t>(high * 16 + v));
            high = -1;
        }
    }
    return out;
}

bool truthy(const pugi::xml_node& n) {
    const std::string_view t = n.child_value();
    return t == "1" || t == "true";
}

std::uint32_t line_of(std::string_view xml, std::ptrdiff_t offset) {
    std::uint32_t line = 1;
    for (std::ptrdiff_t i = 0; i < offset && i < static_cast<std::ptrdiff_t>(xml.size()); ++i)
        if (xml[static_cast<std::size_t>(i)] == '\n') ++line;
    return line;
}

}  // namespace

std::optional<EniFacts> read_eni_facts(std::string_view xml, const std::string& path, Diagnostics& diagnostics) {
    pugi::xml_document doc;
    const pugi::xml_parse_result parsed = doc.load_buffer(xml.data(), xml.size());
    if (!parsed) {
        diagnostics.emplace(Severity::error, "net-eni", std::string("not well-formed XML: ") + parsed.description(), path,
                            SourcePos{line_of(xml, parsed.offset), 1});
        return std::nullopt;
    }
    const pugi::xml_node root = doc.document_element();
    if (std::strcmp(root.name(), "EncryptedEtherCATConfig") == 0) {
        diagnostics.emplace(Severity::error, "net-eni-encrypted",
                            "this ENI is encrypted (EncryptedEtherCATConfig); only the tool that wrote it can read it: export it "
                            "unencrypted (EC-Engineer: without the encryption option)",
                            path, SourcePos{line_of(xml, root.offset_debug()), 1});
        return std::nullopt;
    }
    const pugi::xml_node config = root.child("Config");
    if (std::strcmp(root.name(), "EtherCATConfig") != 0 || !config) {
        diagnostics.emplace(Severity::error, "net-eni", std::string("not an ENI: the root element is <") + root.name() + ">, not <EtherCATConfig> with <Config>",
                            path, SourcePos{line_of(xml, root.offset_debug()), 1});
        return std::nullopt;
    }
    EniFacts facts;
    facts.master_name = config.child("Master").child("Info").child_value("Name");
    if (const auto cycle = number(config.child("Cyclic").child_value("CycleTime")); cycle && *cycle > 0) facts.cycle_time_us = *cycle;
    for (pugi::xml_node slave : config.children("Slave")) {
        EniSlaveFacts s;
        s.line = line_of(xml, slave.offset_debug());
        const pugi::xml_node info = slave.child("Info");
        s.name = info.child_value("Name");
        const auto vendor = number(info.child_value("VendorId"));
        const auto product = number(info.child_value("ProductCode"));
        if (!vendor || !product) {
            diagnostics.emplace(Severity::error, "net-eni", "a Slave without a VendorId or ProductCode", path, SourcePos{s.line, 1});
            continue;
        }
        s.vendor_id = *vendor;
        s.product_code = *product;
        s.revision = number(info.child_value("RevisionNo")).value_or(0);
        s.phys_addr = number(info.child_value("PhysAddr"));
        pugi::xml_node previous;
        for (pugi::xml_node p : slave.children("PreviousPort")) {
            const std::string selected = p.attribute("Selected").as_string();
            if (!previous || selected == "1" || selected == "true") previous = p;
        }
        if (previous) {
            const std::string port = previous.child_value("Port");
            if (port.size() == 1 && port[0] >= 'A' && port[0] <= 'D') s.previous_port = port[0];
            s.previous_phys_addr = number(previous.child_value("PhysAddr"));
        }
        // A station alias: Identification on the alias register 0x0012 (ETG.2100).
        if (const pugi::xml_node id = info.child("Identification"); id && number(id.child_value("Ado")) == 0x0012u)
            if (const auto v = number(id.attribute("Value").as_string()); v && *v && *v <= 0xFFFF) s.alias = static_cast<std::uint16_t>(*v);

        // The assigned PDOs: the SmN elements' Pdo lists, SM by SM; their entries from the
        // RxPdo/TxPdo elements of the same index.
        const pugi::xml_node pd = slave.child("ProcessData");
        std::map<std::uint32_t, pugi::xml_node> pdo_elements;
        for (pugi::xml_node p : pd.children()) {
            if (std::strcmp(p.name(), "RxPdo") != 0 && std::strcmp(p.name(), "TxPdo") != 0) continue;
            if (const auto i = number(p.child_value("Index"))) {
                // A PDO listed twice (TwinCAT lists every PDO; the assigned copy has Sm): prefer the one with Sm.
                if (!pdo_elements.count(*i) || p.attribute("Sm")) pdo_elements[*i] = p;
            }
        }
        for (int n = 0; n < 16; ++n) {
            const pugi::xml_node sm = pd.child(("Sm" + std::to_string(n)).c_str());
            if (!sm) continue;
            for (pugi::xml_node ref : sm.children("Pdo")) {
                const auto i = number(ref.child_value());
                if (!i) continue;
                EniPdoFact p;
                p.index = *i;
                if (const auto it = pdo_elements.find(*i); it != pdo_elements.end())
                    for (pugi::xml_node e : it->second.children("Entry"))
                        p.entries.push_back({number(e.child_value("Index")).value_or(0), number(e.child_value("SubIndex")).value_or(0),
                                             number(e.child_value("BitLen")).value_or(0)});
                s.assigned.push_back(std::move(p));
            }
        }

        for (pugi::xml_node cmd : slave.child("Mailbox").child("CoE").child("InitCmds").children("InitCmd")) {
            CoeCommand c;
            for (pugi::xml_node t : cmd.children("Transition")) c.transitions.push_back(t.child_value());
            c.comment = cmd.child_value("Comment");
            c.index = static_cast<std::uint16_t>(number(cmd.child_value("Index")).value_or(0));
            c.subindex = static_cast<std::uint8_t>(number(cmd.child_value("SubIndex")).value_or(0));
            c.data = hex_bytes(cmd.child_value("Data"));
            // An attribute in ETG.2100 (TwinCAT "true", esi-net and EC-Engineer "1"); some writers use an element.
            const std::string_view ca = cmd.attribute("CompleteAccess").as_string();
            c.complete_access = ca == "1" || ca == "true" || truthy(cmd.child("CompleteAccess"));
            s.coe.push_back(std::move(c));
        }

        // DC: the value written to AssignActivate (0x0980) on the way to SAFEOP.
        for (pugi::xml_node cmd : slave.child("InitCmds").children("InitCmd")) {
            if (number(cmd.child_value("Ado")).value_or(0) != 0x0980) continue;
            bool to_safeop = false;
            for (pugi::xml_node t : cmd.children("Transition")) to_safeop = to_safeop || std::string_view(t.child_value()) == "PS";
            const std::vector<std::uint8_t> data = hex_bytes(cmd.child_value("Data"));
            if (to_safeop && data.size() >= 2) s.assign_activate = static_cast<std::uint16_t>(data[0] | (data[1] << 8));
        }
        facts.slaves.push_back(std::move(s));
    }
    return facts;
}

}  // namespace esi::net
