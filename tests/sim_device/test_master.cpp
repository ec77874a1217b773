#include "sim_device/test_master.hpp"

#include <algorithm>

namespace esi::sim::test_bench {

namespace {

std::uint32_t u32(const std::vector<std::uint8_t>& b, std::size_t at) {
    return static_cast<std::uint32_t>(b[at]) | (static_cast<std::uint32_t>(b[at + 1]) << 8) |
           (static_cast<std::uint32_t>(b[at + 2]) << 16) | (static_cast<std::uint32_t>(b[at + 3]) << 24);
}

std::vector<std::uint8_t> sdo(std::uint8_t command, std::uint16_t index, std::uint8_t subindex) {
    return {0x00, 0x20, command, static_cast<std::uint8_t>(index), static_cast<std::uint8_t>(index >> 8), subindex, 0, 0, 0, 0};
}

}  // namespace

TestMaster::TestMaster(FakeEsc& esc, esc::SlaveStack& slave, const EtherCATInfo& info, const Device& device)
    : esc_(esc), slave_(slave), image_(sii::build_image(info, device)) {
    poll();
}

void TestMaster::poll(int times) {
    for (int i = 0; i < times; ++i) slave_.poll(esc_);
}

std::uint16_t TestMaster::request_state(std::uint16_t control) {
    esc_.master_write_u16(0x0120, control);
    poll(2);
    return al_status();
}

void TestMaster::configure_mailbox() {
    const auto& h = image_.image.header;
    std::uint8_t out_control = 0x26, in_control = 0x22;
    if (const sii::SyncManagers* sms = sii_sms(); sms && sms->items.size() >= 2) {
        out_control = sms->items[0].control;
        in_control = sms->items[1].control;
    }
    esc_.configure_sm(0, h.standard_receive_offset, h.standard_receive_size, out_control, true);
    esc_.configure_sm(1, h.standard_send_offset, h.standard_send_size, in_control, true);
}

void TestMaster::configure_process_sm(unsigned n, std::uint16_t length) {
    const sii::SyncManagerRecord& r = sii_sms()->items.at(n);
    esc_.configure_sm(n, r.start_address, length, r.control, length > 0);
}

bool TestMaster::to_preop() {
    configure_mailbox();
    return (request_state(2) & 0x1F) == 2;
}

void TestMaster::write_request(std::uint8_t type, const std::vector<std::uint8_t>& payload, std::optional<std::uint8_t> counter) {
    const auto& h = image_.image.header;
    if (!counter) {
        counter_ = static_cast<std::uint8_t>(counter_ % 7 + 1);
        counter = counter_;
    }
    std::vector<std::uint8_t> buffer(h.standard_receive_size, 0);
    const std::size_t n = std::min<std::size_t>(payload.size(), buffer.size() - 6);
    buffer[0] = static_cast<std::uint8_t>(n);
    buffer[1] = static_cast<std::uint8_t>(n >> 8);
    buffer[5] = static_cast<std::uint8_t>(type | (*counter << 4));
    std::copy_n(payload.begin(), n, buffer.begin() + 6);
    esc_.master_write(h.standard_receive_offset, buffer);
}

std::optional<std::vector<std::uint8_t>> TestMaster::read_answer() {
    const auto& h = image_.image.header;
    for (int i = 0; i < 8; ++i) {
        if (esc_.mailbox_full(1)) return esc_.master_read(h.standard_send_offset, h.standard_send_size);
        poll();
    }
    return std::nullopt;
}

std::optional<std::vector<std::uint8_t>> TestMaster::exchange(std::uint8_t type, const std::vector<std::uint8_t>& payload,
                                                              std::optional<std::uint8_t> counter) {
    write_request(type, payload, counter);
    poll();
    return read_answer();
}

SdoResult TestMaster::upload(std::uint16_t index, std::uint8_t subindex, bool complete) {
    SdoResult result;
    auto answer = exchange(3, sdo(complete ? 0x50 : 0x40, index, subindex));
    if (!answer || answer->size() < 16) return {0xFFFFFFFF, {}};
    const std::vector<std::uint8_t>& a = *answer;
    const std::uint8_t command = a[8];
    if (command == 0x80) return {u32(a, 12), {}};
    if (command & 0x02) {  // expedited
        const std::size_t size = 4 - ((command >> 2) & 0x03);
        result.data.assign(a.begin() + 12, a.begin() + 12 + static_cast<std::ptrdiff_t>(size));
        return result;
    }
    const std::uint32_t total = u32(a, 12);
    const std::size_t length = a[0] | (a[1] << 8);
    const std::size_t first = std::min<std::size_t>(length - 10, total);
    result.data.assign(a.begin() + 16, a.begin() + 16 + static_cast<std::ptrdiff_t>(first));
    std::uint8_t toggle = 0;
    while (result.data.size() < total) {
        auto segment = exchange(3, {0x00, 0x20, static_cast<std::uint8_t>(0x60 | toggle), 0, 0, 0, 0, 0, 0, 0});
        if (!segment) return {0xFFFFFFFF, {}};
        const std::vector<std::uint8_t>& s = *segment;
        if (s[8] == 0x80) return {u32(s, 12), {}};
        if ((s[8] & 0x10) != toggle) return {0xFFFFFFFE, {}};
        std::size_t n = (s[0] | (s[1] << 8)) - 3u;
        if ((s[8] & 0x01) && n == 7) n -= (s[8] >> 1) & 0x07;
        result.data.insert(result.data.end(), s.begin() + 9, s.begin() + 9 + static_cast<std::ptrdiff_t>(n));
        if (s[8] & 0x01) break;
        toggle ^= 0x10;
    }
    if (result.data.size() != total) result.abort = 0xFFFFFFFD;
    return result;
}

std::uint32_t TestMaster::download(std::uint16_t index, std::uint8_t subindex, const std::vector<std::uint8_t>& data, bool complete) {
    const std::uint8_t ca = complete ? 0x10 : 0;
    if (data.size() <= 4 && !data.empty()) {
        std::vector<std::uint8_t> r = sdo(static_cast<std::uint8_t>(0x23 | ca | ((4 - data.size()) << 2)), index, subindex);
        std::copy(data.begin(), data.end(), r.begin() + 6);
        auto a = exchange(3, r);
        if (!a) return 0xFFFFFFFF;
        return (*a)[8] == 0x80 ? u32(*a, 12) : ((*a)[8] == 0x60 ? 0 : 0xFFFFFFFE);
    }
    const std::size_t room = mailbox_out_size() - 16u;
    std::vector<std::uint8_t> r = sdo(static_cast<std::uint8_t>(0x21 | ca), index, subindex);
    const auto size = static_cast<std::uint32_t>(data.size());
    for (int i = 0; i < 4; ++i) r[6 + i] = static_cast<std::uint8_t>(size >> (8 * i));
    const std::size_t first = std::min(room, data.size());
    r.insert(r.end(), data.begin(), data.begin() + static_cast<std::ptrdiff_t>(first));
    auto a = exchange(3, r);
    if (!a) return 0xFFFFFFFF;
    if ((*a)[8] == 0x80) return u32(*a, 12);
    std::size_t sent = first;
    std::uint8_t toggle = 0;
    while (sent < data.size()) {
        const std::size_t n = std::min<std::size_t>(data.size() - sent, mailbox_out_size() - 9u);
        const bool last = sent + n == data.size();
        std::vector<std::uint8_t> s{0x00, 0x20, static_cast<std::uint8_t>(toggle | (last ? 1 : 0))};
        s.insert(s.end(), data.begin() + static_cast<std::ptrdiff_t>(sent), data.begin() + static_cast<std::ptrdiff_t>(sent + n));
        if (n < 7) {
            s[2] |= static_cast<std::uint8_t>((7 - n) << 1);
            s.resize(10, 0);
        }
        auto sa = exchange(3, s);
        if (!sa) return 0xFFFFFFFF;
        if ((*sa)[8] == 0x80) return u32(*sa, 12);
        sent += n;
        toggle ^= 0x10;
    }
    return 0;
}

std::uint32_t TestMaster::download_segmented(std::uint16_t index, std::uint8_t subindex, const std::vector<std::uint8_t>& data) {
    std::vector<std::uint8_t> r = sdo(0x21, index, subindex);
    const auto size = static_cast<std::uint32_t>(data.size());
    for (int i = 0; i < 4; ++i) r[6 + i] = static_cast<std::uint8_t>(size >> (8 * i));
    auto a = exchange(3, r);
    if (!a) return 0xFFFFFFFF;
    if ((*a)[8] == 0x80) return u32(*a, 12);
    std::size_t sent = 0;
    std::uint8_t toggle = 0;
    while (sent < data.size()) {
        const std::size_t n = std::min<std::size_t>(data.size() - sent, 7);
        const bool last = sent + n == data.size();
        std::vector<std::uint8_t> s{0x00, 0x20, static_cast<std::uint8_t>(toggle | (last ? 1 : 0) | ((7 - n) << 1))};
        s.insert(s.end(), data.begin() + static_cast<std::ptrdiff_t>(sent), data.begin() + static_cast<std::ptrdiff_t>(sent + n));
        s.resize(10, 0);
        auto sa = exchange(3, s);
        if (!sa) return 0xFFFFFFFF;
        if ((*sa)[8] == 0x80) return u32(*sa, 12);
        sent += n;
        toggle ^= 0x10;
    }
    return 0;
}

}  // namespace esi::sim::test_bench
