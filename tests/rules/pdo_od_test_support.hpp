#pragma once
// Helpers for the pdo/od/profile rule tests: lint a text, pick one rule's findings, and find the
// lines a test marks with <!-- expect: RULE -->.

#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "esi/lint/lint.hpp"
#include "support/test_support.hpp"

namespace esi::test {

inline FileReport lint_text(const std::string& xml, const EffectiveConfig& config = {}) {
    return lint_bytes(xml, "test.xml", config);
}

inline std::vector<Diagnostic> findings_of(const FileReport& report, std::string_view rule) {
    std::vector<Diagnostic> out;
    for (const auto& d : report.diagnostics)
        if (d.rule == rule) out.push_back(d);
    return out;
}

inline std::set<std::uint32_t> finding_lines(const FileReport& report, std::string_view rule) {
    std::set<std::uint32_t> out;
    for (const auto& d : report.diagnostics)
        if (d.rule == rule) out.insert(d.pos.line);
    return out;
}

// Line numbers (1-based) of the lines containing `needle`.
inline std::set<std::uint32_t> lines_containing(const std::string& text, std::string_view needle) {
    std::set<std::uint32_t> out;
    std::istringstream in(text);
    std::string line;
    std::uint32_t number = 0;
    while (std::getline(in, line)) {
        ++number;
        if (line.find(needle) != std::string::npos) out.insert(number);
    }
    return out;
}

inline std::set<std::uint32_t> marked_lines(const std::string& text, std::string_view rule) {
    return lines_containing(text, "<!-- expect: " + std::string(rule) + " -->");
}

inline std::size_t count_with_prefix(const FileReport& report, std::string_view prefix) {
    std::size_t n = 0;
    for (const auto& d : report.diagnostics)
        if (d.rule.rfind(prefix, 0) == 0) ++n;
    return n;
}

// A one-device EtherCATInfo around `device_body` (everything inside <Device>).
inline std::string one_device(const std::string& device_body, const std::string& product_code = "#x00001001") {
    return "<?xml version=\"1.0\"?>\n"
           "<EtherCATInfo Version=\"1.17\">\n"
           "  <Vendor><Id>#x00000E4A</Id><Name>Example</Name></Vendor>\n"
           "  <Descriptions>\n"
           "    <Groups><Group><Type>G</Type><Name>G</Name></Group></Groups>\n"
           "    <Devices>\n"
           "      <Device Physics=\"YY\">\n"
           "        <Type ProductCode=\"" + product_code + "\" RevisionNo=\"#x1\">D</Type>\n"
           "        <Name>D</Name>\n"
           "        <GroupType>G</GroupType>\n" +
           device_body +
           "      </Device>\n"
           "    </Devices>\n"
           "  </Descriptions>\n"
           "</EtherCATInfo>\n";
}

inline const char* const standard_sms =
    "        <Sm StartAddress=\"#x1000\" ControlByte=\"#x26\" DefaultSize=\"128\" Enable=\"1\">MBoxOut</Sm>\n"
    "        <Sm StartAddress=\"#x1080\" ControlByte=\"#x22\" DefaultSize=\"128\" Enable=\"1\">MBoxIn</Sm>\n"
    "        <Sm StartAddress=\"#x1100\" ControlByte=\"#x64\" Enable=\"1\">Outputs</Sm>\n"
    "        <Sm StartAddress=\"#x1400\" ControlByte=\"#x20\" Enable=\"1\">Inputs</Sm>\n";

inline const char* const coe_mailbox = "        <Mailbox DataLinkLayer=\"true\"><CoE SdoInfo=\"true\"/></Mailbox>\n";

}  // namespace esi::test
