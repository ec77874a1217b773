#include "sim_esc/line_master.hpp"

#include <algorithm>

#include "esi/esc/frame.hpp"
#include "esi/ethercat/al_state.hpp"
#include "esi/ethercat/mailbox.hpp"
#include "esi/ethercat/registers.hpp"
#include "esi/sii/image.hpp"

namespace esi::test {

namespace {

namespace reg = ethercat::reg;
using esc::Command;

std::uint16_t u16(const std::vector<std::uint8_t>& b, std::size_t at) {
    return static_cast<std::uint16_t>(b[at] | (b[at + 1] << 8));
}
std::uint32_t u32(const std::vector<std::uint8_t>& b, std::size_t at) {
    return static_cast<std::uint32_t>(b[at]) | (static_cast<std::uint32_t>(b[at + 1]) << 8) |
           (static_cast<std::uint32_t>(b[at + 2]) << 16) | (static_cast<std::uint32_t>(b[at + 3]) << 24);
}
void put16(std::vector<std::uint8_t>& b, std::size_t at, std::uint16_t v) {
    b[at] = static_cast<std::uint8_t>(v);
    b[at + 1] = static_cast<std::uint8_t>(v >> 8);
}
void put32(std::vector<std::uint8_t>& b, std::size_t at, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) b[at + i] = static_cast<std::uint8_t>(v >> (8 * i));
}
std::vector<std::uint8_t> le16(std::uint16_t v) { return {static_cast<std::uint8_t>(v), static_cast<std::uint8_t>(v >> 8)}; }

// The protocol's codes (esi/ethercat/mailbox.hpp).
namespace cmd = ethercat::sdo_command;
namespace op = ethercat::sdo_info_opcode;
using ethercat::coe_service::sdo_information;
using ethercat::coe_service::sdo_request;
using ethercat::coe_service::sdo_response;
using ethercat::mailbox_type::coe;
using ethercat::mailbox_type::error;

std::uint8_t coe_service(const std::vector<std::uint8_t>& answer) { return answer[7] >> 4; }

// An SDO request: CoE header, command, index, sub-index, four data bytes.
std::vector<std::uint8_t> sdo_request_frame(std::uint8_t command, std::uint16_t index, std::uint8_t subindex) {
    return {0x00, static_cast<std::uint8_t>(sdo_request << 4), command, static_cast<std::uint8_t>(index),
            static_cast<std::uint8_t>(index >> 8), subindex, 0, 0, 0, 0};
}

// An SDO answer that is an abort (command 0x80): its code. ETG.1000.6 5.6.2.7 has the abort
// transfer as an "SDO request" (service 2); an abort under another service is not taken as one.
std::optional<std::uint32_t> abort_code(const std::vector<std::uint8_t>& a) {
    if (a.size() >= 16 && coe_service(a) == sdo_request && a[8] == ethercat::sdo_abort_command) return u32(a, 12);
    return std::nullopt;
}

}  // namespace

std::optional<std::vector<Answer>> LineMaster::frame(
    const std::vector<std::tuple<esc::Command, std::uint16_t, std::uint16_t, std::vector<std::uint8_t>>>& datagrams) {
    std::vector<std::uint8_t> payload(2);
    std::vector<std::uint8_t> indices;
    for (std::size_t i = 0; i < datagrams.size(); ++i) {
        const auto& [command, adp, ado, data] = datagrams[i];
        const std::size_t at = payload.size();
        payload.resize(at + 10 + data.size() + 2, 0);
        payload[at] = static_cast<std::uint8_t>(command);
        payload[at + 1] = next_index_;
        indices.push_back(next_index_++);
        put16(payload, at + 2, adp);
        put16(payload, at + 4, ado);
        put16(payload, at + 6, static_cast<std::uint16_t>(data.size() | (i + 1 < datagrams.size() ? 0x8000 : 0)));
        std::copy(data.begin(), data.end(), payload.begin() + static_cast<std::ptrdiff_t>(at + 10));
    }
    put16(payload, 0, static_cast<std::uint16_t>((payload.size() - 2) | 0x1000));
    time_ns += frame_gap_ns;
    capture.push_back({time_ns, true, payload});
    const esc::FrameOutcome outcome = line_.process(payload, time_ns);
    if (outcome != esc::FrameOutcome::answered) return std::nullopt;
    capture.push_back({time_ns + 1000, false, payload});
    std::vector<esc::DatagramSlot> slots;
    if (!esc::parse_frame(payload, slots) || slots.size() != datagrams.size()) return std::nullopt;
    std::vector<Answer> answers;
    for (std::size_t i = 0; i < slots.size(); ++i) {
        const std::size_t at = slots[i].header;
        const auto& [command, adp, ado, data] = datagrams[i];
        if (payload[at] != static_cast<std::uint8_t>(command) || payload[at + 1] != indices[i] || slots[i].length != data.size())
            return std::nullopt;
        Answer a;
        a.data.assign(payload.begin() + static_cast<std::ptrdiff_t>(at + 10),
                      payload.begin() + static_cast<std::ptrdiff_t>(at + 10 + data.size()));
        a.working_counter = u16(payload, at + 10 + data.size());
        answers.push_back(std::move(a));
    }
    return answers;
}

