#include "net/lcec_fork_rules.hpp"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <optional>
#include <string_view>

namespace esi::test {

namespace {

struct ElementRule {
    std::string_view name;
    std::string_view parent;  // "" for the root
    std::vector<std::string_view> attributes;
    std::vector<std::string_view> required;
    bool any_attribute = false;  // the reader has no attribute handler for it
};

std::vector<ElementRule> rules_of(LcecForkRules fork) {
    const bool sittner = fork == LcecForkRules::sittner;
    std::vector<std::string_view> master = {"idx", "name", "appTimePeriod", "refClockSyncCycles"};
    if (sittner) {
        master.insert(master.end(), {"refClockSlaveIdx", "useSeparateLrdLwr"});
    } else {
        master.push_back("syncToRefClock");
    }
    // vid, pid and configPdos are checked against the slave type below.
    const std::vector<std::string_view> slave = {"type", "idx", "name", "vid", "pid", "configPdos"};
    // linuxcnc-ethercat's idnConfig reader compares the name "drive" twice and never "state".
    std::vector<std::string_view> idn = {"drive", "idn"};
    if (sittner) idn.push_back("state");
    return {
        {"masters", "", {}, {}, true},
        {"master", "masters", master, {}},
        {"slave", "master", slave, {"type"}},
        {"dcConf", "slave", {"assignActivate", "sync0Cycle", "sync0Shift", "sync1Cycle", "sync1Shift"}, {}},
        {"watchdog", "slave", {"divider", "intervals"}, {}},
        {"sdoConfig", "slave", {"idx", "subIdx"}, {"idx", "subIdx"}},
        {"sdoDataRaw", "sdoConfig", {"data"}, {}},
        {"idnConfig", "slave", idn, {"idn"}},
        {"idnDataRaw", "idnConfig", {"data"}, {}},
        {"initCmds", "slave", {"filename"}, {"filename"}},
        {"syncManager", "slave", {"idx", "dir"}, {"idx", "dir"}},
        {"pdo", "syncManager", {"idx"}, {"idx"}},
        {"pdoEntry", "pdo", {"idx", "subIdx", "bitLen", "halType", "scale", "offset", "halPin"}, {"idx", "subIdx", "bitLen"}},
        {"complexEntry", "pdoEntry", {"bitLen", "halType", "scale", "offset", "halPin"}, {"bitLen"}},
        {"modParam", "slave", {"name", "value"}, {}},
    };
}

bool equals_ignoring_case(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
}

std::vector<std::string_view> hal_types(LcecForkRules fork, bool complex_entry) {
    std::vector<std::string_view> types = {"bit", "s32", "u32", "float", "float-unsigned", "float-ieee"};
    if (!complex_entry) types.push_back("complex");
    if (fork == LcecForkRules::linuxcnc_ethercat && !complex_entry) types.push_back("float-double-ieee");
    return types;
}

// strtol(text, NULL, 16) as the readers call it: leading "0x" allowed, stops at the first non-digit.
long hex_value(const char* text) { return std::strtol(text, nullptr, 16); }

class Checker {
public:
    Checker(const pugi::xml_document& doc, LcecForkRules fork) : fork_(fork), rules_(rules_of(fork)) {
        for (pugi::xml_node n : doc.children())
            if (n.type() == pugi::node_element) element(n, "");
    }
    std::vector<LcecRefusal> refusals;

private:
    void refuse(pugi::xml_node n, const std::string& what) {
        refusals.push_back({std::string(n.name()) + " (offset " + std::to_string(n.offset_debug()) + "): " + what});
    }

