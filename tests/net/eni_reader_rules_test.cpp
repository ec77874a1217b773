// The generated ENI against what the masters that read ENI files need of it:
//  - the ETG.2100 schema v1.6 (xmllint): every generated file validates;
//  - the rules SOEM's ENI converter and CherryECAT's ENI parser follow when they read a file
//    (../shared/domain/eni-etg2100-notes.md §11, docs/esi-net.md "ENI readers"), as assertions
//    on our own file: the readers themselves are not run. For SOEM's converter: one Config under
//    an EtherCATConfig root; one VendorId, ProductCode and RevisionNo per slave, each a number
//    Python's int(text, 0) takes; the slave number (1 - AutoIncAddr) & 0xFFFF; each CoE InitCmd
//    with at least one Transition, exactly one Ccs, Index, SubIndex and Timeout, hex Data, and
//    complete access written "1" (the converter reads "true" as false) — carrying the network
//    model's commands in order. For CherryECAT's parser: identities in decimal only (it calls
//    int(text)), PDO indices with a "#x" prefix (without one it tries hex first), entry SubIndex
//    and BitLen in decimal, and only the assigned PDOs in ProcessData (it ignores `Sm` and takes
//    every PDO it finds as assigned) — carrying the model's PDO assignment and entry counts.

#include <gtest/gtest.h>

#include <pugixml.hpp>

#include <cstdio>
#include <optional>

#include "esi/net/outputs.hpp"
#include "net/net_test_support.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;

bool have_tool(const std::string& name) {
    return esi::test::run({"/bin/sh", "-c", "command -v " + name}).exit_code == 0;
}

bool all_of(const std::string& text, const char* allowed) {
    return !text.empty() && text.find_first_not_of(allowed) == std::string::npos;
}

// Python's int(text): an optional sign and decimal digits (a leading zero is fine there).
std::optional<long long> python_int(const std::string& text) {
    const std::string digits = !text.empty() && (text[0] == '-' || text[0] == '+') ? text.substr(1) : text;
    if (!all_of(digits, "0123456789") || digits.size() > 18) return std::nullopt;
    return std::stoll(text);
}

// Python's int(text, 0): decimal without leading zeros (but "0"), or 0x/0o/0b with digits.
std::optional<long long> python_int_base0(const std::string& text) {
    const bool negative = !text.empty() && text[0] == '-';
    const std::string t = negative ? text.substr(1) : text;
    long long magnitude = 0;
    if (t.size() > 2 && t[0] == '0' && (t[1] == 'x' || t[1] == 'X')) {
        if (!all_of(t.substr(2), "0123456789abcdefABCDEF") || t.size() > 17) return std::nullopt;
        magnitude = std::stoll(t.substr(2), nullptr, 16);
    } else {
        if (!all_of(t, "0123456789") || t.size() > 18 || (t.size() > 1 && t[0] == '0')) return std::nullopt;
        magnitude = std::stoll(t);
    }
    return negative ? -magnitude : magnitude;
}

// An xs:int identity as the readers get it back, modulo 2^32 (the schema makes values at or above
// 0x80000000 negative).
std::uint32_t as_u32(long long v) { return static_cast<std::uint32_t>(v); }

std::string hex(unsigned long long v, int digits) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "0x%0*llX", digits, v);
    return buf;
}

struct WrittenNetwork {
    esi::net::BuildResult built;
    pugi::xml_document eni;
    pugi::xml_parse_result parsed;
    std::string text;
};

std::unique_ptr<WrittenNetwork> written(const esi::test::NamedNetwork& network) {
    auto out = std::make_unique<WrittenNetwork>();
    out->built = esi::test::build_corpus_network(network.yaml);
    if (!out->built.network) return out;
    out->text = esi::net::write_eni(*out->built.network);
    out->parsed = out->eni.load_string(out->text.c_str());
    return out;
}

// The one child `name` of `node`: fails the test when there are none or several.
pugi::xml_node only_child(pugi::xml_node node, const char* name, const std::string& where) {
    std::size_t count = 0;
    pugi::xml_node found;
    for (pugi::xml_node c : node.children(name)) {
        if (!count) found = c;
        ++count;
    }
    EXPECT_EQ(count, 1u) << where << ": " << count << " <" << name << "> where a reader takes exactly one";
    return found;
}

class EniReaders : public ::testing::TestWithParam<esi::test::NamedNetwork> {};

TEST_P(EniReaders, ValidateAgainstTheEtg2100Schema) {
    ESI_REQUIRE_CORPUS();
    if (!have_tool("xmllint")) GTEST_SKIP() << "xmllint not installed: schema check skipped";
    const esi::net::BuildResult built = esi::test::build_corpus_network(GetParam().yaml);
    ASSERT_TRUE(built.network) << esi::test::diagnostics_text(built.diagnostics);
    esi::test::TempDir dir;
    esi::test::write_text(dir / "network.xml", esi::net::write_eni(*built.network));
    const auto result = esi::test::run({"xmllint", "--noout", "--schema",
                                        (esi::test::corpus_dir() / "schema" / "eni-v1.6" / "EtherCATConfig.xsd").string(),
                                        (dir / "network.xml").string()});
    EXPECT_EQ(result.exit_code, 0) << result.err;
}