std::optional<Answer> LineMaster::datagram(esc::Command command, std::uint16_t adp, std::uint16_t ado, std::vector<std::uint8_t> data) {
    auto answers = frame({{command, adp, ado, std::move(data)}});
    if (!answers) return std::nullopt;
    return std::move(answers->front());
}

std::optional<std::vector<std::uint8_t>> LineMaster::read(std::uint16_t station, std::uint16_t address, std::size_t length) {
    auto a = datagram(Command::fprd, station, address, std::vector<std::uint8_t>(length, 0));
    if (!a || a->working_counter != 1) return std::nullopt;
    return std::move(a->data);
}

bool LineMaster::write(std::uint16_t station, std::uint16_t address, std::vector<std::uint8_t> data) {
    const auto a = datagram(Command::fpwr, station, address, std::move(data));
    return a && a->working_counter == 1;
}

std::optional<std::uint16_t> LineMaster::read16(std::uint16_t station, std::uint16_t address) {
    const auto b = read(station, address, 2);
    if (!b) return std::nullopt;
    return u16(*b, 0);
}

bool LineMaster::write16(std::uint16_t station, std::uint16_t address, std::uint16_t value) {
    return write(station, address, le16(value));
}

std::optional<std::vector<std::uint8_t>> LineMaster::read_sii(std::uint16_t station, std::uint32_t word, std::size_t bytes) {
    std::vector<std::uint8_t> out;
    const auto status = read16(station, reg::eeprom_control);
    if (!status) return std::nullopt;
    const std::size_t step = (*status & reg::eeprom_read_8_bytes) ? 8 : 4;
    while (out.size() < bytes) {
        std::vector<std::uint8_t> command(6, 0);
        put16(command, 0, reg::eeprom_command_read);
        put32(command, 2, word + static_cast<std::uint32_t>(out.size() / 2));
        if (!write(station, reg::eeprom_control, command)) return std::nullopt;
        std::optional<std::uint16_t> control;
        for (int poll = 0; poll < 10; ++poll) {  // the emulated EEPROM is never busy; a real one is for ~100 us
            control = read16(station, reg::eeprom_control);
            if (!control || !(*control & reg::eeprom_busy)) break;
        }
        if (!control || (*control & (reg::eeprom_busy | reg::eeprom_ack_error))) return std::nullopt;
        const auto data = read(station, reg::eeprom_data, step);
        if (!data) return std::nullopt;
        out.insert(out.end(), data->begin(), data->end());
    }
    out.resize(bytes);
    return out;
}

