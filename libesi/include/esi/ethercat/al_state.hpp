#pragma once
// The EtherCAT state machine (ETG.1000.6 6.4): the AL states as AL control (0x0120) and AL status
// (0x0130) code them, the transitions between them with their two-letter names (ETG.2000 and
// ETG.2100 InitCmd/Transition), and the AL status codes (0x0134) a device refuses a transition
// with (ETG.1000.6 Table 11). Named once here for the emulated slave, the master, the rules and
// the network writers.

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace esi::ethercat {

enum class AlState : std::uint8_t { init = 1, preop = 2, boot = 3, safeop = 4, op = 8 };

// The state part of AL control and AL status (bits 0..3); bit 4 is the error indication in AL
// status and the error acknowledge in AL control.
inline constexpr std::uint16_t al_state_mask = 0x000F;
inline constexpr std::uint16_t al_error_bit = 0x0010;

// "INIT", "PREOP", "BOOT", "SAFEOP", "OP"; nullopt for any other value of the state bits.
[[nodiscard]] std::optional<AlState> al_state_from_bits(std::uint16_t status);
[[nodiscard]] std::string_view al_state_name(AlState state);
[[nodiscard]] std::optional<AlState> parse_al_state(std::string_view name);

// A transition by its two letters: I(NIT), P(REOP), B(OOT), S(AFEOP), O(P); "PS" is PREOP to
// SAFEOP.
struct Transition {
    AlState from = AlState::init;
    AlState to = AlState::init;
    friend bool operator==(const Transition&, const Transition&) = default;
};
[[nodiscard]] std::optional<Transition> parse_transition(std::string_view text);
[[nodiscard]] std::string_view transition_name(const Transition& transition);
// The transitions of the state machine (ETG.1000.6 Figure 12): IP, PI, PS, SP, SO, OS, OP, SI,
// OI, IB, BI. A device refuses any other request with 0x0011.
[[nodiscard]] std::span<const Transition> state_machine_transitions();
[[nodiscard]] bool is_state_machine_transition(const Transition& transition);
// Their two-letter names, in the same order ("IP", "PI", "PS", ...).
[[nodiscard]] std::span<const std::string_view> state_machine_transition_names();

// AL status codes (ETG.1000.6 Table 11).
namespace al_code {
inline constexpr std::uint16_t none = 0x0000;
inline constexpr std::uint16_t unspecified = 0x0001;
inline constexpr std::uint16_t no_memory = 0x0002;
inline constexpr std::uint16_t invalid_state_change = 0x0011;
inline constexpr std::uint16_t unknown_state = 0x0012;
inline constexpr std::uint16_t bootstrap_not_supported = 0x0013;
inline constexpr std::uint16_t no_valid_firmware = 0x0014;
inline constexpr std::uint16_t invalid_bootstrap_mailbox_configuration = 0x0015;
inline constexpr std::uint16_t invalid_mailbox_configuration = 0x0016;
inline constexpr std::uint16_t invalid_sm_configuration = 0x0017;
inline constexpr std::uint16_t no_valid_inputs = 0x0018;
inline constexpr std::uint16_t no_valid_outputs = 0x0019;
inline constexpr std::uint16_t synchronization_error = 0x001A;
inline constexpr std::uint16_t sm_watchdog = 0x001B;
inline constexpr std::uint16_t invalid_sm_types = 0x001C;
inline constexpr std::uint16_t invalid_output_configuration = 0x001D;
inline constexpr std::uint16_t invalid_input_configuration = 0x001E;
inline constexpr std::uint16_t invalid_watchdog_configuration = 0x001F;
inline constexpr std::uint16_t invalid_dc_sync_configuration = 0x0030;
inline constexpr std::uint16_t invalid_dc_latch_configuration = 0x0031;
inline constexpr std::uint16_t invalid_sync_cycle_time = 0x0035;
}  // namespace al_code

// The text ETG.1000.6 Table 11 gives a code ("Invalid mailbox configuration"); for a code it does
// not list, "vendor specific" (0x8000 and above) or "reserved".
[[nodiscard]] std::string_view al_status_code_text(std::uint16_t code);

}  // namespace esi::ethercat
