// The generated ENI read by two readers libesi's authors did not write:
//  - the ETG.2100 schema v1.6 (xmllint): every generated file validates;
//  - SOEM's converter (scripts/eniconv.py): the same identities and CoE start-up commands
//    (transitions, complete access, index, sub-index, data bytes) as the network model;
//  - CherryECAT's parser (scripts/eni_parser.py): the same identities and PDO assignment
//    (the assigned PDOs of each direction and their entry counts).

#include <gtest/gtest.h>

#include <map>
#include <cstdio>
#include <sstream>

#include "esi/net/outputs.hpp"
#include "net/net_test_support.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;

std::string hex(unsigned long long v, int digits) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "0x%0*llX", digits, v);
    return buf;
}

fs::path readers_dir() { return esi::test::shared_dir() / "tools" / "eni-readers"; }

bool have_tool(const std::string& name) {
    return esi::test::run({"/bin/sh", "-c", "command -v " + name}).exit_code == 0;
}

std::string trim_line(const std::string& line) {
    const std::size_t a = line.find_first_not_of(" \t");
    const std::size_t b = line.find_last_not_of(" \t\r,");
    return a == std::string::npos ? std::string() : line.substr(a, b - a + 1);
}

struct SoemCommand {
    std::string transition;
    bool ca = false;
    unsigned index = 0, subindex = 0;
    std::vector<unsigned> data;
};

struct SoemSlave {
    unsigned slave = 0;
    unsigned long long vendor = 0, product = 0, revision = 0;
    std::vector<SoemCommand> commands;
};

// SOEM's generated C: the data arrays, the command arrays and the slave table.
std::vector<SoemSlave> parse_soem(const std::string& c) {
    std::map<std::string, std::vector<unsigned>> data;
    std::map<std::string, std::vector<SoemCommand>> commands;
    std::vector<std::pair<SoemSlave, std::string>> slaves;
    std::istringstream in(c);
    std::string line, array, kind;
    std::vector<std::pair<std::string, std::size_t>> data_refs;  // per command of the current array
    while (std::getline(in, line)) {
        const std::string t = trim_line(line);
        if (t.rfind("static uint8 ", 0) == 0) {
            kind = "data";
            array = t.substr(13, t.find('[') - 13);
        } else if (t.rfind("static ec_enicoecmdt ", 0) == 0) {
            kind = "cmds";
            array = t.substr(21, t.find('[') - 21);
        } else if (t.rfind("static ec_enislavet ", 0) == 0) {
            kind = "slaves";
        } else if (t == "};") {
            kind.clear();
        } else if (kind == "data" && !t.empty() && std::isdigit(static_cast<unsigned char>(t[0]))) {
            std::istringstream nums(t);
            std::string n;
            while (std::getline(nums, n, ',')) data[array].push_back(static_cast<unsigned>(std::stoul(trim_line(n))));
        } else if (kind == "cmds") {
            auto value = [&](const char* key) { return trim_line(t.substr(std::string(key).size())); };
            if (t == "{") commands[array].emplace_back();
            else if (t.rfind(".Transition = ", 0) == 0) commands[array].back().transition = value(".Transition = ");
            else if (t.rfind(".CA = ", 0) == 0) commands[array].back().ca = value(".CA = ") == "TRUE";
            else if (t.rfind(".Index = ", 0) == 0) commands[array].back().index = static_cast<unsigned>(std::stoul(value(".Index = "), nullptr, 16));
            else if (t.rfind(".SubIdx = ", 0) == 0) commands[array].back().subindex = static_cast<unsigned>(std::stoul(value(".SubIdx = ")));
            else if (t.rfind(".DataSize = ", 0) == 0) commands[array].back().data.resize(std::stoul(value(".DataSize = ")));
            else if (t.rfind(".Data = (", 0) == 0) {
                const std::string ref = value(".Data = (");
                const std::string name = ref.substr(0, ref.find(' '));
                const std::size_t offset = std::stoul(ref.substr(ref.find('+') + 1));
                SoemCommand& cmd = commands[array].back();
                for (std::size_t i = 0; i < cmd.data.size(); ++i) cmd.data[i] = data[name].at(offset + i);
            }
        } else if (kind == "slaves") {
            auto value = [&](const char* key) { return trim_line(t.substr(std::string(key).size())); };
            if (t == "{") slaves.emplace_back();
            else if (t.rfind(".Slave = ", 0) == 0) slaves.back().first.slave = static_cast<unsigned>(std::stoul(value(".Slave = ")));
            else if (t.rfind(".VendorId = ", 0) == 0) slaves.back().first.vendor = std::stoull(value(".VendorId = "));
            else if (t.rfind(".ProductCode = ", 0) == 0) slaves.back().first.product = std::stoull(value(".ProductCode = "));
            else if (t.rfind(".RevisionNo = ", 0) == 0) slaves.back().first.revision = std::stoull(value(".RevisionNo = "));
            else if (t.rfind(".CoECmds = ", 0) == 0) slaves.back().second = value(".CoECmds = ");
        }
    }
    std::vector<SoemSlave> out;
    for (auto& [slave, cmds] : slaves) {
        slave.commands = commands[cmds];
        out.push_back(slave);
    }
    return out;
}

std::string soem_transitions(const std::vector<std::string>& transitions) {
    std::string out;
    for (const std::string& t : transitions) out += (out.empty() ? "" : " | ") + ("ECT_ESMTRANS_" + t);
    return transitions.size() > 1 ? "(" + out + ")" : out;
}

