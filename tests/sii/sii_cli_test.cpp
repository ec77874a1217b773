// esi-sii end to end: the interface of issue 5 and its exit codes (0 all well, 1 fault or
// mismatch, 2 usage error or unusable input).

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "esi/sii/image_file.hpp"
#include "fixture.hpp"
#include "support/test_support.hpp"

namespace {

using esi::test::read_text;
using esi::test::run;
using esi::test::TempDir;
using esi::test::write_text;

std::string sii() { return esi::test::tool("esi-sii").string(); }

std::string two_device_xml() {
    std::string xml = esi::test::fixture_xml();
    const auto begin = xml.find("<Device ");
    std::string second = xml.substr(begin, xml.find("</Device>") + 9 - begin);
    second.replace(second.find("#x00020001"), 10, "#x00030001");
    xml.insert(xml.find("</Devices>"), second);
    return xml;
}

TEST(SiiCli, UsageErrorsExitWith2) {
    EXPECT_EQ(run({sii()}).exit_code, 2);
    EXPECT_EQ(run({sii(), "frobnicate"}).exit_code, 2);
    EXPECT_EQ(run({sii(), "build", "x.xml"}).exit_code, 2);  // -o is required
    EXPECT_EQ(run({sii(), "dump"}).exit_code, 2);
    EXPECT_EQ(run({sii(), "check", "only-one"}).exit_code, 2);
    EXPECT_EQ(run({sii(), "--help"}).exit_code, 0);
}

TEST(SiiCli, BuildWritesTheImageAndIsDeterministic) {
    TempDir dir;
    write_text(dir / "dev.xml", esi::test::fixture_xml());
    const auto r = run({sii(), "build", (dir / "dev.xml").string(), "-o", (dir / "a.bin").string()});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    const std::string a = read_text(dir / "a.bin");
    EXPECT_EQ(a.size(), 2048u);
    ASSERT_EQ(run({sii(), "build", (dir / "dev.xml").string(), "-o", (dir / "b.bin").string()}).exit_code, 0);
    EXPECT_EQ(read_text(dir / "b.bin"), a);
}

TEST(SiiCli, BuildFormatsHexAndC) {
    TempDir dir;
    write_text(dir / "dev.xml", esi::test::fixture_xml());
    ASSERT_EQ(run({sii(), "build", (dir / "dev.xml").string(), "-o", (dir / "a.bin").string()}).exit_code, 0);
    ASSERT_EQ(run({sii(), "build", (dir / "dev.xml").string(), "-o", (dir / "a.hex").string(), "--format", "hex"}).exit_code, 0);
    ASSERT_EQ(run({sii(), "build", (dir / "dev.xml").string(), "-o", (dir / "a.c").string(), "--format", "c"}).exit_code, 0);
    const std::string bin = read_text(dir / "a.bin");
    const auto hex = esi::sii::parse_intel_hex(read_text(dir / "a.hex"));
    ASSERT_TRUE(hex.bytes.has_value()) << hex.error;
    EXPECT_EQ(std::string(hex.bytes->begin(), hex.bytes->end()), bin);
    const std::string c = read_text(dir / "a.c");
    EXPECT_NE(c.find("const uint8_t sii_eeprom[2048] = {"), std::string::npos);
    EXPECT_NE(c.find("TD-100"), std::string::npos);
    EXPECT_EQ(run({sii(), "build", (dir / "dev.xml").string(), "-o", (dir / "x"), "--format", "srec"}).exit_code, 2);
    // dump and check read the HEX form as well.
    EXPECT_EQ(run({sii(), "dump", (dir / "a.hex").string()}).exit_code, 0);
    EXPECT_EQ(run({sii(), "check", (dir / "dev.xml").string(), (dir / "a.hex").string()}).exit_code, 0);
}

TEST(SiiCli, BuildNamesTheDevicesWhenTheChoiceIsOpen) {
    TempDir dir;
    write_text(dir / "two.xml", two_device_xml());
    const std::string in = (dir / "two.xml").string();
    const std::string out = (dir / "o.bin").string();
    const auto ambiguous = run({sii(), "build", in, "-o", out});
    EXPECT_EQ(ambiguous.exit_code, 2);
    EXPECT_NE(ambiguous.err.find("--device 0x00001234:0x00020001"), std::string::npos) << ambiguous.err;
    EXPECT_NE(ambiguous.err.find("--device 0x00001234:0x00030001"), std::string::npos);
    EXPECT_FALSE(std::filesystem::exists(out));
    EXPECT_EQ(run({sii(), "build", in, "-o", out, "--device", "#x1234"}).exit_code, 2);  // still two
    EXPECT_EQ(run({sii(), "build", in, "-o", out, "--device", "0x9999"}).exit_code, 2);
    EXPECT_EQ(run({sii(), "build", in, "-o", out, "--device", "12:ab"}).exit_code, 2);
    const auto chosen = run({sii(), "build", in, "-o", out, "--device", "0x1234:#x00030001"});
    EXPECT_EQ(chosen.exit_code, 0) << chosen.err;
    const auto dump = run({sii(), "dump", out, "--format", "json"});
    EXPECT_EQ(nlohmann::json::parse(dump.out)["header"]["revision_no"], 0x00030001);
}

TEST(SiiCli, BuildWithoutPdoAndDc) {
    TempDir dir;
    write_text(dir / "dev.xml", esi::test::fixture_xml());
    ASSERT_EQ(run({sii(), "build", (dir / "dev.xml").string(), "-o", (dir / "a.bin").string(), "--no-pdo", "--no-dc"}).exit_code, 0);
    const auto json = nlohmann::json::parse(run({sii(), "dump", (dir / "a.bin").string(), "--format", "json"}).out);
    for (const auto& c : json["categories"]) {
        EXPECT_NE(c["name"], "TxPDO");
        EXPECT_NE(c["name"], "RxPDO");
        EXPECT_NE(c["name"], "DC");
    }
}

TEST(SiiCli, BuildRefusesWhatDoesNotFitAndWritesNothing) {
    // 128 bytes hold the header only: the mandatory part of the image does not fit.
    TempDir dir;
    write_text(dir / "dev.xml", esi::test::fixture_xml({}, "128"));
    const auto r = run({sii(), "build", (dir / "dev.xml").string(), "-o", (dir / "a.bin").string()});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("[sii-image-too-large]"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("the mandatory part"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("dev.xml:"), std::string::npos);
    EXPECT_FALSE(std::filesystem::exists(dir / "a.bin"));
}

TEST(SiiCli, BuildLeavesOutOptionalContentWithANoteUnlessStrictSize) {
    TempDir dir;
    write_text(dir / "dev.xml", esi::test::fixture_xml({}, "256"));
    const auto fitted = run({sii(), "build", (dir / "dev.xml").string(), "-o", (dir / "a.bin").string()});
    EXPECT_EQ(fitted.exit_code, 0) << fitted.err;
    EXPECT_NE(fitted.err.find("info: the TxPDO and RxPDO categories (3 PDOs) left out"), std::string::npos) << fitted.err;
    EXPECT_NE(fitted.err.find("[sii-left-out]"), std::string::npos) << fitted.err;
    EXPECT_EQ(std::filesystem::file_size(dir / "a.bin"), 256u);

    const auto strict = run({sii(), "build", (dir / "dev.xml").string(), "-o", (dir / "b.bin").string(), "--strict-size"});
    EXPECT_EQ(strict.exit_code, 2);
    EXPECT_NE(strict.err.find("[sii-image-too-large]"), std::string::npos) << strict.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "b.bin"));
}

