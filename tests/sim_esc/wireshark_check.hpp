#pragma once
// The traffic of a LineMaster session, as a capture on the master's port (pcap, Ethernet), and
// what Wireshark's EtherCAT dissectors (tshark: ecatf, ecat, ecat_mailbox) make of it. tshark is
// Debian's package, a reader libesi's authors did not write (../shared/tools/README.md).

#include <filesystem>
#include <string>
#include <vector>

#include "sim_esc/line_master.hpp"

namespace esi::test {

// A classic pcap file (link type 1, Ethernet): each frame behind a broadcast destination, a
// locally administered source and EtherType 0x88A4, padded to Ethernet's 60-byte minimum. With
// ESI_KEEP_CAPTURES=DIR set, a copy goes to DIR under the same name, to open in Wireshark.
void write_pcap(const std::filesystem::path& path, const std::vector<CapturedFrame>& frames);

// Whether tshark is installed; a test that needs it skips without it, but fails in CI
// (CI is set), where scripts/install-deps.sh installs it.
bool have_tshark();
#define ESI_REQUIRE_TSHARK()                                                                            \
    do {                                                                                                \
        if (!::esi::test::have_tshark()) {                                                              \
            if (std::getenv("CI")) FAIL() << "tshark not installed in CI (scripts/install-deps.sh)";    \
            GTEST_SKIP() << "tshark not installed (package tshark): Wireshark's decoding not checked";  \
        }                                                                                               \
    } while (0)

struct TsharkDecoding {
    int exit_code = 0;
    std::string error;
    std::size_t frames = 0;            // frames tshark read
    std::size_t ethercat_frames = 0;   // frames it decoded as EtherCAT
    std::vector<std::string> malformed;  // "frame N: info" of every frame with a malformed or error mark
};

// Reads the capture with tshark; every frame flagged malformed, or with an expert item of
// severity error, is listed.
TsharkDecoding tshark_decode(const std::filesystem::path& pcap);

// One field per line of every frame that has `filter` (tshark -Y FILTER -T fields -e ...),
// fields separated by '\t'.
std::vector<std::string> tshark_fields(const std::filesystem::path& pcap, const std::string& filter,
                                       const std::vector<std::string>& fields);

}  // namespace esi::test