bool LineMaster::scan() {
    const auto count = datagram(Command::brd, 0, reg::type, {0, 0});
    if (!count || count->working_counter != line_.size()) return false;
    slaves.clear();
    for (std::size_t i = 0; i < line_.size(); ++i) {
        LineSlave s;
        s.station = static_cast<std::uint16_t>(0x1001 + i);
        const auto position = static_cast<std::uint16_t>(-static_cast<int>(i));  // auto-increment address
        const auto assigned = datagram(Command::apwr, position, reg::station_address, le16(s.station));
        if (!assigned || assigned->working_counter != 1) return false;
        const auto eeprom = read16(s.station, reg::eeprom_control);
        const auto dl = read16(s.station, reg::dl_status);
        if (!eeprom || !dl) return false;
        s.eeprom_status = *eeprom;
        s.dl_status = *dl;
        // The header (64 words), then the categories up to the end marker, 2 KiB at a time.
        auto bytes = read_sii(s.station, 0, 128);
        if (!bytes) return false;
        for (std::size_t at = 128; at < 64 * 1024;) {
            // Walk the category headers read so far; read on while no end marker was seen.
            std::size_t walk = 128;
            bool ended = false;
            while (walk + 4 <= bytes->size()) {
                const std::uint16_t type = u16(*bytes, walk);
                if (type == 0xFFFF) {
                    ended = true;
                    break;
                }
                walk += 4 + 2u * u16(*bytes, walk + 2);
            }
            if (ended) break;
            const auto more = read_sii(s.station, static_cast<std::uint32_t>(at / 2), 2048);
            if (!more) return false;
            bytes->insert(bytes->end(), more->begin(), more->end());
            at += 2048;
        }
        s.sii = std::move(*bytes);
        s.decoded = sii::decode_image(s.sii);
        const sii::Header& h = s.decoded.image.header;
        s.mailbox = h.standard_receive_size != 0 && h.standard_send_size != 0;
        s.coe = s.mailbox && (h.mailbox_protocols & sii::mailbox_protocol::coe);
        slaves.push_back(std::move(s));
    }
    return true;
}

StateResult LineMaster::state_of(const LineSlave& slave) {
    StateResult r;
    if (const auto b = read(slave.station, reg::al_status, 6)) {
        r.al_status = u16(*b, 0);
        r.al_status_code = u16(*b, 4);
    }
    return r;
}

StateResult LineMaster::request_state(LineSlave& slave, std::uint8_t state, int polls) {
    write16(slave.station, reg::al_control, state);
    StateResult r;
    for (int i = 0; i < polls; ++i) {
        if (output_image_bytes_ + input_image_bytes_ > 0 && state >= 4) cycle(std::vector<std::uint8_t>(output_image_bytes_, 0));
        r = state_of(slave);
        if (r.state() == state || r.error()) break;
    }
    return r;
}

StateResult LineMaster::acknowledge_error(LineSlave& slave, std::uint8_t state) {
    write16(slave.station, reg::al_control, static_cast<std::uint16_t>(state | ethercat::al_error_bit));
    StateResult r;
    for (int i = 0; i < 50; ++i) {
        if (output_image_bytes_ + input_image_bytes_ > 0) cycle(std::vector<std::uint8_t>(output_image_bytes_, 0));
        r = state_of(slave);
        if (!r.error()) break;
    }
    return r;
}

bool LineMaster::setup_mailbox(LineSlave& slave) {
    if (!slave.mailbox) return true;
    const sii::Header& h = slave.decoded.image.header;
    slave.mbx_out_start = h.standard_receive_offset;
    slave.mbx_out_size = h.standard_receive_size;
    slave.mbx_in_start = h.standard_send_offset;
    slave.mbx_in_size = h.standard_send_size;
    // The SII's SyncM category gives control bytes; a mailbox SM is 1-buffered, write (0x26) for
    // SM0 and read (0x22) for SM1 as ETG.2010's defaults.
    std::uint8_t out_control = 0x26, in_control = 0x22;
    if (const sii::SyncManagers* sms = slave.decoded.image.sync_managers(); sms && sms->items.size() >= 2) {
        out_control = sms->items[0].control;
        in_control = sms->items[1].control;
    }
    std::vector<std::uint8_t> sm(16, 0);
    put16(sm, 0, slave.mbx_out_start);
    put16(sm, 2, slave.mbx_out_size);
    sm[4] = out_control;
    sm[6] = 1;
    put16(sm, 8, slave.mbx_in_start);
    put16(sm, 10, slave.mbx_in_size);
    sm[12] = in_control;
    sm[14] = 1;
    return write(slave.station, reg::sm0, sm);
}

