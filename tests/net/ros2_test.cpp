// The ROS 2 output (ethercat_driver_ros2 slave configs and the ros2_control xacro) against the
// driver's own example configurations in ../shared/corpus/master-configs/ros2/, read by PyYAML
// (a reader libesi's authors did not write, as YAML-CPP is for the driver):
//  - for the corpus devices whose hand-written config follows the ESI revision in the corpus
//    (EL1008, EL2008, EL4132, the Elmo Gold drive with the hand-written PDO contents), the same
//    PDOs, entries (index, sub-index, type), bool masks and CiA 402 interface names;
//  - EL3102 and the ATI sensor differ for reasons of data (docs/esi-net.md), asserted as such;
//  - refusals: PDOs of one direction on two SMs (EL1252), an override of an unmapped entry or
//    of an entry the driver cannot read; text that could break YAML or xacro stays text.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <pugixml.hpp>

#include <algorithm>

#include "esi/net/ros2_config.hpp"
#include "net/net_test_support.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

fs::path ros2_dir() { return esi::test::corpus_dir() / "master-configs" / "ros2"; }

bool have_pyyaml() { return esi::test::run({"python3", "-c", "import yaml"}).exit_code == 0; }

// YAML texts as JSON through PyYAML (YAML 1.1, as YAML-CPP reads 0x… numbers as integers), all
// in one python run: starting python is what takes the time here.
std::vector<json> load_yamls(const std::vector<std::string>& texts) {
    static const char* script = R"(
import json, math, sys, yaml
def clean(v):
    if isinstance(v, float) and math.isnan(v): return "nan"
    if isinstance(v, dict): return {str(k): clean(x) for k, x in v.items()}
    if isinstance(v, list): return [clean(x) for x in v]
    return v
print(json.dumps([clean(yaml.safe_load(t)) for t in json.loads(sys.stdin.read())]))
)";
    const auto r = esi::test::run({"python3", "-c", script}, json(texts).dump());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    if (r.exit_code != 0) return std::vector<json>(texts.size());
    return json::parse(r.out).get<std::vector<json>>();
}

json load_yaml(const std::string& text) { return load_yamls({text})[0]; }

// "rpdo 0x1600: 7000:01 bool mask 1" lines: what the driver maps and how it reads each channel.
std::vector<std::string> mapping_of(const json& config, bool with_interfaces) {
    std::vector<std::string> out;
    for (const char* key : {"rpdo", "tpdo"}) {
        if (!config.contains(key)) continue;
        for (const json& pdo : config[key]) {
            out.push_back(std::string(key) + " " + std::to_string(pdo["index"].get<int>()));
            for (const json& c : pdo["channels"]) {
                std::string line = "  " + std::to_string(c["index"].get<int>()) + ":" + std::to_string(c["sub_index"].get<int>()) + " " +
                                   c["type"].get<std::string>();
                if (c.contains("mask")) line += " mask " + std::to_string(c["mask"].get<int>());
                const char* iface = std::string(key) == "rpdo" ? "command_interface" : "state_interface";
                if (with_interfaces && c.contains(iface) && !c[iface].is_null()) line += " " + c[iface].get<std::string>();
                out.push_back(line);
            }
        }
    }
    return out;
}

std::string ours(const std::string& network_yaml, esi::Diagnostics* diagnostics = nullptr) {
    const esi::net::BuildResult built = esi::test::build_corpus_network(network_yaml);
    EXPECT_TRUE(built.network) << esi::test::diagnostics_text(built.diagnostics);
    if (!built.network) return {};
    esi::Diagnostics d;
    std::string text = esi::net::write_ros2_slave_config(*built.network, 0, d);
    EXPECT_FALSE(d.has_errors()) << esi::test::diagnostics_text(d);
    if (diagnostics) *diagnostics = d;
    return text;
}

struct HandWritten {
    const char* file;
    const char* network;
    bool interfaces;  // the names are the driver's CiA 402 conventions, so they must agree too
    std::vector<std::pair<std::string, std::string>> differences;  // our line -> theirs, each with its reason
};

const char* elmo_network = R"(slaves:
  - name: Axis
    product_code: 0x00030924
    revision: 0x00010420
    pdos: [0x1607, 0x1A07]
    pdo_entries:
      0x1607: [0x607A:0:32, 0x60FF:0:32, 0x6071:0:16, 0x6072:0:16, 0x6040:0:16, 0x6060:0:8]
      0x1A07: [0x6064:0:32, 0x606C:0:32, 0x6077:0:16, 0x6041:0:16, 0x6061:0:8, 0x2205:1:16]
)";

