// esi-sim's speed (issue 20, "Measured"): frames answered per second by a line of 1 and of 10
// virtual slaves in process (no socket), each frame a 1 ms cycle's traffic (an LRW over every
// slave's process data, the DC system-time ARMW and a BRD of AL status), with every slave's model
// slave polled after each frame as esi-sim does. The target: esi-sim is never the bottleneck of a
// 1 ms cycle with 10 slaves on one core, i.e. well over 1,000 frames per second.
//   esi_sim_frames [SOURCE.yaml] [SECONDS]
// With --veth IF it is instead a master on IF measuring the LRW round trip through esi-sim
// (bench/esi_sim_veth.sh runs it in a namespace): median and 99th percentile of 10,000 frames.

#include <arpa/inet.h>
#include <linux/if_packet.h>
#include <net/if.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "esi/sim/model_slave.hpp"
#include "esi/sim/slave_setup.hpp"

namespace {

using Clock = std::chrono::steady_clock;

struct Datagram {
    std::uint8_t command;
    std::uint16_t adp, ado;
    std::vector<std::uint8_t> data;
};

std::vector<std::uint8_t> payload_of(const std::vector<Datagram>& datagrams) {
    std::vector<std::uint8_t> out(2);
    for (std::size_t i = 0; i < datagrams.size(); ++i) {
        const Datagram& d = datagrams[i];
        const std::uint16_t length = static_cast<std::uint16_t>(d.data.size() | (i + 1 < datagrams.size() ? 0x8000 : 0));
        const std::uint8_t header[10] = {d.command, static_cast<std::uint8_t>(i), static_cast<std::uint8_t>(d.adp),
                                         static_cast<std::uint8_t>(d.adp >> 8), static_cast<std::uint8_t>(d.ado),
                                         static_cast<std::uint8_t>(d.ado >> 8), static_cast<std::uint8_t>(length),
                                         static_cast<std::uint8_t>(length >> 8), 0, 0};
        out.insert(out.end(), header, header + 10);
        out.insert(out.end(), d.data.begin(), d.data.end());
        out.push_back(0);
        out.push_back(0);
    }
    const std::uint16_t total = static_cast<std::uint16_t>((out.size() - 2) | 0x1000);
    out[0] = static_cast<std::uint8_t>(total);
    out[1] = static_cast<std::uint8_t>(total >> 8);
    return out;
}

std::vector<std::uint8_t> le(std::uint32_t v, int bytes) {
    std::vector<std::uint8_t> out;
    for (int i = 0; i < bytes; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
    return out;
}

// Station addresses, the sample's SMs (mailbox 0x1000/0x1080, outputs 0x1100, inputs 0x1400, one
// byte each) and two FMMUs per slave, one logical byte pair per slave; then INIT -> OP.
void configure(esi::sim::Line& line, std::uint64_t& time) {
    const std::size_t n = line.size();
    auto send = [&](const std::vector<Datagram>& datagrams) {
        std::vector<std::uint8_t> p = payload_of(datagrams);
        (void)line.process(p, time += 100'000);
    };
    for (std::size_t i = 0; i < n; ++i)
        send({{2, static_cast<std::uint16_t>(-static_cast<int>(i)), 0x0010, le(0x1001 + static_cast<std::uint32_t>(i), 2)}});
    send({{8, 0, 0x0800, {0x00, 0x10, 0x80, 0x00, 0x26, 0x00, 0x01, 0x00, 0x80, 0x10, 0x80, 0x00, 0x22, 0x00, 0x01, 0x00}}});
    send({{8, 0, 0x0120, {0x02, 0x00}}});
    for (int i = 0; i < 10; ++i) line.poll();
    send({{8, 0, 0x0810, {0x00, 0x11, 0x01, 0x00, 0x64, 0x00, 0x01, 0x00, 0x00, 0x14, 0x01, 0x00, 0x20, 0x00, 0x01, 0x00}}});
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint32_t logical = 0x10000 + 2 * static_cast<std::uint32_t>(i);
        std::vector<std::uint8_t> fmmus;
        for (const auto& [lg, phys, type] : {std::tuple{logical, 0x1100u, 2u}, std::tuple{logical + 1, 0x1400u, 1u}}) {
            const auto a = le(lg, 4), b = le(1, 2), c = le(phys, 2);
            fmmus.insert(fmmus.end(), a.begin(), a.end());
            fmmus.insert(fmmus.end(), b.begin(), b.end());
            fmmus.push_back(0);
            fmmus.push_back(7);
            fmmus.insert(fmmus.end(), c.begin(), c.end());
            fmmus.push_back(0);
            fmmus.push_back(static_cast<std::uint8_t>(type));
            fmmus.push_back(1);
            fmmus.insert(fmmus.end(), 3, 0);
        }
        send({{5, static_cast<std::uint16_t>(0x1001 + i), 0x0600, fmmus}});
    }
    for (std::uint8_t state : {0x04, 0x08}) {
        send({{8, 0, 0x0120, {state, 0x00}}});
        for (int i = 0; i < 10; ++i) send({{12, 0, 1, std::vector<std::uint8_t>(2 * n, 0)}});
    }
}

std::vector<Datagram> cycle_frame(std::size_t slaves) {
    return {{12, 0x0000, 0x0001, std::vector<std::uint8_t>(2 * slaves, 0x55)},  // LRW at 0x10000
            {13, 0x0000, 0x0910, std::vector<std::uint8_t>(8, 0)},
            {7, 0x0000, 0x0130, std::vector<std::uint8_t>(2, 0)}};
}

int in_process(const std::string& source, double seconds) {
    const esi::sim::StackFactory stacks = [](const esi::EtherCATInfo& i, const esi::Device& d, esi::Diagnostics& diagnostics) {
        return esi::sim::make_model_slave(i, d, {}, diagnostics);
    };
    for (const std::size_t slaves : {std::size_t{1}, std::size_t{10}}) {
        esi::sim::Line line;
        for (std::size_t i = 0; i < slaves; ++i) {
            esi::sim::LineResult one = esi::sim::line_from_source(source, {}, stacks);
            if (!one.line) {
                std::fprintf(stderr, "esi_sim_frames: %s cannot be emulated\n", source.c_str());
                return 2;
            }
            // Each slave from its own one-slave line: move it over (the stack copied what it needs).
            line.add(std::move(one.line->slave(0)));
        }
        std::uint64_t time = 0;
        configure(line, time);
        const std::vector<std::uint8_t> frame = payload_of(cycle_frame(slaves));
        std::vector<std::uint8_t> work = frame;
        (void)line.process(work, time += 1000);
        const std::uint16_t wkc = static_cast<std::uint16_t>(work[2 + 10 + 2 * slaves] | work[2 + 10 + 2 * slaves + 1] << 8);
        std::uint64_t frames = 0;
        const auto start = Clock::now();
        const auto until = start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
        while (Clock::now() < until) {
            for (int i = 0; i < 100; ++i) {
                work = frame;
                (void)line.process(work, time += 1000);
            }
            frames += 100;
        }
        const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
        std::printf("%2zu slave(s): %9.0f frames/s (%.2f us per frame; LRW working counter %u of %zu)\n", slaves,
                    static_cast<double>(frames) / elapsed, elapsed * 1e6 / static_cast<double>(frames), wkc, 3 * slaves);
    }
    return 0;
}

int over_veth(const std::string& interface, int count) {
    const int fd = ::socket(AF_PACKET, SOCK_RAW, htons(0x88A4));
    const unsigned index = ::if_nametoindex(interface.c_str());
    if (fd < 0 || index == 0) {
        std::fprintf(stderr, "esi_sim_frames: cannot open %s\n", interface.c_str());
        return 2;
    }
    sockaddr_ll address{};
    address.sll_family = AF_PACKET;
    address.sll_protocol = htons(0x88A4);
    address.sll_ifindex = static_cast<int>(index);
    address.sll_halen = 6;
    std::memset(address.sll_addr, 0xFF, 6);
    if (::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) return 2;
    std::vector<std::uint8_t> frame = {0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0x02, 0x00, 0x00, 0x00, 0x00, 0x01, 0x88, 0xA4};
    const std::vector<std::uint8_t> payload = payload_of({{12, 0x0000, 0x0001, std::vector<std::uint8_t>(32, 0x55)}});
    frame.insert(frame.end(), payload.begin(), payload.end());
    frame.resize(std::max<std::size_t>(frame.size(), 60), 0);
    std::vector<double> rtt;
    std::uint8_t buffer[2048];
    for (int i = 0; i < count; ++i) {
        const auto t0 = Clock::now();
        if (::sendto(fd, frame.data(), frame.size(), 0, reinterpret_cast<sockaddr*>(&address), sizeof address) < 0) return 2;
        pollfd p{fd, POLLIN, 0};
        if (::poll(&p, 1, 1000) <= 0) continue;
        if (::recv(fd, buffer, sizeof buffer, 0) <= 0) continue;
        rtt.push_back(std::chrono::duration<double, std::micro>(Clock::now() - t0).count());
    }
    std::sort(rtt.begin(), rtt.end());
    if (rtt.empty()) return 1;
    std::printf("LRW round trip over %s: median %.1f us, p99 %.1f us (%zu of %d frames answered)\n", interface.c_str(),
                rtt[rtt.size() / 2], rtt[rtt.size() * 99 / 100], rtt.size(), count);
    ::close(fd);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc > 2 && std::string(argv[1]) == "--veth") return over_veth(argv[2], argc > 3 ? std::atoi(argv[3]) : 10000);
    const std::string source = argc > 1 ? argv[1] : std::string(ESI_SOURCE_DIR) + "/samples/digital-io-8.yaml";
    return in_process(source, argc > 2 ? std::atof(argv[2]) : 2.0);
}