std::optional<std::vector<std::uint8_t>> LineMaster::mailbox_receive(LineSlave& slave, int polls) {
    for (int i = 0; i < polls; ++i) {
        const auto status = read(slave.station, static_cast<std::uint16_t>(reg::sm(1) + reg::sm_status), 1);
        if (!status) return std::nullopt;
        if (!((*status)[0] & reg::sm_status_mailbox_full)) continue;  // SM1 not full yet
        auto answer = read(slave.station, slave.mbx_in_start, slave.mbx_in_size);
        if (!answer || answer->size() < 6) return std::nullopt;
        const std::size_t length = u16(*answer, 0);
        if (length + 6 > answer->size()) return std::nullopt;
        answer->resize(6 + length);
        // An emergency (CoE service 1) is not the answer; wait on.
        if ((answer->at(5) & 0x0F) == coe && length >= 2 && coe_service(*answer) == 1) continue;
        return answer;
    }
    return std::nullopt;
}

std::optional<std::vector<std::uint8_t>> LineMaster::mailbox_exchange(LineSlave& slave, std::uint8_t type,
                                                                      const std::vector<std::uint8_t>& payload, int polls) {
    if (payload.size() + 6 > slave.mbx_out_size) return std::nullopt;
    slave.mailbox_counter = static_cast<std::uint8_t>(slave.mailbox_counter % 7 + 1);  // 1..7, ETG.1000.4 5.6
    std::vector<std::uint8_t> buffer(slave.mbx_out_size, 0);
    put16(buffer, 0, static_cast<std::uint16_t>(payload.size()));
    buffer[5] = static_cast<std::uint8_t>(type | (slave.mailbox_counter << 4));
    std::copy(payload.begin(), payload.end(), buffer.begin() + 6);
    bool written = false;
    for (int i = 0; i < polls && !written; ++i) written = write(slave.station, slave.mbx_out_start, buffer);  // 0: SM0 still full
    if (!written) return std::nullopt;
    return mailbox_receive(slave, polls);
}

SdoUpload LineMaster::upload(LineSlave& slave, std::uint16_t index, std::uint8_t subindex, bool complete_access) {
    SdoUpload r;
    const auto command = static_cast<std::uint8_t>(cmd::byte_of(cmd::initiate_upload) | (complete_access ? cmd::complete_access : 0));
    const auto answer = mailbox_exchange(slave, coe, sdo_request_frame(command, index, subindex));
    if (!answer) return {{}, 0, "no answer"};
    const std::vector<std::uint8_t>& a = *answer;
    if ((a[5] & 0x0F) == error) return {{}, 0, "mailbox error"};
    if (a.size() < 16) return {{}, 0, "answer too short"};
    if (const auto code = abort_code(a)) return {{}, *code, ""};
    if (coe_service(a) != sdo_response || cmd::specifier(a[8]) != cmd::response_initiate_upload) return {{}, 0, "not an upload response"};
    if (a[8] & cmd::expedited) {  // 4 - n bytes
        const std::size_t size = (a[8] & cmd::size_indicated) ? 4 - ((a[8] >> 2) & 0x03) : 4;
        r.data.assign(a.begin() + 12, a.begin() + 12 + static_cast<std::ptrdiff_t>(size));
        return r;
    }
    const std::uint32_t total = u32(a, 12);
    const std::size_t first = std::min<std::size_t>(a.size() - 16, total);
    r.data.assign(a.begin() + 16, a.begin() + 16 + static_cast<std::ptrdiff_t>(first));
    std::uint8_t toggle = 0;
    for (int segments = 0; r.data.size() < total; ++segments) {
        if (segments > 10000) return {{}, 0, "too many segments"};
        const auto s = mailbox_exchange(slave, coe,
                                        {0x00, static_cast<std::uint8_t>(sdo_request << 4),
                                         static_cast<std::uint8_t>(cmd::byte_of(cmd::upload_segment) | toggle), 0, 0, 0, 0, 0, 0, 0});
        if (!s || s->size() < 16) return {{}, 0, "no segment"};
        if (const auto code = abort_code(*s)) return {{}, *code, ""};
        if ((s->at(8) & cmd::toggle) != toggle) return {{}, 0, "toggle bit out of step"};
        std::size_t n = s->size() - 9;
        if (n == 7) n -= (s->at(8) >> 1) & 0x07;
        r.data.insert(r.data.end(), s->begin() + 9, s->begin() + 9 + static_cast<std::ptrdiff_t>(n));
        if (s->at(8) & 0x01) break;
        toggle ^= cmd::toggle;
    }
    if (r.data.size() != total) r.failure = "size " + std::to_string(r.data.size()) + " of " + std::to_string(total);
    return r;
}

