#pragma once
// Test helper: a sample device as SOES firmware on the emulated ESC. For a device source, esi-gen
// writes the SOES set and the EEPROM image, esi-net maps a network of that one slave
// (process_image.json), and cc builds the SOES core, the set and the HAL of firmware/ into the
// shared object esi_soes_host loads. Then esi_soes_host and a SOEM master run on the two ends of
// a veth pair in a user and network namespace (unshare -rn), one session per test.

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace esi::test {

// Why SOES runs cannot happen here (no SOES, no cc, no SOEM master, namespaces refused), or empty.
[[nodiscard]] std::string soes_unavailable();

struct SoesFirmware {
    std::filesystem::path source;  // samples/NAME.yaml
    std::string type;              // the device's Type text
    std::string selector;          // PRODUCTCODE:REVISION
    std::filesystem::path generated, eeprom, library;
    nlohmann::json process_image;  // esi-net's map of a network of this one slave
    std::string error;             // what failed while building; empty when ready
    // The model's PDO assignment by default, as 0x1C12/0x1C13 list it over CoE.
    nlohmann::json default_assign;
};

// Builds the firmware of the one device in `source` in `dir`; `sanitize` builds it with
// AddressSanitizer (the host then preloads the runtime).
[[nodiscard]] SoesFirmware build_soes_firmware(const std::filesystem::path& source, const std::filesystem::path& dir,
                                               bool sanitize = false);

// The same, built once per test program run (in a directory that lives as long as it): the
// tests share each sample's firmware instead of compiling the SOES core again.
[[nodiscard]] const SoesFirmware& soes_firmware(const std::filesystem::path& source, bool sanitize = false);

struct SoesStep {
    std::vector<std::string> host_args;    // after `esi_soes_host --iface v1`
    std::vector<std::string> master_args;  // after `MASTER v0`
    std::string master;                    // the master program; empty: esi_soes_master
    bool sanitize = false;                 // preload the AddressSanitizer runtime into the host
};

struct SoesStepResult {
    std::optional<nlohmann::json> master;  // the master's JSON
    std::optional<nlohmann::json> host;    // the host's report (one entry per SOES slave)
    std::string master_output, host_output, host_stderr;
    int host_exit = -1;
};

[[nodiscard]] std::vector<SoesStepResult> run_soes_session(const std::vector<SoesStep>& steps);

// The `bits` bits at bit `offset` of the little-endian image in `hex` (what a variable holds).
[[nodiscard]] std::uint64_t image_bits(const std::string& hex, std::uint32_t offset, std::uint32_t bits);

// Every variable of `process_image` (esi-net's process_image.json) at slave `position`: the bits
// the master holds at its offset (`master`: esi_soes_master's report) equal the value of the
// object in SOES (`host_slave`: the host's report of that slave; outputs: what SOES received
// last in OP, inputs: what the host set). Expects at least one variable when the slave has
// process data.
void expect_variables_match(const nlohmann::json& process_image, int position, const nlohmann::json& master,
                            const nlohmann::json& host_slave);

}  // namespace esi::test

#define ESI_REQUIRE_SOES_ON_SIM()                                                    \
    do {                                                                             \
        const std::string why = ::esi::test::soes_unavailable();                     \
        if (!why.empty()) GTEST_SKIP() << "SOES firmware runs skipped: " << why;     \
    } while (0)
