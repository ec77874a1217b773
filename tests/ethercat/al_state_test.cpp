// The protocol layer's state machine facts (ETG.1000.6 6.4, Table 11): states and transitions
// read and written by their names, the eleven transitions of the machine, status code texts.

#include <gtest/gtest.h>

#include "esi/ethercat/al_state.hpp"

namespace esi::ethercat {
namespace {

TEST(AlStates, EveryStateReadsBackFromItsNameAndItsBits) {
    for (const AlState s : {AlState::init, AlState::preop, AlState::boot, AlState::safeop, AlState::op}) {
        EXPECT_EQ(parse_al_state(al_state_name(s)), s);
        EXPECT_EQ(al_state_from_bits(static_cast<std::uint16_t>(s)), s);
        EXPECT_EQ(al_state_from_bits(static_cast<std::uint16_t>(static_cast<unsigned>(s) | al_error_bit)), s);
    }
    EXPECT_EQ(al_state_name(AlState::safeop), "SAFEOP");
    EXPECT_FALSE(al_state_from_bits(0x0005));
    EXPECT_FALSE(al_state_from_bits(0x0000));
    EXPECT_FALSE(parse_al_state("SAFE-OP"));
}

TEST(AlStates, EveryPairOfStatesHasItsTwoLetterName) {
    const char letters[] = "IPBSO";
    std::size_t pairs = 0;
    for (const char a : std::string_view(letters)) {
        for (const char b : std::string_view(letters)) {
            const std::string name{a, b};
            const std::optional<Transition> t = parse_transition(name);
            ASSERT_TRUE(t) << name;
            EXPECT_EQ(transition_name(*t), name);
            ++pairs;
        }
    }
    EXPECT_EQ(pairs, 25u);
    EXPECT_EQ(parse_transition("PS"), (Transition{AlState::preop, AlState::safeop}));
    EXPECT_FALSE(parse_transition("PX"));
    EXPECT_FALSE(parse_transition("P"));
    EXPECT_FALSE(parse_transition("PSO"));
}

TEST(AlStates, TheMachineHasTheElevenTransitionsOfEtg1000Part6) {
    std::vector<std::string_view> names;
    for (const Transition& t : state_machine_transitions()) names.push_back(transition_name(t));
    EXPECT_EQ(names, (std::vector<std::string_view>{"IP", "PI", "PS", "SP", "SO", "OS", "OP", "SI", "OI", "IB", "BI"}));
    const std::span<const std::string_view> listed = state_machine_transition_names();
    EXPECT_EQ(std::vector<std::string_view>(listed.begin(), listed.end()), names);
    for (const char* bad : {"IS", "IO", "PO", "PB", "SB", "OB", "II", "BO"})
        EXPECT_FALSE(is_state_machine_transition(*parse_transition(bad))) << bad;
}

TEST(AlStatusCodes, KnownCodesHaveTheTableTextOthersSayWhatTheyAre) {
    EXPECT_EQ(al_status_code_text(al_code::invalid_mailbox_configuration), "Invalid mailbox configuration");
    EXPECT_EQ(al_status_code_text(al_code::sm_watchdog), "Sync manager watchdog");
    EXPECT_EQ(al_status_code_text(al_code::invalid_output_configuration), "Invalid output configuration");
    EXPECT_EQ(al_status_code_text(0x0029), "Freerun needs 3-buffer mode");
    EXPECT_EQ(al_status_code_text(0x8001), "vendor specific");
    EXPECT_EQ(al_status_code_text(0x00EE), "reserved");
}

}  // namespace
}  // namespace esi::ethercat