TEST(Ros2, MapsTheSamePdosEntriesAndTypesAsTheHandWrittenConfigs) {
    ESI_REQUIRE_CORPUS();
    if (!have_pyyaml()) GTEST_SKIP() << "python3 with PyYAML is not installed";
    const HandWritten cases[] = {
        {"beckhoff_el1008.yaml", "slaves: [{ name: DI, device: EL1008 }]", false, {}},
        {"beckhoff_el2008.yaml", "slaves: [{ name: DO, device: EL2008, revision: 0x00120000 }]", false, {}},
        // Max torque 0x6072 is UINT in the ESI (UNSIGNED16 in CiA 402); the hand-written file says int16.
        {"elmo_gold.yaml", "", true, {{"  24690:0 uint16", "  24690:0 int16"}}},
    };
    for (const HandWritten& c : cases) {
        SCOPED_TRACE(c.file);
        std::string network = *c.network ? c.network : elmo_network;
        // The hand-written file leaves controlword, statusword and the mode objects unnamed.
        if (!*c.network) network += "    ros2_interfaces: { 0x6040:0: ~, 0x6041:0: ~, 0x6061:0: ~, 0x6060:0: ~, 0x6072:0: ~, 0x2205:1: analog_input1 }\n";
        const std::vector<json> loaded = load_yamls({esi::test::read_text(ros2_dir() / c.file), ours(network)});
        const json& theirs = loaded[0];
        const json& generated = loaded[1];
        EXPECT_EQ(generated["vendor_id"], theirs["vendor_id"]);
        EXPECT_EQ(generated["product_id"], theirs["product_id"]);
        if (theirs.contains("assign_activate")) {
            EXPECT_EQ(generated["assign_activate"], theirs["assign_activate"]);
        }
        std::vector<std::string> mine = mapping_of(generated, c.interfaces);
        for (const auto& [ours_line, theirs_line] : c.differences) {
            const auto it = std::find(mine.begin(), mine.end(), ours_line);
            ASSERT_NE(it, mine.end()) << "the listed difference '" << ours_line << "' is gone";
            *it = theirs_line;
        }
        EXPECT_EQ(mine, mapping_of(theirs, c.interfaces));
    }
}

TEST(Ros2, El4132El3102AndTheAtiSensorDifferWhereTheirDataDo) {
    ESI_REQUIRE_CORPUS();
    if (!have_pyyaml()) GTEST_SKIP() << "python3 with PyYAML is not installed";
    // EL4132: the same two RxPDOs of one INT each; the hand-written file maps 0x3001:01/0x3002:01,
    // every EL4132 revision of the corpus maps 0x6411:01/02.
    const std::vector<json> loaded = load_yamls({esi::test::read_text(ros2_dir() / "beckhoff_el4132.yaml"),
                                                 ours("slaves: [{ name: AO, device: EL4132, revision: 0x03FA0000 }]"),
                                                 esi::test::read_text(ros2_dir() / "ati_ftsensor.yaml"),
                                                 ours("slaves: [{ name: FT, vendor_id: 2, product_code: 0x26483052 }]")});
    const json& theirs = loaded[0];
    const json& generated = loaded[1];
    ASSERT_EQ(generated["rpdo"].size(), theirs["rpdo"].size());
    for (std::size_t i = 0; i < theirs["rpdo"].size(); ++i) {
        EXPECT_EQ(generated["rpdo"][i]["index"], theirs["rpdo"][i]["index"]);
        EXPECT_EQ(generated["rpdo"][i]["channels"][0]["type"], theirs["rpdo"][i]["channels"][0]["type"]);
        EXPECT_EQ(generated["rpdo"][i]["channels"][0]["index"].get<int>(), 0x6411);
        EXPECT_EQ(theirs["rpdo"][i]["channels"][0]["index"].get<int>(), 0x3001 + static_cast<int>(i));
    }
    // EL3102: the corpus has it only in the pre-ETG.2000 catalogue, whose PDOs are references
    // without indices: the ROS 2 output is refused rather than written empty.
    const esi::net::BuildResult el3102 = esi::test::build_corpus_network("slaves: [{ name: AI, device: EL3102 }]");
    ASSERT_TRUE(el3102.network) << esi::test::diagnostics_text(el3102.diagnostics);
    const esi::net::Ros2Output refused = esi::net::ros2_outputs(*el3102.network, "out");
    EXPECT_TRUE(refused.files.empty());
    EXPECT_NE(esi::test::diagnostics_text(refused.diagnostics).find("[net-ros2-layout]"), std::string::npos);
    // The ATI sensor reuses the EL9800 evaluation board's product code under its own vendor id;
    // the corpus has only Beckhoff's EL9800 ESI (vendor 2), whose PDOs are the board's.
    const json& ati = loaded[2];
    const json& board = loaded[3];
    EXPECT_EQ(board["product_id"], ati["product_id"]);
    EXPECT_NE(board["vendor_id"], ati["vendor_id"]);
}