    void element(pugi::xml_node n, std::string_view parent) {
        const auto rule = std::find_if(rules_.begin(), rules_.end(),
                                       [&](const ElementRule& r) { return r.name == n.name() && r.parent == parent; });
        if (rule == rules_.end()) {
            refuse(n, "unexpected under <" + std::string(parent) + ">");
            return;
        }
        if (!rule->any_attribute) {
            for (pugi::xml_attribute a : n.attributes())
                if (std::find(rule->attributes.begin(), rule->attributes.end(), a.name()) == rule->attributes.end())
                    refuse(n, "attribute " + std::string(a.name()) + " is not read");
            for (std::string_view r : rule->required)
                if (!n.attribute(std::string(r).c_str())) refuse(n, "has no " + std::string(r));
        }
        values(n);
        for (pugi::xml_node c : n.children())
            if (c.type() == pugi::node_element) element(c, n.name());
    }

    void values(pugi::xml_node n) {
        const std::string_view name = n.name();
        if (name == "slave") {
            const bool generic = std::string_view(n.attribute("type").as_string()) == "generic";
            // sittner reads vid and pid on generic slaves only; both read configPdos only there.
            for (const char* a : {"vid", "pid", "configPdos"}) {
                const bool generic_only = std::string_view(a) == "configPdos" || fork_ == LcecForkRules::sittner;
                if (n.attribute(a) && generic_only && !generic) refuse(n, std::string("attribute ") + a + " on a non-generic slave");
            }
        }
        if (name == "syncManager") {
            const std::string dir = n.attribute("dir").as_string();
            if (n.attribute("dir") && !equals_ignoring_case(dir, "in") && !equals_ignoring_case(dir, "out")) refuse(n, "dir " + dir);
            const int idx = n.attribute("idx").as_int(-1);
            if (n.attribute("idx") && (idx < 0 || idx >= 16)) refuse(n, "idx out of range");
            if (std::string_view(n.parent().attribute("type").as_string()) != "generic") refuse(n, "on a non-generic slave");
        }
        if (name == "pdo" || name == "pdoEntry" || name == "sdoConfig") {
            if (n.attribute("idx") && hex_value(n.attribute("idx").as_string()) >= 0xffff) refuse(n, "idx out of range");
        }
        if (name == "pdoEntry" || name == "sdoConfig") {
            const std::string sub = n.attribute("subIdx").as_string();
            const bool complete = name == "sdoConfig" && equals_ignoring_case(sub, "complete");
            if (n.attribute("subIdx") && !complete && hex_value(sub.c_str()) >= 0xff) refuse(n, "subIdx out of range");
        }
        if (name == "pdoEntry" || name == "complexEntry") {
            const int bits = n.attribute("bitLen").as_int(0);
            if (n.attribute("bitLen") && (bits <= 0 || bits > (name == "pdoEntry" ? 255 : 32))) refuse(n, "bitLen out of range");
            std::optional<std::string> type;
            if (n.attribute("halType")) {
                type = n.attribute("halType").as_string();
                const auto allowed = hal_types(fork_, name == "complexEntry");
                if (std::none_of(allowed.begin(), allowed.end(), [&](std::string_view t) { return equals_ignoring_case(*type, t); }))
                    refuse(n, "halType " + *type);
            }
            const bool is_float = type && equals_ignoring_case(type->substr(0, 5), "float");
            if ((n.attribute("scale") || n.attribute("offset")) && !is_float) refuse(n, "scale/offset without a float halType");
            if (type && equals_ignoring_case(*type, "complex") && n.attribute("halPin")) refuse(n, "halPin on a complex entry");
        }
    }

    LcecForkRules fork_;
    std::vector<ElementRule> rules_;
};

}  // namespace

std::vector<LcecRefusal> lcec_refusals(const pugi::xml_document& document, LcecForkRules fork) {
    return Checker(document, fork).refusals;
}

std::vector<LcecRefusal> lcec_refusals(const std::string& xml_text, LcecForkRules fork) {
    pugi::xml_document doc;
    if (const pugi::xml_parse_result r = doc.load_string(xml_text.c_str()); !r) return {{std::string("not XML: ") + r.description()}};
    return lcec_refusals(doc, fork);
}

}  // namespace esi::test