TEST(SiiCli, BuildUnusableInputExitsWith2) {
    TempDir dir;
    write_text(dir / "bad.xml", "<EtherCATInfo><Vendor>");
    write_text(dir / "src.yaml", "device: [unclosed\n");
    write_text(dir / "nodev.xml", "<EtherCATInfo><Vendor><Id>1</Id></Vendor><Descriptions><Groups/><Devices/></Descriptions></EtherCATInfo>");
    for (const std::string in : {"missing.xml", "bad.xml", "src.yaml", "nodev.xml"}) {
        SCOPED_TRACE(in);
        const auto r = run({sii(), "build", (dir / in).string(), "-o", (dir / "o.bin").string()});
        EXPECT_EQ(r.exit_code, 2);
        EXPECT_FALSE(r.err.empty());
    }
}

TEST(SiiCli, DumpExitCodesFollowTheFaults) {
    TempDir dir;
    write_text(dir / "dev.xml", esi::test::fixture_xml());
    ASSERT_EQ(run({sii(), "build", (dir / "dev.xml").string(), "-o", (dir / "a.bin").string()}).exit_code, 0);
    const auto clean = run({sii(), "dump", (dir / "a.bin").string()});
    EXPECT_EQ(clean.exit_code, 0);
    EXPECT_NE(clean.out.find("Faults: none"), std::string::npos);
    EXPECT_NE(clean.out.find("0x08 vendor id                 0x0000ABCD"), std::string::npos);
    std::string bytes = read_text(dir / "a.bin");
    bytes[0] = static_cast<char>(bytes[0] ^ 0x10);
    write_text(dir / "bad.bin", bytes);
    const auto bad = run({sii(), "dump", (dir / "bad.bin").string()});
    EXPECT_EQ(bad.exit_code, 1);
    EXPECT_NE(bad.out.find("0x000E error:"), std::string::npos);
    EXPECT_NE(bad.out.find("[sii-crc]"), std::string::npos);
    const auto json = run({sii(), "dump", (dir / "bad.bin").string(), "--format", "json"});
    EXPECT_EQ(json.exit_code, 1);
    const auto j = nlohmann::json::parse(json.out);
    EXPECT_EQ(j["faults"][0]["rule"], "sii-crc");
    EXPECT_EQ(j["faults"][0]["offset"], 14);
    EXPECT_EQ(run({sii(), "dump", (dir / "a.bin").string(), "--format", "xml"}).exit_code, 2);
    EXPECT_EQ(run({sii(), "dump", (dir / "none.bin").string()}).exit_code, 2);
    write_text(dir / "broken.hex", ":0400000080\n");
    EXPECT_EQ(run({sii(), "dump", (dir / "broken.hex").string()}).exit_code, 2);
}