std::uint32_t LineMaster::download(LineSlave& slave, std::uint16_t index, std::uint8_t subindex, const std::vector<std::uint8_t>& data,
                                   bool complete_access) {
    const std::uint8_t ca = complete_access ? cmd::complete_access : 0;
    std::vector<std::uint8_t> request;
    if (!data.empty() && data.size() <= 4) {
        const auto unused = static_cast<std::uint8_t>((4 - data.size()) << 2);  // bytes of the 4 not used
        const auto command =
            static_cast<std::uint8_t>(cmd::byte_of(cmd::initiate_download) | cmd::expedited | cmd::size_indicated | ca | unused);
        request = sdo_request_frame(command, index, subindex);
        std::copy(data.begin(), data.end(), request.begin() + 6);
    } else {
        request = sdo_request_frame(static_cast<std::uint8_t>(cmd::byte_of(cmd::initiate_download) | cmd::size_indicated | ca), index,
                                    subindex);
        put32(request, 6, static_cast<std::uint32_t>(data.size()));
        if (data.size() + 16 > slave.mbx_out_size) return 0xFFFFFFFF;  // segmented download: not needed by the tests
        request.insert(request.end(), data.begin(), data.end());
    }
    const auto a = mailbox_exchange(slave, coe, request);
    if (!a || a->size() < 16) return 0xFFFFFFFF;
    if (const auto code = abort_code(*a)) return *code;
    return coe_service(*a) == sdo_response && a->at(8) == cmd::byte_of(cmd::response_initiate_download) ? 0 : 0xFFFFFFFE;
}

std::optional<std::vector<std::uint16_t>> LineMaster::od_list(LineSlave& slave, std::string& failure) {
    const std::vector<std::uint8_t> request{0x00, static_cast<std::uint8_t>(sdo_information << 4), op::get_od_list, 0x00, 0x00, 0x00,
                                            0x01, 0x00};
    auto answer = mailbox_exchange(slave, coe, request);
    std::vector<std::uint16_t> indices;
    bool first = true;
    for (int fragments = 0; fragments < 1000; ++fragments) {
        if (!answer) {
            failure = "no answer";
            return std::nullopt;
        }
        const std::vector<std::uint8_t>& a = *answer;
        if ((a[5] & 0x0F) == error) {
            failure = "mailbox error " + std::to_string(a.size() >= 10 ? u16(a, 8) : 0);
            return std::nullopt;
        }
        if (a.size() < 12 || coe_service(a) != sdo_information || (a[8] & ~op::incomplete) != op::od_list_response) {
            const bool info_error = a.size() >= 16 && (a[8] & ~op::incomplete) == op::error;
            failure = info_error ? "SDO Information error " + std::to_string(u32(a, 12)) : "not an OD list response";
            return std::nullopt;
        }
        std::size_t at = 12;
        if (first) at += 2;  // the list type
        first = false;
        for (; at + 2 <= a.size(); at += 2) indices.push_back(u16(a, at));
        if (!(a[8] & op::incomplete)) return indices;  // no more fragments
        answer = mailbox_receive(slave);
    }
    failure = "too many fragments";
    return std::nullopt;
}

std::optional<ObjectDescription> LineMaster::object_description(LineSlave& slave, std::uint16_t index, std::string& failure) {
    const std::vector<std::uint8_t> request{0x00, static_cast<std::uint8_t>(sdo_information << 4), op::get_object_description, 0x00, 0x00,
                                            0x00,
                                            static_cast<std::uint8_t>(index), static_cast<std::uint8_t>(index >> 8)};
    auto answer = mailbox_exchange(slave, coe, request);
    if (!answer || answer->size() < 18 || coe_service(*answer) != sdo_information ||
        (answer->at(8) & ~op::incomplete) != op::object_description_response) {
        failure = "no object description";
        return std::nullopt;
    }
    const std::vector<std::uint8_t>& a = *answer;
    ObjectDescription d;
    d.index = u16(a, 12);
    d.data_type = u16(a, 14);
    d.max_subindex = a[16];
    d.object_code = a[17];
    d.name.assign(a.begin() + 18, a.end());
    // A name longer than one mailbox comes in further fragments.
    for (int fragments = 0; (answer->at(8) & op::incomplete) && fragments < 100; ++fragments) {
        answer = mailbox_receive(slave);
        if (!answer || answer->size() < 12) break;
        d.name.append(answer->begin() + 12, answer->end());
    }
    return d;
}

