// schemas/esi-device.schema.json against the parser and the samples:
//  - the schema declares exactly the keys the parser accepts, context by context;
//  - every sample validates against it (a small validator for the JSON Schema subset the schema
//    uses; a test checks that the schema uses no other keyword);
//  - the validator does reject what it should, so the sample check can fail.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <regex.h>
#include <set>

#include "esi/import/import.hpp"
#include "esi/xml/reader.hpp"
#include "esi/yaml/format_keys.hpp"
#include "esi/yaml/tree.hpp"
#include "yaml/yaml_test_support.hpp"

using nlohmann::json;

namespace {

// POSIX extended regular expressions: the schema's patterns use only what ERE and ECMA-262 (JSON
// Schema's dialect) share. (std::regex trips a GCC 12 false positive under the sanitizers.)
bool matches(const std::string& text, const std::string& pattern) {
    regex_t re;
    if (regcomp(&re, pattern.c_str(), REG_EXTENDED | REG_NOSUB) != 0) {
        ADD_FAILURE() << "bad pattern " << pattern;
        return false;
    }
    const bool found = regexec(&re, text.c_str(), 0, nullptr, 0) == 0;
    regfree(&re);
    return found;
}

json load_schema() { return json::parse(esi::test::read_text(esi::test::source_dir() / "schemas" / "esi-device.schema.json")); }

// YAML -> JSON the way yaml-language-server sees it: the YAML 1.2 core schema for plain scalars,
// quoted scalars are strings, keys are strings as written.
json to_json(const esi::yaml::Node& node) {
    if (node.IsMap()) {
        json out = json::object();
        for (auto it = node.begin(); it != node.end(); ++it) out[it->first.Scalar()] = to_json(it->second);
        return out;
    }
    if (node.IsSequence()) {
        json out = json::array();
        for (const auto& item : node) out.push_back(to_json(item));
        return out;
    }
    if (node.IsNull()) return nullptr;
    const std::string s = node.Scalar();
    if (node.quoted()) return s;
    if (matches(s, "^(~|null|Null|NULL)$")) return nullptr;
    if (matches(s, "^(true|True|TRUE|false|False|FALSE)$")) return s[0] == 't' || s[0] == 'T';
    try {
        if (matches(s, "^[-+]?[0-9]+$")) return std::stoll(s);
        if (matches(s, "^0x[0-9a-fA-F]+$")) return std::stoll(s.substr(2), nullptr, 16);
        if (matches(s, "^0o[0-7]+$")) return std::stoll(s.substr(2), nullptr, 8);
    } catch (const std::out_of_range&) {
        return std::stod(s);
    }
    if (matches(s, "^[-+]?([.][0-9]+|[0-9]+([.][0-9]*)?)([eE][-+]?[0-9]+)?$")) return std::stod(s);
    return s;
}

json yaml_to_json(const std::string& text) {
    esi::Diagnostics diagnostics;
    bool empty = false;
    const auto tree = esi::yaml::Tree::parse(text, "test.yaml", esi::yaml::TreeLimits{}, diagnostics, empty);
    EXPECT_TRUE(tree) << (diagnostics.empty() ? "empty document" : diagnostics.items()[0].message);
    return tree ? to_json(esi::yaml::Node(tree->root())) : json();
}

json yaml_file_to_json(const std::filesystem::path& path) { return yaml_to_json(esi::test::read_text(path)); }

class Validator {
public:
    explicit Validator(json schema) : root_(std::move(schema)) {}

    std::vector<std::string> validate(const json& value) {
        errors_.clear();
        check(root_, value, "");
        return errors_;
    }

    static const std::set<std::string>& supported() {
        static const std::set<std::string> keywords = {
            "$schema", "$id", "title", "description", "$ref", "definitions", "type", "properties", "additionalProperties",
            "patternProperties", "required", "items", "enum", "pattern", "minimum", "maximum", "minItems", "maxItems",
            "minProperties", "anyOf", "oneOf"};
        return keywords;
    }

private:
    const json& resolve(const std::string& ref) const {
        const std::string prefix = "#/definitions/";
        return root_.at("definitions").at(ref.substr(prefix.size()));
    }