TEST(Ros2, Cia402DrivesGetTheDriversInterfaceNamesAndPlugin) {
    ESI_REQUIRE_CORPUS();
    if (!have_pyyaml()) GTEST_SKIP() << "python3 with PyYAML is not installed";
    const esi::net::BuildResult built = esi::test::build_corpus_network(std::string("master: { cycle_time_us: 2000 }\n") + elmo_network);
    ASSERT_TRUE(built.network) << esi::test::diagnostics_text(built.diagnostics);
    esi::Diagnostics d;
    const json config = load_yaml(esi::net::write_ros2_slave_config(*built.network, 0, d));
    std::map<int, json> rx;
    for (const json& p : config["rpdo"])
        for (const json& c : p["channels"]) rx[c["index"].get<int>()] = c;
    EXPECT_EQ(rx[0x607A]["command_interface"], "position");
    EXPECT_EQ(rx[0x607A]["default"], "nan");
    EXPECT_EQ(rx[0x6040]["default"], 0);
    EXPECT_EQ(rx[0x6060]["default"], 8);  // CSP: the target position is mapped
    // The ESI's InitCmd sets the interpolation period to the cycle (2 ms), sent in PREOP.
    bool interpolation = false;
    for (const json& s : config["sdo"]) interpolation = interpolation || (s["index"] == 0x60C2 && s["sub_index"] == 1 && s["value"] == 2);
    EXPECT_TRUE(interpolation) << config.dump();

    pugi::xml_document xacro;
    ASSERT_TRUE(xacro.load_string(esi::net::write_ros2_control_xacro(*built.network).c_str()));
    const pugi::xml_node joint = xacro.select_node("//ros2_control/joint").node();
    ASSERT_TRUE(joint);
    EXPECT_STREQ(joint.child("ec_module").child_value("plugin"), "ethercat_generic_plugins/EcCiA402Drive");
    EXPECT_TRUE(joint.find_child_by_attribute("command_interface", "name", "reset_fault"));
    EXPECT_STREQ(xacro.select_node("//hardware/param[@name='control_frequency']").node().child_value(), "500");
}

TEST(Ros2, TextStaysTextInYamlAndXacro) {
    ESI_REQUIRE_CORPUS();
    if (!have_pyyaml()) GTEST_SKIP() << "python3 with PyYAML is not installed";
    const esi::net::BuildResult built = esi::test::build_corpus_network(R"(slaves:
  - name: "a \"b\" ${evil}\nc: d # e"
    device: EL2008
    revision: 0x00120000
    ros2_interfaces: { 0x7000:0x01: "x:y#z,[a]{b}&*!|>%@" }
  - { name: "a \"b\" ${evil}\nc: d # e!", device: EL1008, revision: 0x00100000 }
)");
    ASSERT_TRUE(built.network) << esi::test::diagnostics_text(built.diagnostics);
    const esi::net::Ros2Output out = esi::net::ros2_outputs(*built.network, "out");
    ASSERT_FALSE(out.diagnostics.has_errors()) << esi::test::diagnostics_text(out.diagnostics);
    ASSERT_EQ(out.files.size(), 3u);
    EXPECT_EQ(out.files[0].path, fs::path("out/ros2/a__b____evil__c__d___e.yaml"));
    EXPECT_EQ(out.files[1].path, fs::path("out/ros2/a__b____evil__c__d___e_.yaml"));
    const json config = load_yaml(out.files[0].content);
    EXPECT_EQ(config["rpdo"][0]["channels"][0]["command_interface"], "x:y#z,[a]{b}&*!|>%@");
    EXPECT_EQ(config.size(), 4u) << config.dump();  // vendor_id, product_id, rpdo, sm: nothing injected
    pugi::xml_document xacro;
    ASSERT_TRUE(xacro.load_string(out.files[2].content.c_str()));
    // xacro's escape for '$': the name can never be evaluated as ${…}.
    EXPECT_STREQ(xacro.select_node("//gpio").node().attribute("name").value(), "a \"b\" $${evil}\nc: d # e");
}

