// esi-net's process_image.html (esi/doc/process_image_page.hpp) for samples/networks/line.yaml:
// every variable of process_image.json is one labelled box in a picture and one table row, the
// pictures have a size and a title, the page is self-contained, and it is the same run to run.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <regex>

#include "doc_test_support.hpp"
#include "esi/doc/datasheet.hpp"
#include "esi/doc/process_image_page.hpp"
#include "esi/net/network.hpp"
#include "esi/net/outputs.hpp"

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

std::string diagnostics_text(const esi::Diagnostics& diagnostics) {
    std::string out;
    for (const esi::Diagnostic& d : diagnostics) out += esi::format_diagnostic(d);
    return out;
}

fs::path line_network() { return esi::test::source_dir() / "samples" / "networks" / "line.yaml"; }

esi::net::Network build_line() {
    const esi::net::NetworkFileResult read = esi::net::read_network_file(line_network().string());
    EXPECT_TRUE(read.spec) << diagnostics_text(read.diagnostics);
    if (!read.spec) return {};
    esi::net::BuildResult built = esi::net::build_network(*read.spec, esi::net::BuildOptions{});
    EXPECT_TRUE(built.network) << diagnostics_text(built.diagnostics);
    return built.network ? std::move(*built.network) : esi::net::Network{};
}

std::string render(const esi::net::Network& network) {
    esi::doc::ProcessImagePageOptions options;
    options.template_dirs = esi::doc::template_search_path({}, std::nullopt);
    const esi::doc::ProcessImagePage page = esi::doc::render_process_image_page(network, "out", options);
    EXPECT_FALSE(page.diagnostics.has_errors()) << diagnostics_text(page.diagnostics);
    if (page.files.size() != 1) return {};
    EXPECT_EQ(page.files[0].path, fs::path("out") / "process_image.html");
    return page.files[0].content;
}

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

std::string html_escaped(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '&') out += "&amp;";
        else if (c == '<') out += "&lt;";
        else if (c == '>') out += "&gt;";
        else if (c == '"') out += "&quot;";
        else out += c;
    }
    return out;
}

TEST(ProcessImagePage, EveryVariableOfTheMapIsOneBoxAndOneTableRow) {
    const esi::net::Network network = build_line();
    const std::string html = render(network);
    ASSERT_FALSE(html.empty());
    const Json map = Json::parse(esi::net::write_map_json(network));
    ASSERT_GE(map["variables"].size(), 10u);
    for (const Json& v : map["variables"]) {
        const std::string name = v["name"], slave = v["slave"];
        SCOPED_TRACE(name);
        ASSERT_TRUE(name.starts_with(slave + "."));
        // The box: "slave: rest of the name: 0x6000:01, TYPE, N bits at byte B bit b", its
        // accessible label as esi/doc/bit_layout.hpp words it, with offsets from the image start.
        const std::string object = v["index"].get<std::string>() + ":" + v["subindex"].get<std::string>().substr(2);
        const std::string bits = std::to_string(v["bit_size"].get<int>()) + (v["bit_size"] == 1 ? " bit" : " bits");
        const std::string label = slave + ": " + name.substr(slave.size() + 1) + ": " + object + ", " + v["data_type"].get<std::string>() +
                                  ", " + bits + " at byte " + std::to_string(v["byte_offset"].get<int>()) + " bit " +
                                  std::to_string(v["bit_offset"].get<int>());
        EXPECT_EQ(count(html, "role=\"img\" aria-label=\"" + html_escaped(label) + "\""), 1u) << label;
        EXPECT_EQ(count(html, "<tr data-variable=\"" + html_escaped(name) + "\">"), 1u);
    }
    EXPECT_EQ(count(html, "role=\"img\" aria-label=\""), map["variables"].size());
    EXPECT_EQ(count(html, "<tr data-variable="), map["variables"].size());
}