std::uint32_t LineMaster::sm_bits_over_coe(LineSlave& slave, unsigned sm, bool& ok) {
    const auto count = upload(slave, static_cast<std::uint16_t>(0x1C10 + sm), 0);
    if (!count.ok() || count.data.empty()) {
        ok = false;
        return 0;
    }
    std::uint32_t bits = 0;
    for (unsigned i = 1; i <= count.data[0]; ++i) {
        const auto pdo = upload(slave, static_cast<std::uint16_t>(0x1C10 + sm), static_cast<std::uint8_t>(i));
        if (!pdo.ok() || pdo.data.size() < 2) {
            ok = false;
            return 0;
        }
        const auto pdo_index = static_cast<std::uint16_t>(pdo.data[0] | (pdo.data[1] << 8));
        if (pdo_index == 0) continue;  // an empty slot of the assignment, skipped as SOEM does
        const auto entries = upload(slave, pdo_index, 0);
        if (!entries.ok() || entries.data.empty()) {
            ok = false;
            return 0;
        }
        for (unsigned e = 1; e <= entries.data[0]; ++e) {
            const auto entry = upload(slave, pdo_index, static_cast<std::uint8_t>(e));
            if (!entry.ok() || entry.data.empty()) {
                ok = false;
                return 0;
            }
            bits += entry.data[0];  // the low byte of a mapping entry is its bit length
        }
    }
    return bits;
}

std::uint32_t LineMaster::sm_bits_from_sii(const LineSlave& slave, unsigned sm) const {
    std::uint32_t bits = 0;
    for (const std::uint16_t category : {sii::category::rx_pdo, sii::category::tx_pdo})
        if (const sii::Pdos* pdos = slave.decoded.image.pdos(category))
            for (const sii::PdoRecord& p : pdos->items)
                if (p.sync_manager == sm)
                    for (const sii::PdoEntryRecord& e : p.entries) bits += e.bit_len;
    return bits;
}

