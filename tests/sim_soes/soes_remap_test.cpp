// Dynamic PDO mapping on SOES firmware under SOEM (issue 21): the sample with flexible PDOs
// (samples/inverter-stoeber-mds5000.yaml, 0x1600-0x1603 with six entries each, 0x1C12 with four)
// is remapped by the master over CoE in PREOP — a legal remap with a padding entry, and the
// largest one that runs (all 24 mapping slots of MAX_MAPPINGS_SM2, and the 42 bytes three SM2
// buffers hold between 0x1100 and SM3 at 0x1180) — SOES accepts it, SOEM's process image follows
// the new mapping and the outputs arrive in SOES's objects at their new offsets. A mapping of
// MAX_RXPDO_SIZE (48) bytes, which the dictionary accepts, does not fit the SyncManager layout:
// SOES refuses SAFEOP with AL status code 0x001D. The firmware is built with AddressSanitizer:
// SOES copies SM2 into a static buffer sized by the generated ecat_options.h, so a buffer too
// small for the mapping ends the run.

#include <gtest/gtest.h>

#include <fmt/format.h>

#include "sim_soes/soes_fixtures.hpp"
#include "support/test_support.hpp"

namespace esi::test {
namespace {

// Parameters of the STÖBER sample: A180 (USINT), D230 and C230 (INT).
constexpr std::uint32_t A180 = 0x20B4, D230 = 0x26E6, C230 = 0x24E6;
constexpr std::uint32_t map_entry(std::uint32_t index, std::uint32_t bits) { return index << 16 | bits; }
constexpr std::uint32_t gap(std::uint32_t bits) { return bits; }

struct Remap {
    std::string name;
    std::vector<std::pair<std::uint16_t, std::vector<std::uint32_t>>> pdos;  // assigned to SM2, in order
    bool fits = true;  // false: SOES must refuse SAFEOP (the SM2 buffers would overlap SM3)
};

std::string sdo_write(std::uint16_t index, std::uint8_t sub, int bytes, std::uint32_t value) {
    return fmt::format("1:{:x}:{:x}:{:x}:{:x}", index, sub, bytes, value);
}

// The master's downloads, as ETG.1020 orders them: the assignment cleared, each PDO's count
// cleared, its entries, its count, then the assignment's entries and count.
std::vector<std::string> remap_args(const Remap& remap) {
    std::vector<std::string> args{"--cycles", "1000", "--state-timeout-ms", "3000"};
    const auto add = [&](const std::string& write) { args.insert(args.end(), {"--sdo-write", write}); };
    add(sdo_write(0x1C12, 0, 1, 0));
    for (const auto& [pdo, entries] : remap.pdos) {
        add(sdo_write(pdo, 0, 1, 0));
        for (std::size_t i = 0; i < entries.size(); ++i) add(sdo_write(pdo, static_cast<std::uint8_t>(i + 1), 4, entries[i]));
        add(sdo_write(pdo, 0, 1, static_cast<std::uint32_t>(entries.size())));
    }
    for (std::size_t i = 0; i < remap.pdos.size(); ++i)
        add(sdo_write(0x1C12, static_cast<std::uint8_t>(i + 1), 2, remap.pdos[i].first));
    add(sdo_write(0x1C12, 0, 1, static_cast<std::uint32_t>(remap.pdos.size())));
    return args;
}

TEST(SoesRemap, SoesAcceptsAPaddedAndAMaximalRemapAndTheProcessImageFollows) {
    ESI_REQUIRE_SOES_ON_SIM();
    const SoesFirmware& fw = soes_firmware(source_dir() / "samples" / "inverter-stoeber-mds5000.yaml", true);
    if (fw.error.find("AddressSanitizer") != std::string::npos || fw.error.find("asan") != std::string::npos)
        GTEST_SKIP() << "cc cannot build with AddressSanitizer here: " << fw.error;
    ASSERT_EQ(fw.error, "");

    const std::vector<std::uint32_t> six_gaps(6, gap(16));
    const std::vector<Remap> remaps{
        {"padded", {{0x1600, {map_entry(A180, 8), gap(8), map_entry(D230, 16)}}}},
        {"maximal",
         {{0x1600, {map_entry(A180, 8), gap(8), map_entry(D230, 16), gap(8), gap(8), gap(16)}},
          {0x1601, {gap(8), gap(8), gap(16), gap(16), gap(16), gap(16)}},
          {0x1602, six_gaps},
          {0x1603, {gap(16), gap(16), gap(16), gap(16), gap(16), map_entry(C230, 16)}}}},
        {"MAX_RXPDO_SIZE bytes",
         {{0x1600, {map_entry(A180, 8), gap(8), map_entry(D230, 16), gap(16), gap(16), gap(16)}},
          {0x1601, six_gaps},
          {0x1602, six_gaps},
          {0x1603, {gap(16), gap(16), gap(16), gap(16), gap(16), map_entry(C230, 16)}}},
         false},
    };
    std::vector<SoesStep> steps;
    for (const Remap& r : remaps)
        steps.push_back({{fw.source.string(), "--eeprom", fw.eeprom.string(), "--firmware", fw.library.string()},
                         remap_args(r), {}, true});
    const auto results = run_soes_session(steps);
    ASSERT_EQ(results.size(), remaps.size());
    for (std::size_t i = 0; i < remaps.size(); ++i) {
        const Remap& remap = remaps[i];
        const SoesStepResult& r = results[i];
        SCOPED_TRACE(remap.name);
        EXPECT_EQ(r.host_stderr.find("AddressSanitizer"), std::string::npos) << r.host_stderr;
        ASSERT_TRUE(r.master) << r.host_stderr << r.master_output;
        ASSERT_TRUE(r.host) << r.host_stderr << r.host_output;
        const auto& m = *r.master;
        for (const auto& w : m["sdo_writes"]) EXPECT_EQ(w["ok"], true) << w.dump();
        const auto& s = m["slave"][0];
        if (!remap.fits) {
            EXPECT_EQ(m["op"], false);
            EXPECT_EQ(s["al_status_code"], 0x001D) << "invalid output configuration";
            continue;
        }
        ASSERT_EQ(m["op"], true) << "state " << s["state"] << ", AL status code " << s["al_status_code"];
        EXPECT_EQ(m["wkc_ok"], 1000);

        // What SOEM reads back over CoE, and sized its image by, is the remap.
        nlohmann::json assign = nlohmann::json::array();
        std::uint32_t bits = 0;
        std::map<std::uint32_t, std::uint32_t> offset_of;  // object index -> bit offset in the outputs
        for (const auto& [pdo, entries] : remap.pdos) {
            assign.push_back({{"pdo", pdo}, {"entries", entries}});
            for (std::uint32_t e : entries) {
                if (e >> 16) offset_of[e >> 16] = bits;
                bits += e & 0xFF;
            }
        }
        EXPECT_EQ(s["assign"]["7186"], assign);
        EXPECT_EQ(s["assign"]["7187"], fw.default_assign["7187"]) << "the inputs keep their default mapping";
        EXPECT_EQ(m["obytes"], bits / 8);
        if (remap.name == "maximal") {
            EXPECT_EQ(bits, 42u * 8);
        }

        // The outputs of the last cycle are in SOES's objects, taken from their new offsets.
        const std::string& outputs = m["outputs"].get_ref<const std::string&>();
        int checked = 0;
        for (const auto& o : (*r.host)[0]["outputs"]) {
            const auto it = offset_of.find(o["index"].get<std::uint32_t>());
            if (it == offset_of.end()) continue;
            SCOPED_TRACE(fmt::format("0x{:04X}", it->first));
            ASSERT_TRUE(o.contains("value"));
            const std::uint32_t width = it->first == A180 ? 8 : 16;
            EXPECT_EQ(image_bits(outputs, it->second, width), o["value"].get<std::uint64_t>());
            ++checked;
        }
        EXPECT_EQ(checked, static_cast<int>(offset_of.size()));
    }
}

}  // namespace
}  // namespace esi::test