TEST_P(EniReaders, SoemsConverterRulesHoldForTheIdentitiesAndStartUpCommands) {
    ESI_REQUIRE_CORPUS();
    const auto w = written(GetParam());
    ASSERT_TRUE(w->built.network) << esi::test::diagnostics_text(w->built.diagnostics);
    ASSERT_TRUE(w->parsed) << w->parsed.description();
    const pugi::xml_node root = w->eni.document_element();
    ASSERT_STREQ(root.name(), "EtherCATConfig");
    const pugi::xml_node config = only_child(root, "Config", "EtherCATConfig");
    std::vector<pugi::xml_node> slaves;
    for (pugi::xml_node s : config.children("Slave")) slaves.push_back(s);
    const std::vector<esi::net::NetworkSlave>& model = w->built.network->slaves;
    ASSERT_EQ(slaves.size(), model.size());
    std::size_t commands_checked = 0;
    for (std::size_t i = 0; i < slaves.size(); ++i) {
        const esi::net::NetworkSlave& s = model[i];
        const std::string where = "slave " + std::to_string(i + 1) + " (" + s.name + ")";
        const pugi::xml_node info = only_child(slaves[i], "Info", where);
        const std::pair<const char*, std::uint32_t> identity[] = {
            {"VendorId", s.vendor_id}, {"ProductCode", s.product_code}, {"RevisionNo", s.revision}};
        for (const auto& [name, value] : identity) {
            const std::string text = only_child(info, name, where).text().get();
            const std::optional<long long> read = python_int_base0(text);
            ASSERT_TRUE(read) << where << ": " << name << " '" << text << "' is no int(text, 0)";
            EXPECT_EQ(as_u32(*read), value) << where << ": " << name;
        }
        const std::optional<long long> auto_inc = python_int_base0(only_child(info, "AutoIncAddr", where).text().get());
        ASSERT_TRUE(auto_inc) << where;
        EXPECT_EQ((1 - *auto_inc) & 0xFFFF, static_cast<long long>(s.position + 1)) << where << ": the converter's slave number";

        std::vector<pugi::xml_node> commands;
        for (pugi::xml_node c : slaves[i].child("Mailbox").child("CoE").child("InitCmds").children("InitCmd")) commands.push_back(c);
        ASSERT_EQ(commands.size(), s.coe_init_cmds.size()) << where;
        for (std::size_t k = 0; k < commands.size(); ++k) {
            const pugi::xml_node c = commands[k];
            const esi::net::CoeCommand& ours = s.coe_init_cmds[k];
            const std::string at = where + " CoE InitCmd #" + std::to_string(k);
            std::vector<std::string> transitions;
            for (pugi::xml_node t : c.children("Transition")) transitions.push_back(t.text().get());
            EXPECT_FALSE(transitions.empty()) << at;
            EXPECT_EQ(transitions, ours.transitions) << at;
            for (const std::string& t : transitions)
                EXPECT_TRUE(t == "IP" || t == "PS" || t == "SO" || t == "SP" || t == "OP" || t == "OS" || t == "PI" || t == "SI" ||
                            t == "OI" || t == "II" || t == "IB" || t == "BI")
                    << at << ": transition " << t;
            const std::optional<long long> ccs = python_int_base0(only_child(c, "Ccs", at).text().get());
            const std::optional<long long> index = python_int_base0(only_child(c, "Index", at).text().get());
            const std::optional<long long> sub = python_int_base0(only_child(c, "SubIndex", at).text().get());
            const std::optional<long long> timeout = python_int_base0(only_child(c, "Timeout", at).text().get());
            ASSERT_TRUE(ccs && index && sub && timeout) << at << ": a field int(text, 0) refuses";
            EXPECT_EQ(*ccs, 1) << at << ": an SDO download";
            EXPECT_EQ(*index, ours.index) << at;
            EXPECT_EQ(*sub, ours.subindex) << at;
            const pugi::xml_attribute ca = c.attribute("CompleteAccess");
            EXPECT_EQ(std::string(ca.value()) == "1", ours.complete_access) << at << ": CompleteAccess='" << ca.value() << "'";
            if (ca) {
                EXPECT_STREQ(ca.value(), "1") << at << ": the converter takes complete access only from \"1\"";
            }
            const pugi::xml_attribute disabled = c.attribute("Disabled");
            EXPECT_TRUE(!disabled || std::string(disabled.value()) == "0") << at << ": a command the network runs is not disabled";
            const std::string data = c.child("Data").text().get();
            ASSERT_TRUE(data.empty() || (data.size() % 2 == 0 && all_of(data, "0123456789abcdefABCDEF")))
                << at << ": Data '" << data << "' is no bytes.fromhex";
            std::vector<std::uint8_t> bytes;
            for (std::size_t b = 0; b < data.size(); b += 2)
                bytes.push_back(static_cast<std::uint8_t>(std::stoul(data.substr(b, 2), nullptr, 16)));
            EXPECT_EQ(bytes, ours.data) << at;
            ++commands_checked;
        }
    }
    const bool model_has_commands = std::any_of(model.begin(), model.end(), [](const auto& s) { return !s.coe_init_cmds.empty(); });
    if (model_has_commands) {
        EXPECT_GT(commands_checked, 0u);
    }
}