std::uint16_t LineMaster::setup_process_data() {
    // Sizes: per SM, over CoE where the device has it (as SOEM's ecx_readPDOmap), else from the
    // SII; a CoE mapping of no bits at all falls back to the SII too, as SOEM does.
    for (LineSlave& s : slaves) {
        s.sm_types.clear();
        s.sm_bits.clear();
        bool over_coe = false;
        if (s.coe) {
            const auto count = upload(s, 0x1C00, 0);
            if (count.ok() && !count.data.empty() && count.data[0] <= 32) {
                over_coe = true;
                for (unsigned n = 1; n <= count.data[0]; ++n) {
                    const auto type = upload(s, 0x1C00, static_cast<std::uint8_t>(n));
                    if (!type.ok() || type.data.empty()) {
                        over_coe = false;
                        break;
                    }
                    if (type.data[0] == 3 || type.data[0] == 4) s.sm_types[n - 1] = type.data[0];
                }
                std::uint32_t total = 0;
                for (const auto& [sm, type] : s.sm_types) {
                    bool ok = true;
                    s.sm_bits[sm] = sm_bits_over_coe(s, sm, ok);
                    if (!ok) s.sm_bits[sm] = sm_bits_from_sii(s, sm);
                    total += s.sm_bits[sm];
                }
                if (over_coe && total == 0) s.sm_bits.clear();
            }
        }
        if (!over_coe) {
            s.sm_types.clear();
            if (const sii::SyncManagers* sms = s.decoded.image.sync_managers())
                for (std::size_t n = 0; n < sms->items.size(); ++n)
                    if (sms->items[n].type == 3 || sms->items[n].type == 4) s.sm_types[static_cast<unsigned>(n)] = sms->items[n].type;
        }
        if (s.sm_bits.empty())
            for (const auto& [sm, type] : s.sm_types) s.sm_bits[sm] = sm_bits_from_sii(s, sm);
        // Where the SII has no record for an SM, its start address is unknown: the master maps
        // nothing through it (the firmware, whose expectations come from the same SII, expects
        // nothing there either).
        const sii::SyncManagers* records = s.decoded.image.sync_managers();
        for (auto& [sm, bits] : s.sm_bits)
            if (!records || sm >= records->items.size()) bits = 0;
        s.output_bits = s.input_bits = 0;
        for (const auto& [sm, type] : s.sm_types) (type == 3 ? s.output_bits : s.input_bits) += (s.sm_bits[sm] + 7) / 8 * 8;
    }
    // The logical image: every slave's outputs, then every slave's inputs.
    std::uint32_t at = 0;
    for (LineSlave& s : slaves) {
        s.output_offset = at;
        at += s.output_bytes();
    }
    output_image_bytes_ = at;
    for (LineSlave& s : slaves) {
        s.input_offset = at;
        at += s.input_bytes();
    }
    input_image_bytes_ = at - output_image_bytes_;

    std::uint16_t expected = 0;
    for (LineSlave& s : slaves) {
        const sii::SyncManagers* sms = s.decoded.image.sync_managers();
        std::uint32_t out_at = s.output_offset, in_at = s.input_offset;
        unsigned fmmu = 0;
        bool reads = false, writes = false;
        for (const auto& [sm, type] : s.sm_types) {
            const std::uint16_t bytes = static_cast<std::uint16_t>((s.sm_bits[sm] + 7) / 8);
            const sii::SyncManagerRecord* record = sms && sm < sms->items.size() ? &sms->items[sm] : nullptr;
            if (!record) continue;  // unknown start address: nothing mapped (above)
            std::vector<std::uint8_t> config(8, 0);
            put16(config, 0, record->start_address);
            put16(config, 2, bytes);
            config[4] = record->control;
            config[6] = bytes > 0 ? 1 : 0;
            write(s.station, reg::sm(sm), config);
            if (bytes == 0) continue;
            std::vector<std::uint8_t> f(16, 0);
            const std::uint32_t logical = type == 3 ? out_at : in_at;
            put32(f, reg::fmmu_logical_start, logical);
            put16(f, reg::fmmu_length, bytes);
            f[reg::fmmu_logical_stop_bit] = 7;
            put16(f, reg::fmmu_physical_start, record->start_address);
            f[reg::fmmu_type] = type == 3 ? 2 : 1;
            f[reg::fmmu_activate] = 1;
            write(s.station, reg::fmmu(fmmu++), f);
            (type == 3 ? out_at : in_at) += bytes;
            (type == 3 ? writes : reads) = true;
        }
        expected = static_cast<std::uint16_t>(expected + (writes ? 2 : 0) + (reads ? 1 : 0));
    }
    return expected;
}

std::optional<Answer> LineMaster::cycle(const std::vector<std::uint8_t>& outputs, std::uint64_t ns) {
    std::vector<std::uint8_t> image(output_image_bytes_ + input_image_bytes_, 0);
    std::copy_n(outputs.begin(), std::min<std::size_t>(outputs.size(), output_image_bytes_), image.begin());
    const std::uint64_t gap = frame_gap_ns;
    frame_gap_ns = ns;
    auto a = datagram(Command::lrw, 0, 0, std::move(image));
    frame_gap_ns = gap;
    if (!a) return std::nullopt;
    a->data.erase(a->data.begin(), a->data.begin() + output_image_bytes_);
    return a;
}

bool LineMaster::to_op(std::size_t* refused, StateResult* refusal) {
    auto refuse = [&](std::size_t i, const StateResult& r) {
        if (refused) *refused = i;
        if (refusal) *refusal = r;
        return false;
    };
    for (std::size_t i = 0; i < slaves.size(); ++i) {
        if (!setup_mailbox(slaves[i])) return refuse(i, state_of(slaves[i]));
        const StateResult r = request_state(slaves[i], 2);
        if (r.state() != 2 || r.error()) return refuse(i, r);
    }
    setup_process_data();
    for (std::size_t i = 0; i < slaves.size(); ++i) {
        const StateResult r = request_state(slaves[i], 4);
        if (r.state() != 4 || r.error()) return refuse(i, r);
    }
    for (int i = 0; i < 3; ++i) cycle(std::vector<std::uint8_t>(output_image_bytes_, 0));
    for (std::size_t i = 0; i < slaves.size(); ++i) {
        const StateResult r = request_state(slaves[i], 8);
        if (r.state() != 8 || r.error()) return refuse(i, r);
    }
    return true;
}

}  // namespace esi::test
