#include "esi/model/mailbox_protocol.hpp"

namespace esi {

std::string mailbox_protocol_names(std::uint16_t sii_bits, std::string_view none) {
    std::string out;
    for (const MailboxProtocol protocol : mailbox_protocols) {
        if (!(sii_bits & sii_bit(protocol))) continue;
        if (!out.empty()) out += ' ';
        out += to_string(protocol);
    }
    return out.empty() ? std::string(none) : out;
}

}  // namespace esi
