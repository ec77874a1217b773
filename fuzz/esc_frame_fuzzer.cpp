// Fuzz target: the emulated ESC's datagram processor and, through it, the model slave's mailbox
// server. The input is a sequence of frames (2-byte little-endian length, then the EtherCAT
// payload from its header on) passed through a line of two slaves of the bundled sample, whose
// mailbox SyncManagers a fixed prelude has set up in PREOP, so that fuzzed mailbox writes reach
// the CoE server. Any input must leave the frames their size and never crash, hang, read out of
// bounds or grow memory with a length field.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <vector>

#include "esi/sim/line.hpp"
#include "esi/sim/model_slave.hpp"
#include "esi/sim/slave_setup.hpp"
#include "esi/xml/reader.hpp"

namespace {

const esi::EsiDocument& reference_document() {
    static const esi::EsiDocument document = [] {
        esi::ReadResult read = esi::read_esi_file(ESI_FUZZ_REFERENCE_ESI);
        if (!read.document || read.document->infos.empty() || read.document->infos.front().devices.empty()) std::abort();
        return std::move(*read.document);
    }();
    return document;
}

// One datagram in a payload of its own (ETG.1000.4 §5).
std::vector<std::uint8_t> frame(std::uint8_t command, std::uint16_t adp, std::uint16_t ado, std::vector<std::uint8_t> data) {
    std::vector<std::uint8_t> out(2 + 10 + data.size() + 2, 0);
    const std::size_t length = out.size() - 2;
    out[0] = static_cast<std::uint8_t>(length);
    out[1] = static_cast<std::uint8_t>(0x10 | (length >> 8));
    out[2] = command;
    out[4] = static_cast<std::uint8_t>(adp);
    out[5] = static_cast<std::uint8_t>(adp >> 8);
    out[6] = static_cast<std::uint8_t>(ado);
    out[7] = static_cast<std::uint8_t>(ado >> 8);
    out[8] = static_cast<std::uint8_t>(data.size());
    out[9] = static_cast<std::uint8_t>(data.size() >> 8);
    std::copy(data.begin(), data.end(), out.begin() + 12);
    return out;
}

std::unique_ptr<esi::sim::Line> prepared_line() {
    const esi::EsiDocument& document = reference_document();
    const esi::EtherCATInfo& info = document.infos.front();
    const esi::sim::StackFactory stacks = [](const esi::EtherCATInfo& i, const esi::Device& d, esi::Diagnostics& diagnostics) {
        return esi::sim::make_model_slave(i, d, {.echo = true}, diagnostics);
    };
    auto line = std::make_unique<esi::sim::Line>();
    esi::Diagnostics diagnostics;
    for (int n = 0; n < 2; ++n) {
        std::optional<esi::sim::VirtualSlave> slave =
            esi::sim::build_slave(info, info.devices.front(), {}, stacks, "fuzz", diagnostics);
        if (!slave) std::abort();
        line->add(std::move(*slave));
    }
    // Station addresses 0x1001, 0x1002; mailbox SMs as the sample's ESI sets them; PREOP.
    const std::vector<std::vector<std::uint8_t>> prelude = {
        frame(2, 0x0000, 0x0010, {0x01, 0x10}),
        frame(2, 0xFFFF, 0x0010, {0x02, 0x10}),
        frame(8, 0, 0x0800, {0x00, 0x10, 0x80, 0x00, 0x26, 0x00, 0x01, 0x00, 0x80, 0x10, 0x80, 0x00, 0x22, 0x00, 0x01, 0x00}),
        frame(8, 0, 0x0120, {0x02, 0x00}),
    };
    for (std::uint64_t t = 0; t < prelude.size(); ++t) {
        std::vector<std::uint8_t> payload = prelude[t];
        (void)line->process(payload, t * 1000);
    }
    for (int i = 0; i < 4; ++i) line->poll();
    return line;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::unique_ptr<esi::sim::Line> line = prepared_line();
    std::size_t at = 0;
    std::uint64_t time = 1'000'000;
    for (int frames = 0; at + 2 <= size && frames < 64; ++frames) {
        const std::size_t length = static_cast<std::size_t>(data[at] | data[at + 1] << 8) % 1600;
        at += 2;
        const std::size_t take = std::min(length, size - at);
        std::vector<std::uint8_t> payload(data + at, data + at + take);
        at += take;
        const std::size_t before = payload.size();
        (void)line->process(payload, time += 10'000);
        if (payload.size() != before) std::abort();
    }
    return 0;
}
