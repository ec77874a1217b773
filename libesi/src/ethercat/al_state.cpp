// AL states, transitions and status codes (al_state.hpp).

#include "esi/ethercat/al_state.hpp"

#include <algorithm>
#include <array>
#include <utility>

namespace esi::ethercat {

namespace {

struct StateName {
    AlState state;
    std::string_view name;
    char letter;
};
constexpr std::array<StateName, 5> states = {{
    {AlState::init, "INIT", 'I'},
    {AlState::preop, "PREOP", 'P'},
    {AlState::boot, "BOOT", 'B'},
    {AlState::safeop, "SAFEOP", 'S'},
    {AlState::op, "OP", 'O'},
}};

constexpr std::array<Transition, 11> machine = {{
    {AlState::init, AlState::preop},   {AlState::preop, AlState::init},   {AlState::preop, AlState::safeop},
    {AlState::safeop, AlState::preop}, {AlState::safeop, AlState::op},    {AlState::op, AlState::safeop},
    {AlState::op, AlState::preop},     {AlState::safeop, AlState::init},  {AlState::op, AlState::init},
    {AlState::init, AlState::boot},    {AlState::boot, AlState::init},
}};

// Two-letter names of every pair of states, in the order of `states`.
constexpr std::array<std::string_view, 25> pair_names = {
    "II", "IP", "IB", "IS", "IO", "PI", "PP", "PB", "PS", "PO", "BI", "BP", "BB", "BS", "BO",
    "SI", "SP", "SB", "SS", "SO", "OI", "OP", "OB", "OS", "OO",
};

std::size_t position(AlState s) {
    return static_cast<std::size_t>(std::find_if(states.begin(), states.end(), [s](const StateName& n) { return n.state == s; }) -
                                    states.begin());
}

// ETG.1000.6 Table 11.
constexpr std::pair<std::uint16_t, std::string_view> code_texts[] = {
    {0x0000, "No error"},
    {0x0001, "Unspecified error"},
    {0x0002, "No memory"},
    {0x0003, "Invalid device setup"},
    {0x0011, "Invalid requested state change"},
    {0x0012, "Unknown requested state"},
    {0x0013, "Bootstrap not supported"},
    {0x0014, "No valid firmware"},
    {0x0015, "Invalid mailbox configuration (bootstrap)"},
    {0x0016, "Invalid mailbox configuration"},
    {0x0017, "Invalid sync manager configuration"},
    {0x0018, "No valid inputs available"},
    {0x0019, "No valid outputs"},
    {0x001A, "Synchronization error"},
    {0x001B, "Sync manager watchdog"},
    {0x001C, "Invalid sync manager types"},
    {0x001D, "Invalid output configuration"},
    {0x001E, "Invalid input configuration"},
    {0x001F, "Invalid watchdog configuration"},
    {0x0020, "Slave needs cold start"},
    {0x0021, "Slave needs INIT"},
    {0x0022, "Slave needs PREOP"},
    {0x0023, "Slave needs SAFEOP"},
    {0x0024, "Invalid input mapping"},
    {0x0025, "Invalid output mapping"},
    {0x0026, "Inconsistent settings"},
    {0x0027, "Freerun not supported"},
    {0x0028, "Synchronization not supported"},
    {0x0029, "Freerun needs 3-buffer mode"},
    {0x002A, "Background watchdog"},
    {0x002B, "No valid inputs and outputs"},
    {0x002C, "Fatal sync error"},
    {0x002D, "No sync error"},
    {0x002E, "Cycle time too small"},
    {0x0030, "Invalid DC SYNC configuration"},
    {0x0031, "Invalid DC latch configuration"},
    {0x0032, "PLL error"},
    {0x0033, "DC sync IO error"},
    {0x0034, "DC sync timeout error"},
    {0x0035, "DC invalid sync cycle time"},
    {0x0036, "DC SYNC0 cycle time"},
    {0x0037, "DC SYNC1 cycle time"},
    {0x0041, "Mailbox AoE"},
    {0x0042, "Mailbox EoE"},
    {0x0043, "Mailbox CoE"},
    {0x0044, "Mailbox FoE"},
    {0x0045, "Mailbox SoE"},
    {0x004F, "Mailbox VoE"},
    {0x0050, "EEPROM no access"},
    {0x0051, "EEPROM error"},
    {0x0052, "External hardware not ready"},
    {0x0060, "Slave restarted locally"},
    {0x0061, "Device identification value updated"},
    {0x00F0, "Application controller available"},
};

}  // namespace

std::optional<AlState> al_state_from_bits(std::uint16_t status) {
    const auto bits = static_cast<std::uint8_t>(status & al_state_mask);
    for (const StateName& n : states)
        if (static_cast<std::uint8_t>(n.state) == bits) return n.state;
    return std::nullopt;
}

std::string_view al_state_name(AlState state) { return states[position(state)].name; }

std::optional<AlState> parse_al_state(std::string_view name) {
    for (const StateName& n : states)
        if (n.name == name) return n.state;
    return std::nullopt;
}

std::optional<Transition> parse_transition(std::string_view text) {
    if (text.size() != 2) return std::nullopt;
    std::optional<AlState> from, to;
    for (const StateName& n : states) {
        if (n.letter == text[0]) from = n.state;
        if (n.letter == text[1]) to = n.state;
    }
    if (!from || !to) return std::nullopt;
    return Transition{*from, *to};
}

std::string_view transition_name(const Transition& transition) {
    return pair_names[position(transition.from) * states.size() + position(transition.to)];
}

std::span<const Transition> state_machine_transitions() { return machine; }

std::span<const std::string_view> state_machine_transition_names() {
    static const std::array<std::string_view, machine.size()> names = [] {
        std::array<std::string_view, machine.size()> out{};
        for (std::size_t i = 0; i < machine.size(); ++i)
            out[i] = transition_name(machine[i]);
        return out;
    }();
    return names;
}

bool is_state_machine_transition(const Transition& transition) {
    return std::find(machine.begin(), machine.end(), transition) != machine.end();
}

std::string_view al_status_code_text(std::uint16_t code) {
    for (const auto& [value, text] : code_texts)
        if (value == code) return text;
    return code >= 0x8000 ? "vendor specific" : "reserved";
}

}  // namespace esi::ethercat
