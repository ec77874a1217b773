// Fuzz target: the model slave's mailbox and CoE server (esi-sim). The input is a script of
// master actions on a slave made from the bundled sample device (with complete access and SDO
// Information switched on, so every service is reachable): whole mailbox buffers written into
// the write mailbox, AL control writes, repeat requests and SyncManager rewrites, the slave polled
// after each. Any input must leave the slave answering; never a crash, a hang, an out-of-bounds
// access or an allocation that grows with a length field instead of the input.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <span>
#include <vector>

#include "esi/esc/pdi.hpp"
#include "esi/sim/model_slave.hpp"
#include "esi/xml/reader.hpp"

namespace {

const esi::EsiDocument& coe_fuzz_document() {
    static const esi::EsiDocument document = [] {
        esi::ReadResult read = esi::read_esi_file(ESI_FUZZ_REFERENCE_ESI);
        if (!read.document || read.document->infos.empty() || read.document->infos.front().devices.empty()) std::abort();
        esi::EsiDocument d = std::move(*read.document);
        esi::Device& device = d.infos.front().devices.front();
        if (!device.mailbox || !device.mailbox->coe) std::abort();
        device.mailbox->coe->complete_access = true;
        device.mailbox->coe->sdo_info = true;
        return d;
    }();
    return document;
}

// Just enough of an ESC for the stack: memory, the AL control event and 1-buffer mailboxes.
class CoeFuzzEsc final : public esi::esc::Pdi {
public:
    CoeFuzzEsc() : memory_(0x10000, 0) {}
    void read(std::uint16_t address, std::span<std::uint8_t> out) override {
        for (std::size_t i = 0; i < out.size(); ++i) {
            const std::size_t a = address + i;
            out[i] = a <= 0xFFFF ? memory_[a] : 0;
            if (a == 0x0120) memory_[0x0220] &= 0xFE;
            if (a <= 0xFFFF) after(a, false);
        }
    }
    void write(std::uint16_t address, std::span<const std::uint8_t> in) override {
        for (std::size_t i = 0; i < in.size() && address + i <= 0xFFFF; ++i) {
            const std::size_t a = address + i;
            if ((a >= 0x0800 && a < 0x0880 && (a & 7) != 7) || a == 0x0120 || a == 0x0121) continue;
            memory_[a] = in[i];
            after(a, true);
        }
    }
    [[nodiscard]] std::uint32_t al_event() const override { return memory_[0x0220]; }

    void master_write(std::uint16_t address, std::span<const std::uint8_t> in) {
        for (std::size_t i = 0; i < in.size() && address + i <= 0xFFFF; ++i) {
            const std::size_t a = address + i;
            memory_[a] = in[i];
            if (a == 0x0120 || a == 0x0121) memory_[0x0220] |= 1;
            for (unsigned n = 0; n < 8; ++n)
                if (mailbox(n, true) && a == end(n)) memory_[sm(n) + 5] |= 0x08;
        }
    }
    void master_drain(unsigned n) {
        if (memory_[sm(n) + 5] & 0x08) memory_[sm(n) + 5] &= 0xF7;
    }
    [[nodiscard]] std::uint16_t u16(std::size_t a) const { return static_cast<std::uint16_t>(memory_[a] | (memory_[a + 1] << 8)); }
    static std::size_t sm(unsigned n) { return 0x0800 + 8 * n; }

private:
    [[nodiscard]] std::size_t end(unsigned n) const { return u16(sm(n)) + u16(sm(n) + 2) - 1u; }
    [[nodiscard]] bool mailbox(unsigned n, bool master_writes) const {
        const std::uint8_t c = memory_[sm(n) + 4];
        return (memory_[sm(n) + 6] & 1) && (c & 3) == 2 && (((c >> 2) & 3) == 1) == master_writes && u16(sm(n) + 2) > 0;
    }
    void after(std::size_t a, bool write) {
        for (unsigned n = 0; n < 8; ++n) {
            if (a != end(n)) continue;
            if (write && mailbox(n, false)) memory_[sm(n) + 5] |= 0x08;
            if (!write && mailbox(n, true)) memory_[sm(n) + 5] &= 0xF7;
        }
    }
    std::vector<std::uint8_t> memory_;
};

void coe_fuzz_configure_sm(CoeFuzzEsc& esc, unsigned n, const esi::SyncManager& s) {
    const std::uint16_t start = static_cast<std::uint16_t>(s.start_address.value_or(0));
    const std::uint16_t length = static_cast<std::uint16_t>(s.default_size.value_or(0));
    const std::array<std::uint8_t, 7> r{static_cast<std::uint8_t>(start), static_cast<std::uint8_t>(start >> 8),
                                        static_cast<std::uint8_t>(length), static_cast<std::uint8_t>(length >> 8),
                                        static_cast<std::uint8_t>(s.control_byte.value_or(0)), 0, 1};
    esc.master_write(static_cast<std::uint16_t>(CoeFuzzEsc::sm(n)), r);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const esi::EsiDocument& document = coe_fuzz_document();
    const esi::EtherCATInfo& info = document.infos.front();
    const esi::Device& device = info.devices.front();
    esi::Diagnostics diagnostics;
    std::unique_ptr<esi::esc::SlaveStack> slave = esi::sim::make_model_slave(info, device, {.echo = (size & 1) != 0}, diagnostics);
    if (!slave) std::abort();
    CoeFuzzEsc esc;
    for (unsigned n = 0; n < device.sms.size() && n < 4; ++n) coe_fuzz_configure_sm(esc, n, device.sms[n]);
    const std::array<std::uint8_t, 2> preop{2, 0};
    esc.master_write(0x0120, preop);
    slave->poll(esc);

    const std::uint16_t out_start = esc.u16(CoeFuzzEsc::sm(0));
    const std::uint16_t out_length = esc.u16(CoeFuzzEsc::sm(0) + 2);
    std::span<const std::uint8_t> script(data, size);
    while (!script.empty()) {
        const std::uint8_t action = script[0];
        script = script.subspan(1);
        switch (action % 4) {
            case 0: {  // a mailbox request: the next bytes, as many as the mailbox holds
                std::vector<std::uint8_t> buffer(out_length, 0);
                const std::size_t n = std::min<std::size_t>(buffer.size(), script.size());
                std::copy_n(script.begin(), n, buffer.begin());
                script = script.subspan(n);
                esc.master_write(out_start, buffer);
                break;
            }
            case 1: {  // AL control
                if (script.size() < 2) return 0;
                esc.master_write(0x0120, script.first(2));
                script = script.subspan(2);
                break;
            }
            case 2: {  // toggle SM1's repeat request
                std::array<std::uint8_t, 1> activate{static_cast<std::uint8_t>(1 | ((action >> 2) & 2))};
                esc.master_write(static_cast<std::uint16_t>(CoeFuzzEsc::sm(1) + 6), activate);
                break;
            }
            default: {  // rewrite one byte of an SM register or of the DC activation
                if (script.size() < 2) return 0;
                const std::uint16_t address = script[0] < 0x80 ? static_cast<std::uint16_t>(0x0800 + (script[0] & 0x1F))
                                                               : static_cast<std::uint16_t>(0x0980 + (script[0] & 0x3F));
                esc.master_write(address, script.subspan(1, 1));
                script = script.subspan(2);
                break;
            }
        }
        slave->poll(esc);
        esc.master_drain(1);
        slave->poll(esc);
    }
    return 0;
}