TEST(SiiCli, CheckExitCodesFollowTheMismatches) {
    TempDir dir;
    write_text(dir / "dev.xml", esi::test::fixture_xml());
    write_text(dir / "two.xml", two_device_xml());
    ASSERT_EQ(run({sii(), "build", (dir / "dev.xml").string(), "-o", (dir / "a.bin").string()}).exit_code, 0);
    const auto clean = run({sii(), "check", (dir / "dev.xml").string(), (dir / "a.bin").string()});
    EXPECT_EQ(clean.exit_code, 0) << clean.out;
    EXPECT_NE(clean.out.find("consistent"), std::string::npos);
    // The two-device file finds the built device by its identity.
    EXPECT_EQ(run({sii(), "check", (dir / "two.xml").string(), (dir / "a.bin").string()}).exit_code, 0);

    std::string bytes = read_text(dir / "a.bin");
    bytes[0x10] = 0x01;  // vendor id, outside the CRC area
    write_text(dir / "other.bin", bytes);
    const auto mismatch = run({sii(), "check", (dir / "dev.xml").string(), (dir / "other.bin").string()});
    EXPECT_EQ(mismatch.exit_code, 1);
    EXPECT_NE(mismatch.out.find("[sii-vendor-id]"), std::string::npos) << mismatch.out;
    EXPECT_NE(mismatch.out.find((dir / "other.bin").string() + ": note: image byte 0x0010 (word 0x08)"), std::string::npos);

    bytes = read_text(dir / "a.bin");
    bytes[0x14] = 0x77;  // product code: not in the two-device file
    write_text(dir / "alien.bin", bytes);
    EXPECT_EQ(run({sii(), "check", (dir / "two.xml").string(), (dir / "alien.bin").string()}).exit_code, 1);
    EXPECT_EQ(run({sii(), "check", (dir / "dev.xml").string(), (dir / "none.bin").string()}).exit_code, 2);
    EXPECT_EQ(run({sii(), "check", (dir / "none.xml").string(), (dir / "a.bin").string()}).exit_code, 2);
}

TEST(SiiCli, RealImagesDumpAndCheck) {
    ESI_REQUIRE_CORPUS();
    const auto sii_dir = esi::test::shared_dir() / "corpus" / "sii";
    for (const auto& entry : std::filesystem::directory_iterator(sii_dir)) {
        if (entry.path().extension() != ".bin") continue;
        SCOPED_TRACE(entry.path().filename().string());
        const std::string name = entry.path().filename().string();
        const bool faulty = name.rfind("Empty__", 0) == 0 || name.find("null_strings") != std::string::npos;
        const auto text = run({sii(), "dump", entry.path().string()});
        EXPECT_EQ(text.exit_code, faulty ? 1 : 0) << text.out;
        const auto json = run({sii(), "dump", entry.path().string(), "--format", "json"});
        EXPECT_EQ(json.exit_code, text.exit_code);
        EXPECT_TRUE(nlohmann::json::accept(json.out));
    }
    const auto esi_dir = esi::test::corpus_esi_dir();
    EXPECT_EQ(run({sii(), "check", (esi_dir / "Beckhoff__EL2xxx__dls-ethercat.xml").string(),
                   (sii_dir / "Beckhoff__EL2004__ethercrab-dump.bin").string()})
                  .exit_code,
              0);
    const auto soes = run({sii(), "check", (esi_dir / "SOES__linux_lan9252demo__soes.xml").string(),
                           (sii_dir / "SOES__linux_lan9252demo__soes.bin").string()});
    EXPECT_EQ(soes.exit_code, 1);
    EXPECT_NE(soes.out.find("[sii-physical-ports]"), std::string::npos);
}

}  // namespace
