#include "net/net_test_support.hpp"

#include "esi/net/network_spec.hpp"
#include "support/test_support.hpp"

namespace esi::test {

std::filesystem::path corpus_dir() { return shared_dir() / "corpus"; }

const esi::net::LibraryIndex& corpus_index() {
    static const esi::net::LibraryIndex index = [] {
        const std::vector<std::filesystem::path> roots = {corpus_dir() / "esi", corpus_dir() / "eni" / "esi",
                                                          corpus_dir() / "master-configs" / "lcec" / "esi"};
        return esi::net::build_library_index(roots, {}).index;
    }();
    return index;
}

esi::net::BuildResult build_corpus_network(const std::string& yaml, const std::string& name) {
    const esi::net::NetworkFileResult read = esi::net::read_network_text(yaml, name);
    if (!read.spec) {
        esi::net::BuildResult result;
        result.diagnostics = read.diagnostics;
        return result;
    }
    return esi::net::build_network(*read.spec, corpus_index());
}

std::string cherry_esi_file() { return (corpus_dir() / "eni" / "esi" / "cherry-embedded__CherryECAT__ECAT_CIA402_ESI.xml").string(); }

std::filesystem::path igh_api_dir() { return source_dir() / "tests" / "net" / "data" / "igh_api"; }

std::string diagnostics_text(const esi::Diagnostics& diagnostics) {
    std::string out;
    for (const esi::Diagnostic& d : diagnostics) out += esi::format_diagnostic(d);
    return out;
}

}  // namespace esi::test

namespace esi::test {

const std::vector<NamedNetwork>& corpus_networks() {
    static const std::vector<NamedNetwork> networks = [] {
        std::vector<NamedNetwork> out;
        out.push_back({"beckhoff-terminals", R"(master: { name: Mega Master (EtherCAT), cycle_time_us: 2000 }
slaves:
  - { name: Coupler, product_code: 0x044C2C52, revision: 0x00120000 }
  - { name: Outputs, product_code: 0x07D83052, revision: 0x00120000 }
  - { name: Inputs, device: EL1809 }
  - { name: Latches, product_code: 0x04E43052, revision: 0x00120000 }
)"});
        std::string drives = "master: { name: Line, cycle_time_us: 1000 }\nslaves:\n";
        for (int i = 1; i <= 2; ++i)
            drives += "  - { name: Axis " + std::to_string(i) + ", product_code: 0x00030924, revision: 0x00010420, pdos: [0x1601, 0x1A03] }\n";
        out.push_back({"elmo-drives", drives});
        out.push_back({"elmo-configured", R"(master: { name: Line, cycle_time_us: 2000 }
slaves:
  - name: Axis 1
    product_code: 0x00030924
    revision: 0x00010420
    pdos: [0x1607, 0x1A07]
    pdo_entries:
      0x1607: [0x607A:0x00:32, 0x60FE:0x01:32, 0x6071:0x00:16, 0x6040:0x00:16]
      0x1A07: [0x6064:0x00:32, 0x6041:0x00:16, 0x0000:0x00:16]
    sdos:
      - { index: 0x6060, subindex: 0, value: 8, comment: Op mode CSP }
      - { index: 0x6065, value: 10000, transition: [PS, SO] }
      - { index: 0x3FFF, type: UDINT, value: 0x12345678 }
)"});
        // Three corpus files describe ECAT_CIA402 and configure it differently: CherryECAT's export
        // was made from the one in eni/esi.
        out.push_back({"cherry-modular", R"(master: { name: Device 2 (EtherCAT), cycle_time_us: 2000 }
slaves:
  - name: Drive 1
    device: ECAT_CIA402
    esi_file: ")" + cherry_esi_file() + R"("
    modules: [csv -  axis, csp - axis]
    sdos: [{ index: 0x6060, value: 9, transition: SO }]
)"});
        out.push_back({"high-identities", R"(master: { name: ETG sample, cycle_time_us: 4000 }
slaves:
  - { name: Drive, device: Drive1, modules: [0x100, Position Mode (DC)] }
)"});
        // A tree (issue 24 §4): an EK1122 junction on the coupler's E-Bus, a drive on each of its
        // Ethernet ports (D is visited before B) and a terminal on its E-Bus port C.
        out.push_back({"junction-tree", R"(master: { name: Tree, cycle_time_us: 1000 }
slaves:
  - { name: Coupler, product_code: 0x044C2C52, revision: 0x00120000 }
  - { name: Junction, product_code: 0x04622C52, revision: 0x00110000 }
  - { name: Axis D, product_code: 0x00030924, revision: 0x00010420, previous_port: D }
  - { name: Axis B, product_code: 0x00030924, revision: 0x00010420, previous_slave: Junction, previous_port: B }
  - { name: Outputs, product_code: 0x07D83052, revision: 0x00120000, previous_slave: Junction }
)"});
        return out;
    }();
    return networks;
}

}  // namespace esi::test
