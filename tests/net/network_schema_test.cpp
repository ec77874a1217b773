// schemas/esi-network.schema.json against the reader and the samples:
//  - it declares exactly the keys the reader accepts, context by context (esi/net/network_keys.hpp);
//  - every network in samples/networks/ validates against it in Python's jsonschema (a
//    validator libesi's authors did not write), reading YAML as editors do (keys as written);
//  - a network with an unknown key or a bad PDO entry is rejected there too, so the check can fail.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <set>

#include "esi/net/network_keys.hpp"
#include "esi/net/network_spec.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

fs::path schema_path() { return esi::test::source_dir() / "schemas" / "esi-network.schema.json"; }

TEST(NetworkSchema, DeclaresExactlyTheKeysTheReaderAccepts) {
    const json schema = json::parse(esi::test::read_text(schema_path()));
    for (const esi::net::NetworkContextKeys& context : esi::net::network_contexts()) {
        ASSERT_TRUE(schema["definitions"].contains(std::string(context.name))) << context.name;
        std::set<std::string> declared, accepted;
        for (auto it = schema["definitions"][std::string(context.name)]["properties"].begin();
             it != schema["definitions"][std::string(context.name)]["properties"].end(); ++it)
            declared.insert(it.key());
        for (std::string_view key : context.keys) accepted.insert(std::string(key));
        EXPECT_EQ(declared, accepted) << context.name;
    }
}

// Validates YAML files with Python's jsonschema; returns the validator's messages ("" when valid).
std::string python_validate(const std::vector<fs::path>& files) {
    static const char* script = R"(
import json, sys, yaml, jsonschema
class Loader(yaml.SafeLoader):
    pass
def mapping(loader, node):
    # Keys as written: an editor's YAML->JSON keeps "0x1607" as the key text.
    return {(k.value if isinstance(k, yaml.ScalarNode) else loader.construct_object(k)): loader.construct_object(v, deep=True)
            for k, v in node.value}
Loader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_MAPPING_TAG, mapping)
schema = json.load(open(sys.argv[1]))
validator = jsonschema.Draft7Validator(schema)
for path in sys.argv[2:]:
    for error in validator.iter_errors(yaml.load(open(path), Loader=Loader)):
        print(path, list(error.absolute_path), error.message)
)";
    std::vector<std::string> argv = {"python3", "-c", script, schema_path().string()};
    for (const fs::path& f : files) argv.push_back(f.string());
    const auto r = esi::test::run(argv);
    return r.exit_code == 0 ? r.out : "python failed: " + r.err;
}

bool have_python_jsonschema() {
    return esi::test::run({"python3", "-c", "import jsonschema, yaml"}).exit_code == 0;
}

TEST(NetworkSchema, TheSampleNetworksValidate) {
    if (!have_python_jsonschema()) GTEST_SKIP() << "python3 with jsonschema and PyYAML not installed: schema validation skipped";
    std::vector<fs::path> samples;
    for (const auto& entry : fs::directory_iterator(esi::test::source_dir() / "samples" / "networks"))
        if (entry.path().extension() == ".yaml") samples.push_back(entry.path());
    ASSERT_FALSE(samples.empty());
    for (const fs::path& sample : samples) {
        const esi::net::NetworkFileResult read = esi::net::read_network_file(sample.string());
        EXPECT_TRUE(read.spec) << sample;
    }
    EXPECT_EQ(python_validate(samples), "");
}

TEST(NetworkSchema, RejectsWhatTheReaderRejects) {
    if (!have_python_jsonschema()) GTEST_SKIP() << "python3 with jsonschema and PyYAML not installed: schema validation skipped";
    esi::test::TempDir dir;
    esi::test::write_text(dir / "a.yaml", "slaves:\n  - { devise: EL1008 }\n");
    esi::test::write_text(dir / "b.yaml", "slaves:\n  - { device: X, pdo_entries: { 0x1600: [0x6040-0-16] } }\n");
    esi::test::write_text(dir / "c.yaml", "slaves:\n  - { device: X, sdos: [{ index: 0x6060, transition: XS }] }\n");
    for (const char* name : {"a.yaml", "b.yaml", "c.yaml"}) {
        EXPECT_FALSE(esi::net::read_network_file((dir / name).string()).spec) << name;
        EXPECT_NE(python_validate({dir / name}), "") << name;
    }
}

}  // namespace