    static bool has_type(const json& value, const std::string& type) {
        if (type == "object") return value.is_object();
        if (type == "array") return value.is_array();
        if (type == "string") return value.is_string();
        if (type == "boolean") return value.is_boolean();
        if (type == "integer") return value.is_number_integer();
        if (type == "number") return value.is_number();
        if (type == "null") return value.is_null();
        return false;
    }

    bool ok(const json& schema, const json& value) {
        const auto saved = errors_;
        const std::size_t before = errors_.size();
        check(schema, value, "");
        const bool good = errors_.size() == before;
        errors_ = saved;
        return good;
    }

    void check(const json& schema, const json& value, const std::string& at) {
        if (schema.contains("$ref")) check(resolve(schema["$ref"]), value, at);
        if (schema.contains("type")) {
            bool match = false;
            if (schema["type"].is_array()) {
                for (const auto& t : schema["type"]) match = match || has_type(value, t);
            } else {
                match = has_type(value, schema["type"]);
            }
            if (!match) {
                errors_.push_back(at + ": " + value.dump() + " is not of type " + schema["type"].dump());
                return;
            }
        }
        if (schema.contains("enum")) {
            bool found = false;
            for (const auto& e : schema["enum"]) found = found || e == value;
            if (!found) errors_.push_back(at + ": " + value.dump() + " is not one of " + schema["enum"].dump());
        }
        if (value.is_string() && schema.contains("pattern") && !matches(value.get<std::string>(), schema["pattern"].get<std::string>()))
            errors_.push_back(at + ": '" + value.get<std::string>() + "' does not match " + schema["pattern"].get<std::string>());
        if (value.is_number()) {
            if (schema.contains("minimum") && value.get<double>() < schema["minimum"].get<double>())
                errors_.push_back(at + ": below the minimum");
            if (schema.contains("maximum") && value.get<double>() > schema["maximum"].get<double>())
                errors_.push_back(at + ": above the maximum");
        }
        if (value.is_object()) {
            for (const auto& r : schema.value("required", json::array()))
                if (!value.contains(r.get<std::string>())) errors_.push_back(at + ": missing " + r.get<std::string>());
            if (schema.contains("minProperties") && value.size() < schema["minProperties"].get<std::size_t>())
                errors_.push_back(at + ": too few properties");
            for (auto it = value.begin(); it != value.end(); ++it) {
                bool known = false;
                if (schema.contains("properties") && schema["properties"].contains(it.key())) {
                    known = true;
                    check(schema["properties"][it.key()], it.value(), at + "/" + it.key());
                }
                if (schema.contains("patternProperties"))
                    for (auto p = schema["patternProperties"].begin(); p != schema["patternProperties"].end(); ++p)
                        if (matches(it.key(), p.key())) {
                            known = true;
                            check(p.value(), it.value(), at + "/" + it.key());
                        }
                if (known || !schema.contains("additionalProperties")) continue;
                const json& extra = schema["additionalProperties"];
                if (extra.is_boolean()) {
                    if (!extra.get<bool>()) errors_.push_back(at + ": unknown key '" + it.key() + "'");
                } else {
                    check(extra, it.value(), at + "/" + it.key());
                }
            }
        }
        if (value.is_array()) {
            if (schema.contains("minItems") && value.size() < schema["minItems"].get<std::size_t>()) errors_.push_back(at + ": too few items");
            if (schema.contains("maxItems") && value.size() > schema["maxItems"].get<std::size_t>()) errors_.push_back(at + ": too many items");
            if (schema.contains("items"))
                for (std::size_t i = 0; i < value.size(); ++i) check(schema["items"], value[i], at + "/" + std::to_string(i));
        }
        if (schema.contains("anyOf")) {
            bool any = false;
            for (const auto& alt : schema["anyOf"]) any = any || ok(alt, value);
            if (!any) errors_.push_back(at + ": " + value.dump().substr(0, 80) + " matches none of anyOf");
        }
        if (schema.contains("oneOf")) {
            int n = 0;
            for (const auto& alt : schema["oneOf"]) n += ok(alt, value) ? 1 : 0;
            if (n != 1) errors_.push_back(at + ": " + value.dump().substr(0, 80) + " matches " + std::to_string(n) + " of oneOf");
        }
    }

