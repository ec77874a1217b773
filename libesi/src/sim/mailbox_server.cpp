// The mailbox of the device (mailbox_server.hpp).

#include "sim/mailbox_server.hpp"

#include "esi/ethercat/mailbox.hpp"
#include "sim/al_registers.hpp"

namespace esi::sim {

namespace {

constexpr std::size_t header_bytes = ethercat::mailbox_header_bytes;

}  // namespace

void MailboxServer::reset() {
    pending_.clear();
    last_written_.clear();
    last_request_counter_ = 0;
    counter_ = 0;
    if (coe_) coe_->reset();
}

void MailboxServer::poll(esc::Pdi& pdi, AlState state) {
    const MailboxGeometry& g = geometry_;
    if (g.in_length <= header_bytes || g.out_length < header_bytes) return;

    // Repeat: the master toggles the repeat request (activate register bit 1) when it lost an
    // answer; the device writes its last answer again and mirrors the bit in PDI control.
    // The activate register is read only here: its read acknowledges SM-change events, which
    // this stack does not use.
    const reg::SmRegisters in = reg::read_sm(pdi, g.in_sm, true);
    const std::uint8_t pdi_control = reg::read_u8(pdi, static_cast<std::uint16_t>(reg::sm(g.in_sm) + reg::sm_pdi_control));
    const bool repeat_request = (in.activate & reg::sm_activate_repeat) != 0;
    const bool repeat_ack = (pdi_control & reg::sm_pdi_repeat_ack) != 0;
    bool in_full = (in.status & reg::sm_status_mailbox_full) != 0;
    if (repeat_request != repeat_ack) {
        if (!in_full && !last_written_.empty()) {
            pdi.write(g.in_start, last_written_);
            in_full = true;
        }
        reg::write_u8(pdi, static_cast<std::uint16_t>(reg::sm(g.in_sm) + reg::sm_pdi_control),
                      static_cast<std::uint8_t>((pdi_control & ~reg::sm_pdi_repeat_ack) | (repeat_request ? reg::sm_pdi_repeat_ack : 0)));
    }

    if (!in_full && !pending_.empty()) {
        last_written_ = std::move(pending_.front());
        pending_.pop_front();
        pdi.write(g.in_start, last_written_);
        in_full = true;
    }

    if (!pending_.empty()) return;
    const reg::SmRegisters out = reg::read_sm(pdi, g.out_sm, false);
    if (!(out.status & reg::sm_status_mailbox_full)) return;
    std::vector<std::uint8_t> request(g.out_length);
    pdi.read(g.out_start, request);  // reading the last byte empties the mailbox
    handle(request, state);
    if (!pending_.empty() && !in_full) {
        last_written_ = std::move(pending_.front());
        pending_.pop_front();
        pdi.write(g.in_start, last_written_);
    }
}

void MailboxServer::handle(const std::vector<std::uint8_t>& request, AlState state) {
    const std::size_t length = static_cast<std::size_t>(request[0] | (request[1] << 8));
    const std::uint8_t type = request[5] & 0x0F;
    const std::uint8_t counter = (request[5] >> 4) & 0x07;
    if (length + header_bytes > request.size()) {
        send_error(ethercat::mailbox_error::invalid_size);
        return;
    }
    // ETG.1000.6 5.5.1: a counter equal to the previous request's marks a request the master
    // sent again after a lost working counter; it was executed already. 0 is never compared.
    if (counter != 0 && counter == last_request_counter_) return;
    last_request_counter_ = counter;
    if (type != mailbox_type::coe || !coe_) {
        send_error(type == mailbox_type::error ? ethercat::mailbox_error::syntax : ethercat::mailbox_error::unsupported_protocol);
        return;
    }
    const std::span<const std::uint8_t> body(request.data() + header_bytes, length);
    CoeReply reply = coe_->handle(body, state, geometry_.in_length - header_bytes);
    if (reply.mailbox_error) {
        send_error(reply.mailbox_error);
        return;
    }
    for (const std::vector<std::uint8_t>& frame : reply.frames) send(mailbox_type::coe, frame);
}

void MailboxServer::send(std::uint8_t type, const std::vector<std::uint8_t>& payload) {
    if (payload.size() + header_bytes > geometry_.in_length) return;  // cannot happen: answers are cut to the room
    counter_ = static_cast<std::uint8_t>(counter_ % 7 + 1);
    std::vector<std::uint8_t> buffer(geometry_.in_length, 0);
    buffer[0] = static_cast<std::uint8_t>(payload.size());
    buffer[1] = static_cast<std::uint8_t>(payload.size() >> 8);
    buffer[5] = static_cast<std::uint8_t>(type | (counter_ << 4));
    std::copy(payload.begin(), payload.end(), buffer.begin() + header_bytes);
    pending_.push_back(std::move(buffer));
}

void MailboxServer::send_error(std::uint16_t detail) {
    // Type 0x0001 ("mailbox command") with the detail (ETG.1000.6 5.5.2, Table 30).
    send(mailbox_type::error, {0x01, 0x00, static_cast<std::uint8_t>(detail), static_cast<std::uint8_t>(detail >> 8)});
}

}  // namespace esi::sim
