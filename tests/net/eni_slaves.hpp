#pragma once
// An ENI file read slave by slave into comparable facts (pugixml, independent of the writer):
// identity, ProcessData (Send/Recv sizes, SmN settings, assigned PDOs and their entries), CoE
// InitCmds, register InitCmds, DC settings and the process-image variables in the slave's
// bit ranges. Values are normalised where the format allows several spellings (decimal or
// #x indices, true or 1, Data or DataLength) so that exports of different tools compare.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace esi::test {

struct EniPdo {
    std::string direction;  // RxPdo, TxPdo
    std::uint32_t index = 0;
    std::uint32_t sm = 0;
    std::vector<std::string> entries;  // "index:sub:bitlen:type" ("0:0:16:" for padding)
};

struct EniSm {
    std::uint32_t number = 0;
    std::string type;
    std::uint32_t start = 0, control = 0;
    bool enable = false;
    std::vector<std::uint32_t> pdos;
};

struct EniSlave {
    std::string name;
    std::uint32_t phys_addr = 0, auto_inc_addr = 0;
    std::uint32_t vendor_id = 0, product_code = 0, revision = 0;
    std::optional<std::uint32_t> send_bits, recv_bits;
    std::uint32_t send_start = 0, recv_start = 0;
    std::vector<EniSm> sms;
    std::vector<EniPdo> pdos;                 // the assigned ones (with an Sm attribute)
    std::vector<std::string> coe_init_cmds;   // "transitions|comment|index:sub|data|CA"
    std::vector<std::string> register_cmds;   // normalised, see eni_slaves.cpp
    std::optional<std::string> dc;            // "ref|cycle0|cycle1|shift"
    std::vector<std::string> outputs;         // "relative bit offset|bits|type" in the Send range
    std::vector<std::string> inputs;          // the same in the Recv range
};

struct EniFile {
    std::vector<EniSlave> slaves;
    std::vector<std::string> cyclic;  // "cmd|length|cnt"
    std::string error;
};

EniFile read_eni(const std::string& xml_text);

}  // namespace esi::test
