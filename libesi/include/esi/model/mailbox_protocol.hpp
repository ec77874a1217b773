#pragma once
// The mailbox protocols a device declares in its Mailbox element (ETG.2000 MailboxType) and in
// SII word 0x1C (ETG.1000.6 Table 18): one name for them in every layer.

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace esi {

// In the order of the SII bits (AoE 0x01 … VoE 0x20), which is also the order of the Mailbox
// children in the schema.
enum class MailboxProtocol : std::uint8_t { aoe, eoe, coe, foe, soe, voe };

inline constexpr std::array<MailboxProtocol, 6> mailbox_protocols = {MailboxProtocol::aoe, MailboxProtocol::eoe,
                                                                     MailboxProtocol::coe, MailboxProtocol::foe,
                                                                     MailboxProtocol::soe, MailboxProtocol::voe};

// The protocols with InitCmds, in the order reports, checks and generated tables list their
// commands: CoE, SoE, EoE, AoE. FoE and VoE carry no typed content.
inline constexpr std::array<MailboxProtocol, 4> init_cmd_protocols = {MailboxProtocol::coe, MailboxProtocol::soe,
                                                                      MailboxProtocol::eoe, MailboxProtocol::aoe};

// The element name in the ESI: "AoE", "EoE", "CoE", "FoE", "SoE", "VoE".
[[nodiscard]] constexpr std::string_view to_string(MailboxProtocol protocol) {
    constexpr std::string_view names[] = {"AoE", "EoE", "CoE", "FoE", "SoE", "VoE"};
    return names[static_cast<std::size_t>(protocol)];
}

// The protocol's bit in SII word 0x1C and in Mailbox::protocol_bits().
[[nodiscard]] constexpr std::uint16_t sii_bit(MailboxProtocol protocol) {
    return static_cast<std::uint16_t>(1u << static_cast<unsigned>(protocol));
}

// The names of the protocols whose bits are set, in bit order, separated by blanks ("EoE CoE");
// `none` when no bit is set.
[[nodiscard]] std::string mailbox_protocol_names(std::uint16_t sii_bits, std::string_view none);

}  // namespace esi