// The n-th "// Vendor ID: 0x…" (or Product Code) line of CherryECAT's output. It reads the ENI's
// xs:int as written, so an identity at or above 0x80000000 (written signed, as the schema
// demands) prints as a negative number ("0x-1FFFFFFF"); taken modulo 2^32 it is the same value.
std::uint32_t printed_identity(const std::string& header, const std::string& label, std::size_t n) {
    std::size_t at = 0;
    for (std::size_t i = 0; i <= n; ++i) {
        at = header.find(label, i == 0 ? 0 : at + 1);
        if (at == std::string::npos) return 0;
    }
    std::string value = header.substr(at + label.size(), header.find('\n', at) - at - label.size());
    const bool negative = value.rfind("0x-", 0) == 0;
    const long long magnitude = std::stoll(value.substr(negative ? 3 : 2), nullptr, 16);
    return static_cast<std::uint32_t>(negative ? -magnitude : magnitude);
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

TEST_P(EniReaders, SoemSeesTheIdentitiesAndStartUpCommands) {
    ESI_REQUIRE_CORPUS();
    if (!have_tool("python3")) GTEST_SKIP() << "python3 not installed: SOEM's ENI converter not run";
    const esi::net::BuildResult built = esi::test::build_corpus_network(GetParam().yaml);
    ASSERT_TRUE(built.network) << esi::test::diagnostics_text(built.diagnostics);
    esi::test::TempDir dir;
    esi::test::write_text(dir / "network.xml", esi::net::write_eni(*built.network));
    const auto result = esi::test::run({"python3", (readers_dir() / "soem_eniconv.py").string(), (dir / "network.xml").string(),
                                        (dir / "soem.c").string()});
    ASSERT_EQ(result.exit_code, 0) << result.err;
    const std::vector<SoemSlave> soem = parse_soem(esi::test::read_text(dir / "soem.c"));
    std::size_t with_commands = 0;
    for (const esi::net::NetworkSlave& s : built.network->slaves) {
        if (s.coe_init_cmds.empty()) continue;
        ++with_commands;
        const auto it = std::find_if(soem.begin(), soem.end(), [&](const SoemSlave& x) { return x.slave == s.position + 1; });
        ASSERT_NE(it, soem.end()) << "SOEM lost slave " << s.position + 1;
        EXPECT_EQ(it->vendor, s.vendor_id);
        EXPECT_EQ(it->product, s.product_code);
        EXPECT_EQ(it->revision, s.revision);
        ASSERT_EQ(it->commands.size(), s.coe_init_cmds.size()) << s.name;
        for (std::size_t i = 0; i < s.coe_init_cmds.size(); ++i) {
            const esi::net::CoeCommand& ours = s.coe_init_cmds[i];
            const SoemCommand& theirs = it->commands[i];
            EXPECT_EQ(theirs.transition, soem_transitions(ours.transitions)) << s.name << " #" << i;
            EXPECT_EQ(theirs.ca, ours.complete_access) << s.name << " #" << i;
            EXPECT_EQ(theirs.index, ours.index) << s.name << " #" << i;
            EXPECT_EQ(theirs.subindex, ours.subindex) << s.name << " #" << i;
            EXPECT_EQ(theirs.data, std::vector<unsigned>(ours.data.begin(), ours.data.end())) << s.name << " #" << i;
        }
    }
    EXPECT_EQ(soem.size(), with_commands);
}

TEST_P(EniReaders, CherryEcatSeesTheIdentitiesAndPdoAssignment) {
    ESI_REQUIRE_CORPUS();
    if (!have_tool("python3")) GTEST_SKIP() << "python3 not installed: CherryECAT's ENI parser not run";
    const esi::net::BuildResult built = esi::test::build_corpus_network(GetParam().yaml);
    ASSERT_TRUE(built.network) << esi::test::diagnostics_text(built.diagnostics);
    esi::test::TempDir dir;
    esi::test::write_text(dir / "network.xml", esi::net::write_eni(*built.network));
    const auto result = esi::test::run({"python3", (readers_dir() / "cherryecat_eni_parser.py").string(), (dir / "network.xml").string(),
                                        (dir / "cherry.h").string()});
    ASSERT_EQ(result.exit_code, 0) << result.out << result.err;
    // Its summary: "✓ Slave N:" then "  - RxPDO 0x1601: 2 entries" per PDO.
    std::vector<std::vector<std::string>> seen;
    std::istringstream out(result.out);
    for (std::string line; std::getline(out, line);) {
        if (line.find("Slave ") != std::string::npos && line.back() == ':') seen.emplace_back();
        else if (line.rfind("  - ", 0) == 0 && !seen.empty()) seen.back().push_back(line.substr(4));
    }
    ASSERT_EQ(seen.size(), built.network->slaves.size()) << result.out;
    const std::string header = esi::test::read_text(dir / "cherry.h");
    for (const esi::net::NetworkSlave& s : built.network->slaves) {
        std::vector<std::string> ours;
        for (const esi::PdoDirection direction : {esi::PdoDirection::rx, esi::PdoDirection::tx})
            for (const esi::net::ConfiguredPdo& p : s.pdos)
                if (p.direction == direction)
                    ours.push_back(std::string(direction == esi::PdoDirection::rx ? "RxPDO " : "TxPDO ") + hex(p.index, 4) + ": " +
                                   std::to_string(p.entries.size()) + " entries");
        EXPECT_EQ(seen[s.position], ours) << s.name;
        EXPECT_EQ(printed_identity(header, "// Vendor ID: ", s.position), s.vendor_id) << s.name;
        EXPECT_EQ(printed_identity(header, "// Product Code: ", s.position), s.product_code) << s.name;
    }
}

INSTANTIATE_TEST_SUITE_P(CorpusNetworks, EniReaders, ::testing::ValuesIn(esi::test::corpus_networks()),
                         [](const auto& info) {
                             std::string name = info.param.name;
                             for (char& c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return name;
                         });

}  // namespace
