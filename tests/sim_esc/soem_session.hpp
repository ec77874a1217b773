#pragma once
// Test helper: esi-sim and the SOEM test master (tests/sim_esc/soem/soem_master.c) on the two ends
// of a veth pair inside a user and network namespace (unshare -rn), so no privileges are needed.
// Several runs share one namespace and run one after the other, each with its own esi-sim.

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace esi::test {

struct SoemStep {
    std::vector<std::string> sim_args;     // after `esi-sim --iface v1`
    std::vector<std::string> master_args;  // after `soem_master v0`
};

struct SoemStepResult {
    std::optional<nlohmann::json> report;  // the master's JSON; absent when it printed none
    std::string master_output;
    std::string sim_stderr;
    int sim_exit = -1;                     // esi-sim's exit code after SIGTERM
};

// Why SOEM runs cannot happen here (no master built, namespaces refused, no `ip`), or empty.
[[nodiscard]] std::string soem_unavailable();

[[nodiscard]] std::vector<SoemStepResult> run_soem_session(const std::vector<SoemStep>& steps);

}  // namespace esi::test

#define ESI_REQUIRE_SOEM()                                                      \
    do {                                                                        \
        const std::string why = ::esi::test::soem_unavailable();                \
        if (!why.empty()) GTEST_SKIP() << "SOEM runs skipped: " << why;         \
    } while (0)
