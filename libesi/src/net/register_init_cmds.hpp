#pragma once
// The register commands of an ENI (ECatCmdType): the master's bus preparation and, per slave,
// every register write and check a master runs on each state transition — AL control and
// status, the identity check through the SII, the station address, the SyncManagers and FMMUs,
// the ESC watchdogs and the DC activation. Both TwinCAT and EC-Engineer write the same skeleton
// (docs/esi-net.md, "Register init commands"); it is reproduced command for command, and the
// comparison test checks it against the corpus exports.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "esi/net/network.hpp"

namespace esi::net {

// ETG.1000.4 datagram commands used by init commands.
enum class RegisterCmd : std::uint8_t { aprd = 1, apwr = 2, fprd = 4, fpwr = 5, brd = 7, bwr = 8 };

struct RegisterValidate {
    std::vector<std::uint8_t> data;
    std::optional<std::vector<std::uint8_t>> mask;
    std::uint32_t timeout_ms = 0;
};

struct RegisterCommand {
    std::vector<std::string> transitions;
    bool before_slave = false;  // master commands
    std::string comment;
    bool requires_cycle = true;
    RegisterCmd cmd = RegisterCmd::fpwr;
    std::uint16_t adp = 0;
    std::uint16_t ado = 0;
    std::vector<std::uint8_t> data;
    std::optional<std::uint16_t> data_length;  // instead of data: that many zero bytes
    std::optional<std::uint16_t> cnt;
    std::uint16_t retries = 3;
    std::optional<RegisterValidate> validate;
    std::optional<std::uint32_t> timeout_ms;
};

[[nodiscard]] std::vector<RegisterCommand> master_init_cmds();
[[nodiscard]] std::vector<RegisterCommand> slave_init_cmds(const Network& network, const NetworkSlave& slave);

// The 8 bytes of SyncManager n (0x0800 + 8n) and the 16 of FMMU n (0x0600 + 16n).
[[nodiscard]] std::vector<std::uint8_t> sm_register_data(std::uint16_t start, std::uint16_t length, std::uint8_t control, bool enable);
[[nodiscard]] std::vector<std::uint8_t> fmmu_register_data(const FmmuSetup& fmmu);

}  // namespace esi::net