TEST(ProcessImagePage, PicturesHaveASizeAndATitleAndThePageIsSelfContained) {
    const std::string html = render(build_line());
    // line.yaml is one frame: its outputs and its inputs.
    const std::regex svg(R"re(<svg xmlns="http://www.w3.org/2000/svg" class="bit-layout" id="([^"]+)" width="(\d+)" height="(\d+)"[^>]*><title id="[^"]+">([^<]+)</title>)re");
    std::vector<std::string> ids;
    for (auto it = std::sregex_iterator(html.begin(), html.end(), svg); it != std::sregex_iterator(); ++it) {
        ids.push_back((*it)[1]);
        EXPECT_GT(std::stoi((*it)[2]), 0);
        EXPECT_GT(std::stoi((*it)[3]), 0);
        EXPECT_NE((*it)[4].str().find("Process image of line"), std::string::npos) << (*it)[4];
    }
    EXPECT_EQ(ids, (std::vector<std::string>{"out-f0", "in-f0"}));
    EXPECT_EQ(count(html, "<svg"), 2u);
    EXPECT_EQ(count(html, "<script"), 0u);
    EXPECT_EQ(count(html, "src="), 0u);
    EXPECT_EQ(count(html, "href=\"http"), 0u);
    EXPECT_EQ(count(html, "<link"), 0u);
    EXPECT_NE(html.find("<style>"), std::string::npos);
    // Named by the master, as the integrator calls it; the network file second.
    EXPECT_NE(html.find("<title>Process image of Line 1 (line)</title>"), std::string::npos);
    EXPECT_NE(html.find("<h1>Process image of Line 1</h1>"), std::string::npos);
}

TEST(ProcessImagePage, IsByteIdenticalRunToRun) {
    const esi::net::Network network = build_line();
    EXPECT_EQ(render(network), render(build_line()));
}

TEST(ProcessImagePage, AMissingTemplateIsADiagnosticAndNoFile) {
    esi::test::TempDir empty;
    esi::doc::ProcessImagePageOptions options;
    options.template_dirs = {empty.path()};
    const esi::doc::ProcessImagePage page = esi::doc::render_process_image_page(build_line(), "out", options);
    EXPECT_TRUE(page.diagnostics.has_errors());
    EXPECT_TRUE(page.files.empty());
}

// Two frames: one picture per frame and direction, each with the variables of its frame's slaves
// at their offsets from the image's start.
TEST(ProcessImagePage, ANetworkOfTwoFramesHasAPicturePerFrameAndDirection) {
    esi::net::Network network;
    network.name = "two-frames";
    network.image.frames.resize(2);
    for (std::size_t i = 0; i < 2; ++i) {
        esi::net::NetworkSlave s;
        s.name = i == 0 ? "Near" : "Far";
        s.position = i;
        s.frame = i;
        s.image_offset = i == 0 ? 0 : 1400;
        network.slaves.push_back(s);
        esi::net::Variable v;
        v.slave = i;
        v.name = s.name + ".Inputs.Value";
        v.index = 0x6000;
        v.subindex = 1;
        v.data_type = "UINT";
        v.bit_size = 16;
        v.bit_offset = std::uint64_t{s.image_offset} * 8;
        v.direction = esi::PdoDirection::tx;
        network.image.inputs.push_back(v);
        v.name = s.name + ".Outputs.Value";
        v.index = 0x7000;
        v.direction = esi::PdoDirection::rx;
        network.image.outputs.push_back(v);
    }
    const std::string html = render(network);
    for (const char* id : {"out-f0", "out-f1", "in-f0", "in-f1"}) EXPECT_EQ(count(html, std::string("class=\"bit-layout\" id=\"") + id + "\""), 1u) << id;
    EXPECT_EQ(count(html, "role=\"img\" aria-label=\"Far: Inputs.Value: 0x6000:01, UINT, 16 bits at byte 1400 bit 0\""), 1u);
    EXPECT_EQ(count(html, "role=\"img\" aria-label=\"Near: Outputs.Value: 0x7000:01, UINT, 16 bits at byte 0 bit 0\""), 1u);
    EXPECT_EQ(count(html, "role=\"img\" aria-label=\""), 4u);
    EXPECT_NE(html.find("Inputs (slaves to master), frame 1"), std::string::npos);
    // Frame 1's picture holds only Far's variable: Near's is drawn in frame 0's.
    const std::size_t f1 = html.find("id=\"out-f1\"");
    ASSERT_NE(f1, std::string::npos);
    const std::string picture = html.substr(f1, html.find("</svg>", f1) - f1);
    EXPECT_EQ(count(picture, "aria-label=\"Far: "), 1u);
    EXPECT_EQ(count(picture, "aria-label=\"Near: "), 0u);
}

TEST(ProcessImagePage, EsiNetWritesItByDefaultAndWithOnlyHtml) {
    esi::test::TempDir dir;
    const auto all = esi::test::run({esi::test::tool("esi-net").string(), "--no-cache", "build", line_network().string(), "-o", (dir / "all").string()});
    ASSERT_EQ(all.exit_code, 0) << all.err;
    EXPECT_TRUE(fs::exists(dir / "all" / "process_image.html"));
    const auto only = esi::test::run({esi::test::tool("esi-net").string(), "--no-cache", "build", line_network().string(), "-o",
                                      (dir / "only").string(), "--only", "html"});
    ASSERT_EQ(only.exit_code, 0) << only.err;
    EXPECT_EQ(esi::test::read_text(dir / "only" / "process_image.html"), esi::test::read_text(dir / "all" / "process_image.html"));
    EXPECT_FALSE(fs::exists(dir / "only" / "process_image.json"));
    EXPECT_FALSE(fs::exists(dir / "only" / "network.xml"));
}

}  // namespace