TEST_P(EniReaders, CherryEcatParserRulesHoldForTheIdentitiesAndPdoAssignment) {
    ESI_REQUIRE_CORPUS();
    const auto w = written(GetParam());
    ASSERT_TRUE(w->built.network) << esi::test::diagnostics_text(w->built.diagnostics);
    ASSERT_TRUE(w->parsed) << w->parsed.description();
    std::vector<pugi::xml_node> slaves;
    // The parser finds every .//Slave in the document.
    for (const pugi::xpath_node& s : w->eni.select_nodes("//Slave")) slaves.push_back(s.node());
    const std::vector<esi::net::NetworkSlave>& model = w->built.network->slaves;
    ASSERT_EQ(slaves.size(), model.size());
    for (std::size_t i = 0; i < slaves.size(); ++i) {
        const esi::net::NetworkSlave& s = model[i];
        const std::string where = "slave " + std::to_string(i + 1) + " (" + s.name + ")";
        const pugi::xml_node info = slaves[i].child("Info");
        for (const auto& [name, value] : {std::pair<const char*, std::uint32_t>{"VendorId", s.vendor_id},
                                          {"ProductCode", s.product_code}, {"RevisionNo", s.revision}}) {
            const std::string text = info.child(name).text().get();
            const std::optional<long long> read = python_int(text);
            ASSERT_TRUE(read) << where << ": " << name << " '" << text << "' is not decimal: int(text) fails the whole parse";
            EXPECT_EQ(as_u32(*read), value) << where << ": " << name;
        }
        // What the parser tables: every RxPdo, then every TxPdo, as "RxPDO 0x1601: 2 entries".
        std::vector<std::string> seen;
        for (const char* element : {"RxPdo", "TxPdo"})
            for (pugi::xml_node pdo : slaves[i].child("ProcessData").children(element)) {
                const std::string index = pdo.child("Index").text().get();
                ASSERT_TRUE(index.rfind("#x", 0) == 0 && all_of(index.substr(2), "0123456789abcdefABCDEF"))
                    << where << ": PDO index '" << index << "' without the #x prefix the parser needs";
                EXPECT_TRUE(pdo.attribute("Sm")) << where << ": " << element << " " << index
                                                 << " is not assigned, and the parser would map it anyway";
                std::size_t entries = 0;
                for (pugi::xml_node e : pdo.children("Entry")) {
                    ++entries;
                    const std::string bit_len = e.child("BitLen").text().get();
                    EXPECT_TRUE(python_int(bit_len)) << where << ": BitLen '" << bit_len << "'";
                    if (const std::string sub = e.child("SubIndex").text().get(); e.child("SubIndex")) {
                        EXPECT_TRUE(python_int(sub)) << where << ": SubIndex '" << sub << "'";
                    }
                }
                seen.push_back(std::string(element[0] == 'R' ? "RxPDO " : "TxPDO ") +
                               hex(std::stoul(index.substr(2), nullptr, 16), 4) + ": " + std::to_string(entries) + " entries");
            }
        std::vector<std::string> ours;
        for (const esi::PdoDirection direction : {esi::PdoDirection::rx, esi::PdoDirection::tx})
            for (const esi::net::ConfiguredPdo& p : s.pdos)
                if (p.direction == direction)
                    ours.push_back(std::string(direction == esi::PdoDirection::rx ? "RxPDO " : "TxPDO ") + hex(p.index, 4) + ": " +
                                   std::to_string(p.entries.size()) + " entries");
        EXPECT_EQ(seen, ours) << where;
    }
}

// The number forms the two readers take, judged as Python judges them: what int(text) and
// int(text, 0) refuse fails the rules above.
TEST(EniReaderRules, NumberFormsAreJudgedAsPythonJudgesThem) {
    EXPECT_FALSE(python_int("0x2"));
    EXPECT_EQ(python_int("-536870911"), -536870911);
    EXPECT_FALSE(python_int_base0("0100"));
    EXPECT_FALSE(python_int_base0("#x1600"));
    EXPECT_EQ(python_int_base0("0x1A00"), 0x1A00);
    EXPECT_EQ(python_int_base0("0"), 0);
    EXPECT_EQ(as_u32(*python_int("-1")), 0xFFFFFFFFu);
}

INSTANTIATE_TEST_SUITE_P(CorpusNetworks, EniReaders, ::testing::ValuesIn(esi::test::corpus_networks()),
                         [](const auto& info) {
                             std::string name = info.param.name;
                             for (char& c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return name;
                         });

}  // namespace
