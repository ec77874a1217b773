// CoE header and service dispatch (coe_server.hpp).

#include "sim/coe_server.hpp"

#include <algorithm>

#include "esi/ethercat/mailbox.hpp"
#include "sim/sdo_info.hpp"

namespace esi::sim {

namespace {

// CoE services (ETG.1000.6 Table 29).
constexpr std::uint8_t service_sdo_request = ethercat::coe_service::sdo_request;
constexpr std::uint8_t service_sdo_response = ethercat::coe_service::sdo_response;
constexpr std::uint8_t service_sdo_information = ethercat::coe_service::sdo_information;
using ethercat::coe_header_bytes;

std::vector<std::uint8_t> with_header(std::uint8_t service, const std::vector<std::uint8_t>& body) {
    std::vector<std::uint8_t> out(coe_header_bytes + body.size(), 0);
    out[1] = static_cast<std::uint8_t>(service << 4);
    std::copy(body.begin(), body.end(), out.begin() + coe_header_bytes);
    return out;
}

}  // namespace

CoeReply CoeServer::handle(std::span<const std::uint8_t> request, AlState state, std::size_t room) {
    CoeReply reply;
    if (request.size() < coe_header_bytes) {
        reply.mailbox_error = ethercat::mailbox_error::size_too_short;
        return reply;
    }
    if (room <= coe_header_bytes) {
        reply.mailbox_error = ethercat::mailbox_error::no_more_memory;
        return reply;
    }
    const std::uint8_t service = request[1] >> 4;
    const std::span<const std::uint8_t> body = request.subspan(coe_header_bytes);
    const std::size_t body_room = room - coe_header_bytes;
    if (service == service_sdo_request) {
        std::vector<std::uint8_t> response = sdo_.handle(body, state, body_room);
        // The abort transfer (command 0x80) is an "SDO request" (ETG.1000.6 5.6.2.7, Table 29);
        // masters recognise it only with that service (IgH's CoE state machine checks service 2,
        // Wireshark's dissector decodes the abort code only there). Every other answer is a response.
        const bool abort = !response.empty() && response[0] == ethercat::sdo_abort_command;
        if (!response.empty()) reply.frames.push_back(with_header(abort ? service_sdo_request : service_sdo_response, response));
        return reply;
    }
    if (service == service_sdo_information && sdo_info_) {
        for (const std::vector<std::uint8_t>& f : sdo_info_response(access_.dictionary(), body, body_room))
            reply.frames.push_back(with_header(service_sdo_information, f));
        if (reply.frames.empty()) reply.mailbox_error = ethercat::mailbox_error::no_more_memory;
        return reply;
    }
    reply.mailbox_error = ethercat::mailbox_error::service_not_supported;
    return reply;
}

}  // namespace esi::sim