    json root_;
    std::vector<std::string> errors_;
};

void collect_keywords(const json& schema, std::set<std::string>& out, bool in_properties = false) {
    if (!schema.is_object()) {
        if (schema.is_array())
            for (const auto& item : schema) collect_keywords(item, out);
        return;
    }
    for (auto it = schema.begin(); it != schema.end(); ++it) {
        if (!in_properties) out.insert(it.key());
        const bool names_follow = !in_properties && (it.key() == "properties" || it.key() == "patternProperties" || it.key() == "definitions");
        if (it.key() == "enum" && !in_properties) continue;
        if (names_follow) {
            for (auto p = it.value().begin(); p != it.value().end(); ++p) collect_keywords(p.value(), out);
        } else {
            collect_keywords(it.value(), out, false);
        }
    }
}

std::string join(const std::vector<std::string>& items) {
    std::string out;
    for (const auto& i : items) out += i + "\n";
    return out;
}

}  // namespace

TEST(YamlSchema, UsesOnlyTheKeywordsTheTestValidatorImplements) {
    std::set<std::string> used;
    collect_keywords(load_schema(), used);
    for (const auto& k : used) EXPECT_TRUE(Validator::supported().count(k)) << "unsupported keyword " << k;
    EXPECT_TRUE(used.count("additionalProperties"));
}

TEST(YamlSchema, DeclaresExactlyTheKeysTheParserAccepts) {
    const json schema = load_schema();
    const json& definitions = schema.at("definitions");
    std::set<std::string> contexts;
    for (const auto& c : esi::yaml::format_contexts()) {
        SCOPED_TRACE(std::string(c.name));
        contexts.insert(std::string(c.name));
        ASSERT_TRUE(definitions.contains(std::string(c.name)));
        const json& d = definitions.at(std::string(c.name));
        ASSERT_TRUE(d.contains("properties"));
        EXPECT_EQ(d.value("additionalProperties", true), false);
        std::set<std::string> in_schema;
        for (auto it = d["properties"].begin(); it != d["properties"].end(); ++it) in_schema.insert(it.key());
        std::set<std::string> in_parser(c.keys.begin(), c.keys.end());
        EXPECT_EQ(in_schema, in_parser);
    }
    // …and no mapping in the schema that the parser does not know.
    for (auto it = definitions.begin(); it != definitions.end(); ++it) {
        if (!it.value().contains("properties")) continue;
        EXPECT_TRUE(contexts.count(it.key())) << it.key();
    }
}

TEST(YamlSchema, EverySampleValidates) {
    Validator validator(load_schema());
    int count = 0;
    for (const auto& e : std::filesystem::directory_iterator(esi::test::source_dir() / "samples")) {
        if (e.path().extension() != ".yaml") continue;
        SCOPED_TRACE(e.path().filename().string());
        const json document = yaml_file_to_json(e.path());
        EXPECT_EQ(join(validator.validate(document)), "");
        ++count;
    }
    EXPECT_GE(count, 5);
}

