// network.xml: the ETG.2100 EtherCAT Network Information (EtherCATConfig, schema v1.6).
//
// Conventions (docs/esi-net.md, "ENI"): numbers of xs:int fields in decimal, identities at or
// above 0x80000000 as the signed value the type demands; PDO and entry indices "#x…" (what
// both third-party readers parse); Data as little-endian hex bytes; booleans 1/0 (SOEM's
// reader takes complete access only when the attribute is exactly "1"); CDATA for names and
// comments; Version="1.3" like every export. Only the assigned PDOs are copied into
// ProcessData, so that readers that ignore the Sm attribute (CherryECAT's) see the assignment.

#include <fmt/format.h>

#include "esi/net/outputs.hpp"
#include "register_init_cmds.hpp"
#include "xml_text.hpp"

namespace esi::net {

namespace {

std::string hex_bytes(const std::vector<std::uint8_t>& bytes) {
    std::string out;
    out.reserve(bytes.size() * 2);
    for (std::uint8_t b : bytes) out += fmt::format("{:02x}", b);
    return out;
}

// xs:int is signed 32-bit: values from 0x80000000 up are written as their signed reading.
long long xs_int(std::uint32_t v) { return static_cast<long long>(static_cast<std::int32_t>(v)); }

std::string esi_hex(std::uint32_t v) { return fmt::format("#x{:04x}", v); }

std::string physics(const std::string& esi) {
    std::string out;
    for (char c : esi) {
        if (out.size() == 4) break;
        out += c == 'H' ? 'Y' : (c == 'Y' || c == 'K' || c == ' ' || c == 'B') ? c : ' ';
    }
    return out;
}

void register_cmd(XmlText& x, const RegisterCommand& c) {
    x.open("InitCmd");
    for (const std::string& t : c.transitions) x.leaf("Transition", t);
    if (c.before_slave) x.leaf("BeforeSlave", "1");
    x.cdata_leaf("Comment", c.comment);
    if (c.requires_cycle) x.leaf("Requires", "cycle");
    x.leaf("Cmd", static_cast<long long>(c.cmd));
    x.leaf("Adp", c.adp);
    x.leaf("Ado", c.ado);
    if (c.data_length) x.leaf("DataLength", *c.data_length);
    else x.leaf("Data", hex_bytes(c.data));
    if (c.cnt) x.leaf("Cnt", *c.cnt);
    x.leaf("Retries", c.retries);
    if (c.validate) {
        x.open("Validate");
        x.leaf("Data", hex_bytes(c.validate->data));
        if (c.validate->mask) x.leaf("DataMask", hex_bytes(*c.validate->mask));
        x.leaf("Timeout", c.validate->timeout_ms);
        x.close();
    } else if (c.timeout_ms) {
        x.leaf("Timeout", *c.timeout_ms);
    }
    x.close();
}

void pdo_element(XmlText& x, const ConfiguredPdo& p) {
    XmlText::Attributes attributes;
    if (p.fixed) attributes.emplace_back("Fixed", "1");
    if (p.mandatory) attributes.emplace_back("Mandatory", "1");
    attributes.emplace_back("Sm", std::to_string(p.sm));
    x.open(p.direction == PdoDirection::rx ? "RxPdo" : "TxPdo", attributes);
    XmlText::Attributes slot;
    if (p.index_depend_on_slot) slot.emplace_back("DependOnSlot", "1");
    x.leaf("Index", esi_hex(p.index), slot);
    x.leaf("Name", p.name);
    for (std::uint32_t e : p.excludes) x.leaf("Exclude", esi_hex(e));
    for (const ConfiguredEntry& e : p.entries) {
        x.open("Entry");
        XmlText::Attributes entry_slot;
        if (e.index_depend_on_slot) entry_slot.emplace_back("DependOnSlot", "1");
        x.leaf("Index", esi_hex(e.index), entry_slot);
        if (!e.is_padding()) x.leaf("SubIndex", e.subindex);
        x.leaf("BitLen", e.bit_len);
        if (!e.is_padding()) {
            if (!e.name.empty()) x.leaf("Name", e.name);
            if (e.comment) x.leaf("Comment", *e.comment);
            x.leaf("DataType", e.data_type);
        }
        x.close();
    }
    x.close();
}

void process_data(XmlText& x, const Network& n, const NetworkSlave& s) {
    if (s.output_bytes == 0 && s.input_bytes == 0 && s.pdos.empty()) {
        x.empty("ProcessData");
        return;
    }
    x.open("ProcessData");
    const std::uint32_t start = 8 * s.image_offset;
    (void)n;
    if (s.output_bytes) {
        x.open("Send");
        x.leaf("BitStart", start);
        x.leaf("BitLength", 8 * s.output_bytes);
        x.close();
    }
    if (s.input_bytes) {
        x.open("Recv");
        x.leaf("BitStart", start);
        x.leaf("BitLength", 8 * s.input_bytes);
        x.close();
    }
    for (const SmSetup& sm : s.sms) {
        if (!sm.is_process_data()) continue;
        x.open("Sm" + std::to_string(sm.number));
        x.leaf("Type", sm.kind == SmKind::outputs ? "Outputs" : "Inputs");
        // The ESI's sizes, as TwinCAT copies them (zeros left out).
        if (sm.min_size.value_or(0)) x.leaf("MinSize", *sm.min_size);
        if (sm.max_size.value_or(0)) x.leaf("MaxSize", *sm.max_size);
        if (sm.default_size.value_or(0)) x.leaf("DefaultSize", *sm.default_size);
        x.leaf("StartAddress", sm.start_address);
        x.leaf("ControlByte", sm.control_byte);
        x.leaf("Enable", sm.enable ? "1" : "0");
        if (sm.is_virtual) x.leaf("Virtual", "1");
        for (std::size_t p : sm.pdos) x.leaf("Pdo", s.pdos[p].index);
        x.close();
    }
    // TxPDOs before RxPDOs, as both tools write them.
    for (const PdoDirection direction : {PdoDirection::tx, PdoDirection::rx})
        for (const ConfiguredPdo& p : s.pdos)
            if (p.direction == direction) pdo_element(x, p);
    x.close();
}

void mailbox(XmlText& x, const NetworkSlave& s) {
    if (!s.mailbox) return;
    const MailboxSetup& m = *s.mailbox;
    XmlText::Attributes attributes;
    if (m.data_link_layer) attributes.emplace_back("DataLinkLayer", *m.data_link_layer ? "1" : "0");
    x.open("Mailbox", attributes);
    x.open("Send");
    x.leaf("Start", m.out_start);
    x.leaf("Length", m.out_length);
    x.close();
    x.open("Recv");
    x.leaf("Start", m.in_start);
    x.leaf("Length", m.in_length);
    // Without a mailbox-state FMMU the master polls the mailbox (10 ms, as EC-Engineer writes).
    if (m.status_bit) x.leaf("StatusBitAddr", *m.status_bit);
    else x.leaf("PollTime", 10);
    x.close();
    if (m.boot_out_start && m.boot_in_start) {
        x.open("BootStrap");
        x.open("Send");
        x.leaf("Start", *m.boot_out_start);
        x.leaf("Length", *m.boot_out_length);
        x.close();
        x.open("Recv");
        x.leaf("Start", *m.boot_in_start);
        x.leaf("Length", *m.boot_in_length);
        x.close();
        x.close();
    }
    const std::pair<bool, const char*> protocols[] = {{m.aoe, "AoE"}, {m.eoe, "EoE"}, {m.coe, "CoE"},
                                                      {m.soe, "SoE"}, {m.foe, "FoE"}, {m.voe, "VoE"}};
    for (const auto& [used, name] : protocols)
        if (used) x.leaf("Protocol", name);
    if (m.coe && (!s.coe_init_cmds.empty() || !m.channel_info.empty())) {
        x.open("CoE");
        if (!s.coe_init_cmds.empty()) {
            x.open("InitCmds");
            for (const CoeCommand& c : s.coe_init_cmds) {
                XmlText::Attributes a;
                if (c.generated()) a.emplace_back("Fixed", "1");
                if (c.complete_access) a.emplace_back("CompleteAccess", "1");
                x.open("InitCmd", a);
                for (const std::string& t : c.transitions) x.leaf("Transition", t);
                if (!c.comment.empty()) x.cdata_leaf("Comment", c.comment);
                x.leaf("Timeout", 0);
                x.leaf("Ccs", 1);  // SDO download (ETG.1000.6)
                x.leaf("Index", c.index);
                x.leaf("SubIndex", c.subindex);
                if (!c.data.empty()) x.leaf("Data", hex_bytes(c.data));
                x.close();
            }
            x.close();
        }
        if (!m.channel_info.empty()) {
            x.open("Profile");
            for (const auto& [profile, add_info] : m.channel_info) {
                x.open("ChannelInfo");
                x.leaf("ProfileNo", profile);
                x.leaf("AddInfo", add_info);
                x.close();
            }
            x.close();
        }
        x.close();
    }
    x.close();
}

void slave(XmlText& x, const Network& n, const NetworkSlave& s) {
    x.open("Slave");
    x.open("Info");
    x.cdata_leaf("Name", s.name);
    x.leaf("PhysAddr", s.phys_addr);
    x.leaf("AutoIncAddr", s.auto_inc_addr);
    if (s.alias) {
        x.open("Identification", {{"Value", std::to_string(*s.alias)}});
        x.leaf("Ado", "#x0012");  // configured station alias register
        x.close();
    } else if (s.identification_reg134) {
        x.open("Identification", {{"Value", "0"}});
        x.leaf("Ado", "#x0134");  // AL status code, where such devices show their ID selector
        x.close();
    }
    x.leaf("Physics", physics(s.physics));
    x.leaf("VendorId", xs_int(s.vendor_id));
    x.leaf("ProductCode", xs_int(s.product_code));
    x.leaf("RevisionNo", xs_int(s.revision));
    x.leaf("SerialNo", 0);
    x.close();
    process_data(x, n, s);
    mailbox(x, s);
    x.open("InitCmds");
    for (const RegisterCommand& c : slave_init_cmds(n, s)) register_cmd(x, c);
    x.close();
    if (s.previous) {
        // The port and station address of the slave it hangs off (topology.cpp), as TwinCAT
        // writes a tree: one selected PreviousPort per slave but the first.
        const NetworkSlave& previous = n.slaves[*s.previous];
        x.open("PreviousPort", {{"Selected", "1"}});
        x.leaf("Port", std::string(1, static_cast<char>('A' + s.previous_port)));
        x.leaf("PhysAddr", previous.phys_addr);
        x.close();
    }
    if (s.dc) {
        x.open("DC");
        x.leaf("ReferenceClock", s.dc->reference_clock ? "1" : "0");
        x.leaf("CycleTime0", s.dc->cycle_time0);
        x.leaf("CycleTime1", s.dc->cycle_time1);
        x.leaf("ShiftTime", s.dc->shift_time0);
        x.close();
    }
    x.close();
}

void cyclic(XmlText& x, const Network& n) {
    x.open("Cyclic");
    x.leaf("CycleTime", n.master.cycle_time_us);
    for (const Frame& f : n.image.frames) {
        x.open("Frame");
        for (const Datagram& d : f.datagrams) {
            x.open("Cmd");
            if (d.preop) x.leaf("State", "PREOP");
            x.leaf("State", "SAFEOP");
            x.leaf("State", "OP");
            x.cdata_leaf("Comment", d.comment);
            x.leaf("Cmd", static_cast<long long>(d.command));
            const bool logical = d.command == Datagram::Command::lrd || d.command == Datagram::Command::lwr || d.command == Datagram::Command::lrw;
            if (logical) {
                x.leaf("Addr", xs_int(d.logical));
            } else {
                x.leaf("Adp", d.adp);
                x.leaf("Ado", d.ado);
            }
            x.leaf("DataLength", d.length);
            if (d.working_counter) x.leaf("Cnt", *d.working_counter);
            x.leaf("InputOffs", d.image_offset);
            x.leaf("OutputOffs", d.image_offset);
            x.close();
        }
        x.close();
    }
    x.close();
}

void image(XmlText& x, const Network& n) {
    x.open("ProcessImage");
    for (const auto& [element, variables] : {std::pair<const char*, const std::vector<Variable>*>{"Inputs", &n.image.inputs},
                                             std::pair<const char*, const std::vector<Variable>*>{"Outputs", &n.image.outputs}}) {
        x.open(element);
        x.leaf("ByteSize", n.image.byte_size);
        for (const Variable& v : *variables) {
            x.open("Variable");
            x.leaf("Name", v.name);
            if (v.comment) x.cdata_leaf("Comment", *v.comment);
            x.leaf("DataType", v.data_type);
            x.leaf("BitSize", v.bit_size);
            x.leaf("BitOffs", static_cast<long long>(v.bit_offset));
            x.close();
        }
        x.close();
    }
    x.close();
}

}  // namespace

std::string write_eni(const Network& n) {
    XmlText x;
    x.open("EtherCATConfig", {{"xmlns:xsi", "http://www.w3.org/2001/XMLSchema-instance"},
                              {"xsi:noNamespaceSchemaLocation", "EtherCATConfig.xsd"},
                              {"Version", "1.3"}});
    x.open("Config");
    x.open("Master");
    x.open("Info");
    x.cdata_leaf("Name", n.master.name);
    x.leaf("Destination", "ffffffffffff");
    x.leaf("Source", n.master.source_mac);
    x.leaf("EtherType", "a488");  // 0x88A4 as it appears on the wire
    x.close();
    std::size_t mailbox_states = 0, eoe = 0;
    for (const NetworkSlave& s : n.slaves) {
        if (s.mailbox && s.mailbox->status_bit) ++mailbox_states;
        if (s.mailbox && s.mailbox->eoe) ++eoe;
    }
    if (mailbox_states) {
        x.open("MailboxStates");
        x.leaf("StartAddr", xs_int(n.image.mailbox_state_base));
        x.leaf("Count", static_cast<long long>(mailbox_states));
        x.close();
    }
    if (eoe) {
        x.open("EoE");
        x.leaf("MaxPorts", static_cast<long long>(eoe));
        x.leaf("MaxFrames", 180);
        x.leaf("MaxMACs", 100);
        x.close();
    }
    x.open("InitCmds");
    for (const RegisterCommand& c : master_init_cmds()) register_cmd(x, c);
    x.close();
    x.close();
    for (const NetworkSlave& s : n.slaves) slave(x, n, s);
    cyclic(x, n);
    image(x, n);
    return x.finish();
}

}  // namespace esi::net
