#include "net/eni_slaves.hpp"

#include <pugixml.hpp>

#include <algorithm>
#include <cstdlib>

namespace esi::test {

namespace {

std::string text(const pugi::xml_node& n, const char* child) { return n.child(child).text().as_string(); }

// HexDecValue: "#x1A00", "0x1A00" or decimal.
std::uint32_t hexdec(std::string s) {
    if (s.rfind("#x", 0) == 0 || s.rfind("0x", 0) == 0) return static_cast<std::uint32_t>(std::strtoul(s.c_str() + 2, nullptr, 16));
    return static_cast<std::uint32_t>(std::strtoll(s.c_str(), nullptr, 10));
}

std::uint32_t xs_int(const pugi::xml_node& n, const char* child) {
    return static_cast<std::uint32_t>(std::strtoll(text(n, child).c_str(), nullptr, 10));
}

bool boolean(const std::string& s) { return s == "1" || s == "true"; }

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

// TwinCAT writes the ESI's BOOL of a 1-bit entry as BIT; both name the same thing.
std::string type_name(std::string t, std::uint32_t bits) {
    if (bits == 1 && (t == "BOOL" || t == "BIT" || t == "BIT1")) return "BIT";
    return t;
}

std::string data_of(const pugi::xml_node& cmd) {
    if (cmd.child("DataLength")) return std::string(2 * std::strtoul(text(cmd, "DataLength").c_str(), nullptr, 10), '0');
    return lower(text(cmd, "Data"));
}

std::string transitions(const pugi::xml_node& cmd) {
    std::string out;
    for (pugi::xml_node t : cmd.children("Transition")) out += (out.empty() ? "" : ",") + std::string(t.text().as_string());
    return out;
}

// A register command without what depends on the slave's place on the bus (its addresses
// become "auto"/"phys") or on the layout of the process image (an FMMU's logical address).
std::string register_cmd(const pugi::xml_node& cmd, const EniSlave& s) {
    const std::string comment = text(cmd, "Comment");
    const std::uint32_t adp = xs_int(cmd, "Adp");
    const std::uint32_t ado = xs_int(cmd, "Ado");
    std::string data = data_of(cmd);
    std::string adp_text = std::to_string(adp);
    if (adp == s.phys_addr) adp_text = "phys";
    else if (adp == s.auto_inc_addr) adp_text = "auto";
    if (ado == 0x10) data = "phys";
    const bool process_fmmu = ado >= 0x600 && ado < 0x700 && comment.rfind("set fmmu", 0) == 0 && comment.find("mailbox") == std::string::npos;
    if (process_fmmu && data.size() == 32) data = "xxxxxxxx" + data.substr(8);
    std::string out = transitions(cmd) + "|" + comment + "|" + text(cmd, "Requires") + "|cmd " + text(cmd, "Cmd") + "|adp " + adp_text +
                      "|ado " + std::to_string(ado) + "|" + data + "|cnt " + text(cmd, "Cnt") + "|retries " + text(cmd, "Retries");
    if (pugi::xml_node v = cmd.child("Validate"))
        out += "|validate " + lower(text(v, "Data")) + "/" + lower(text(v, "DataMask")) + "/" + text(v, "Timeout");
    else if (cmd.child("Timeout"))
        out += "|timeout " + text(cmd, "Timeout");
    return out;
}

}  // namespace

EniFile read_eni(const std::string& xml_text) {
    EniFile file;
    pugi::xml_document doc;
    const pugi::xml_parse_result parsed = doc.load_buffer(xml_text.data(), xml_text.size());
    if (!parsed) {
        file.error = parsed.description();
        return file;
    }
    const pugi::xml_node config = doc.child("EtherCATConfig").child("Config");
    std::vector<std::pair<std::uint64_t, pugi::xml_node>> in_vars, out_vars;
    for (pugi::xml_node v : config.child("ProcessImage").child("Inputs").children("Variable"))
        in_vars.emplace_back(std::strtoull(text(v, "BitOffs").c_str(), nullptr, 10), v);
    for (pugi::xml_node v : config.child("ProcessImage").child("Outputs").children("Variable"))
        out_vars.emplace_back(std::strtoull(text(v, "BitOffs").c_str(), nullptr, 10), v);

    for (pugi::xml_node sn : config.children("Slave")) {
        EniSlave s;
        const pugi::xml_node info = sn.child("Info");
        s.name = text(info, "Name");
        s.phys_addr = xs_int(info, "PhysAddr");
        s.auto_inc_addr = xs_int(info, "AutoIncAddr");
        s.vendor_id = xs_int(info, "VendorId");
        s.product_code = xs_int(info, "ProductCode");
        s.revision = xs_int(info, "RevisionNo");
        const pugi::xml_node pd = sn.child("ProcessData");
        if (pugi::xml_node send = pd.child("Send")) {
            s.send_start = xs_int(send, "BitStart");
            s.send_bits = xs_int(send, "BitLength");
        }
        if (pugi::xml_node recv = pd.child("Recv")) {
            s.recv_start = xs_int(recv, "BitStart");
            s.recv_bits = xs_int(recv, "BitLength");
        }
        for (pugi::xml_node child : pd.children()) {
            const std::string name = child.name();
            if (name.rfind("Sm", 0) == 0 && name.size() > 2 && std::isdigit(static_cast<unsigned char>(name[2]))) {
                EniSm sm;
                sm.number = static_cast<std::uint32_t>(std::stoul(name.substr(2)));
                sm.type = text(child, "Type");
                sm.start = xs_int(child, "StartAddress");
                sm.control = xs_int(child, "ControlByte");
                sm.enable = boolean(text(child, "Enable"));
                for (pugi::xml_node p : child.children("Pdo")) sm.pdos.push_back(static_cast<std::uint32_t>(p.text().as_llong()));
                s.sms.push_back(std::move(sm));
            } else if ((name == "RxPdo" || name == "TxPdo") && child.attribute("Sm")) {
                EniPdo p;
                p.direction = name;
                p.index = hexdec(text(child, "Index"));
                p.sm = child.attribute("Sm").as_uint();
                for (pugi::xml_node e : child.children("Entry")) {
                    const std::uint32_t index = hexdec(text(e, "Index"));
                    const std::uint32_t bits = static_cast<std::uint32_t>(std::stoul(text(e, "BitLen")));
                    p.entries.push_back(index == 0 ? "0:0:" + std::to_string(bits) + ":"
                                                   : std::to_string(index) + ":" + std::to_string(hexdec(text(e, "SubIndex"))) + ":" +
                                                         std::to_string(bits) + ":" + type_name(text(e, "DataType"), bits));
                }
                s.pdos.push_back(std::move(p));
            }
        }
        for (pugi::xml_node c : sn.child("Mailbox").child("CoE").child("InitCmds").children("InitCmd"))
            s.coe_init_cmds.push_back(transitions(c) + "|" + text(c, "Comment") + "|" + text(c, "Index") + ":" + text(c, "SubIndex") + "|" +
                                      lower(text(c, "Data")) + "|" + (boolean(c.attribute("CompleteAccess").as_string()) ? "CA" : ""));
        for (pugi::xml_node c : sn.child("InitCmds").children("InitCmd")) s.register_cmds.push_back(register_cmd(c, s));
        if (pugi::xml_node dc = sn.child("DC"))
            s.dc = std::string(boolean(text(dc, "ReferenceClock")) ? "reference" : "-") + "|" + text(dc, "CycleTime0") + "|" +
                   text(dc, "CycleTime1") + "|" + text(dc, "ShiftTime");
        auto variables = [](const std::vector<std::pair<std::uint64_t, pugi::xml_node>>& vars, std::uint32_t start,
                            std::optional<std::uint32_t> bits) {
            std::vector<std::string> out;
            if (!bits) return out;
            for (const auto& [offset, v] : vars)
                if (offset >= start && offset < start + *bits) {
                    const std::uint32_t size = static_cast<std::uint32_t>(std::stoul(text(v, "BitSize")));
                    out.push_back(std::to_string(offset - start) + "|" + std::to_string(size) + "|" + type_name(text(v, "DataType"), size));
                }
            return out;
        };
        s.outputs = variables(out_vars, s.send_start, s.send_bits);
        s.inputs = variables(in_vars, s.recv_start, s.recv_bits);
        file.slaves.push_back(std::move(s));
    }
    for (pugi::xml_node frame : config.child("Cyclic").children("Frame"))
        for (pugi::xml_node c : frame.children("Cmd"))
            file.cyclic.push_back(text(c, "Cmd") + "|" + text(c, "DataLength") + "|" + text(c, "Cnt"));
    return file;
}

}  // namespace esi::test