// What esi-gen --import writes uses only keys and value kinds the schema declares: the sample ESI
// file, and the corpus files of a few vendors when ../shared is present.
TEST(YamlSchema, ImportedFilesValidate) {
    Validator validator(load_schema());
    std::vector<std::filesystem::path> files = {esi::test::source_dir() / "samples" / "esi" / "example-digital-io.xml"};
    if (esi::test::have_shared_corpus())
        for (const char* name : {"ABT__EasyCAT_V2_0__soes.xml", "Beckhoff__EL1xxx__dls-ethercat__2011-08.xml",
                                 "Beckhoff__AX5xxx__dls-ethercat.xml", "Inovance__IS620N_v2.6.7__hw_device_mgr.xml",
                                 "PollenRobotics__NeckOrbita3d_fw1.5__poulpe.xml", "Weidmueller__UR20_FBC_from_IgH__ethercat-esi.xml"})
            files.push_back(esi::test::corpus_esi_dir() / name);
    for (const auto& path : files) {
        SCOPED_TRACE(path.filename().string());
        const esi::ReadResult read = esi::read_esi_file(path);
        ASSERT_TRUE(read.document);
        const esi::ImportResult imported = esi::import_device_source(*read.document);
        ASSERT_TRUE(imported.yaml);
        EXPECT_EQ(join(validator.validate(yaml_to_json(*imported.yaml))), "");
    }
}

TEST(YamlSchema, RejectsUnknownKeysWrongTypesAndMissingKeys) {
    Validator validator(load_schema());
    const json base = yaml_file_to_json(esi::test::source_dir() / "samples" / "digital-io-8.yaml");
    ASSERT_TRUE(validator.validate(base).empty());

    json unknown = base;
    unknown["devices"][0]["rxpdos"] = json::array();
    EXPECT_NE(join(validator.validate(unknown)).find("unknown key 'rxpdos'"), std::string::npos);

    json wrong = base;
    wrong["devices"][0]["rxpdo"][0]["fixed"] = "maybe";
    EXPECT_FALSE(validator.validate(wrong).empty());

    json missing = base;
    missing["vendor"].erase("id");
    EXPECT_NE(join(validator.validate(missing)).find("missing id"), std::string::npos);

    json bad_access = base;
    bad_access["devices"][0]["objects"]["0x6000"]["entries"]["1"]["access"] = "read";
    EXPECT_FALSE(validator.validate(bad_access).empty());

    json bad_key = base;
    bad_key["devices"][0]["objects"]["six thousand"] = json{{"name", "x"}};
    EXPECT_FALSE(validator.validate(bad_key).empty());
}

// An editor flags a misspelt data type (issue 14, item 8) and accepts every form the parser does.
TEST(YamlSchema, RejectsAMisspeltDataType) {
    Validator validator(load_schema());
    const json base = yaml_file_to_json(esi::test::source_dir() / "samples" / "digital-io-8.yaml");
    ASSERT_TRUE(base["devices"][0]["objects"].contains("0x8000"));
    auto with_type = [&](const std::string& type) {
        json changed = base;
        changed["devices"][0]["objects"]["0x8000"]["type"] = type;
        return join(validator.validate(changed));
    };
    EXPECT_NE(with_type("UNIT"), "");
    EXPECT_NE(with_type("BOLL"), "");
    for (const char* good : {"UINT", "BIT3", "STRING(8)", "ARRAY [0..3] OF BYTE", "DT0800EN08", "UINT_IDN", "UINT1"})
        EXPECT_EQ(with_type(good), "") << good;
    json entry = base;
    entry["devices"][0]["objects"]["0x6000"]["entries"]["1"]["type"] = "BOLL";
    EXPECT_NE(join(validator.validate(entry)), "");
}

TEST(YamlSchema, YamlScalarsResolveLikeTheLanguageServer) {
    const json j = yaml_to_json("{a: 0x10, b: '0x10', c: 1.5, d: true, e: ~, f: pad8, g: -3}");
    EXPECT_EQ(j["a"], 16);
    EXPECT_EQ(j["b"], "0x10");
    EXPECT_EQ(j["c"], 1.5);
    EXPECT_EQ(j["d"], true);
    EXPECT_TRUE(j["e"].is_null());
    EXPECT_EQ(j["f"], "pad8");
    EXPECT_EQ(j["g"], -3);
}