TEST(Ros2, FileNamesAreSafeAndUnique) {
    ESI_REQUIRE_CORPUS();
    const esi::net::BuildResult built = esi::test::build_corpus_network(
        "slaves:\n  - { name: ../x, device: EL1008 }\n  - { name: _.._x, device: EL1008 }\n  - { name: ..-x, device: EL1008 }\n");
    ASSERT_TRUE(built.network) << esi::test::diagnostics_text(built.diagnostics);
    EXPECT_EQ(esi::net::ros2_config_file_names(*built.network), (std::vector<std::string>{"_.._x.yaml", "_.._x-2.yaml", "_..-x.yaml"}));
}

TEST(Ros2, RefusesPdosOfOneDirectionOnTwoSyncManagers) {
    ESI_REQUIRE_CORPUS();
    // EL1252: its latch PDO sits on the virtual SM1, its inputs on SM3; the driver has one tpdo list.
    const esi::net::BuildResult built = esi::test::build_corpus_network("slaves: [{ name: Latch, product_code: 0x04E43052, revision: 0x00120000 }]");
    ASSERT_TRUE(built.network) << esi::test::diagnostics_text(built.diagnostics);
    const esi::net::Ros2Output out = esi::net::ros2_outputs(*built.network, "out");
    EXPECT_TRUE(out.diagnostics.has_errors());
    EXPECT_TRUE(out.files.empty());
    EXPECT_NE(esi::test::diagnostics_text(out.diagnostics).find("net-ros2-layout"), std::string::npos);
}

TEST(Ros2, InterfaceOverridesAreChecked) {
    ESI_REQUIRE_CORPUS();
    const esi::net::BuildResult unmapped =
        esi::test::build_corpus_network("slaves:\n  - name: DI\n    device: EL1008\n    ros2_interfaces: { 0x6000:0x02: x }\n");
    EXPECT_FALSE(unmapped.network);
    EXPECT_NE(esi::test::diagnostics_text(unmapped.diagnostics).find("network.yaml:4:"), std::string::npos)
        << esi::test::diagnostics_text(unmapped.diagnostics);
    const esi::net::BuildResult bad_name =
        esi::test::build_corpus_network("slaves:\n  - name: DI\n    device: EL1008\n    ros2_interfaces: { 0x6000:0x01: a/b }\n");
    EXPECT_FALSE(bad_name.network);
    const esi::net::BuildResult renamed = esi::test::build_corpus_network(
        "slaves:\n  - name: DI\n    device: EL1008\n    ros2_interfaces: { 0x6000:0x01: { name: d_input.1, factor: 2 } }\n");
    ASSERT_TRUE(renamed.network) << esi::test::diagnostics_text(renamed.diagnostics);
    esi::Diagnostics d;
    const std::string text = esi::net::write_ros2_slave_config(*renamed.network, 0, d);
    EXPECT_NE(text.find("mask: 1, state_interface: \"d_input.1\", factor: 2}"), std::string::npos) << text;
}

TEST(Ros2, OutputIsDeterministic) {
    ESI_REQUIRE_CORPUS();
    for (const esi::test::NamedNetwork& n : esi::test::corpus_networks()) {
        const esi::net::BuildResult a = esi::test::build_corpus_network(n.yaml);
        const esi::net::BuildResult b = esi::test::build_corpus_network(n.yaml);
        ASSERT_TRUE(a.network && b.network) << n.name;
        const esi::net::Ros2Output x = esi::net::ros2_outputs(*a.network, "o");
        const esi::net::Ros2Output y = esi::net::ros2_outputs(*b.network, "o");
        ASSERT_EQ(x.files.size(), y.files.size());
        for (std::size_t i = 0; i < x.files.size(); ++i) EXPECT_EQ(x.files[i].content, y.files[i].content) << n.name;
    }
}

}  // namespace
