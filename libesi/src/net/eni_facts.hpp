#pragma once
// What `init --from-eni` reads from an ENI: per slave its identity, the assigned PDOs in SM
// order with their entries, the CoE start-up commands and the DC AssignActivate, plus the
// master's name and cycle. Numbers are read as the exports write them: decimal, "#x…" hex, or a
// negative xs:int for identities from 0x80000000 up.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "esi/diagnostic.hpp"
#include "esi/net/network.hpp"

namespace esi::net {

struct EniEntryFact {
    std::uint32_t index = 0, subindex = 0, bit_len = 0;
    friend bool operator==(const EniEntryFact&, const EniEntryFact&) = default;
};

struct EniPdoFact {
    std::uint32_t index = 0;
    std::vector<EniEntryFact> entries;
};

struct EniSlaveFacts {
    std::string name;
    std::uint32_t vendor_id = 0, product_code = 0, revision = 0;
    std::optional<std::uint16_t> alias;
    std::vector<EniPdoFact> assigned;  // SM by SM, in assignment order
    std::vector<CoeCommand> coe;  // as the ENI sends them (origin: network)
    std::uint16_t assign_activate = 0;  // 0: no DC
    std::uint32_t line = 0;             // of the Slave element, for diagnostics
    std::optional<std::uint32_t> phys_addr;  // Info/PhysAddr
    // The selected PreviousPort (the only one, else the one with Selected 1/true): the port
    // letter of the upstream slave and its station address.
    std::optional<char> previous_port;
    std::optional<std::uint32_t> previous_phys_addr;
};

struct EniFacts {
    std::string master_name;
    std::optional<std::uint32_t> cycle_time_us;
    std::vector<EniSlaveFacts> slaves;
};

// nullopt with an error when the text is not an ENI (or an encrypted one).
[[nodiscard]] std::optional<EniFacts> read_eni_facts(std::string_view xml, const std::string& path, Diagnostics& diagnostics);

}  // namespace esi::net
