// The raw-socket side of esi-sim (Linux AF_PACKET, packet(7)).

#include "esi/sim/raw_socket.hpp"

#include <arpa/inet.h>
#include <linux/if_packet.h>
#include <net/ethernet.h>
#include <net/if.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <chrono>
#include <cstring>

#include "esi/esc/frame.hpp"

namespace esi::sim {

namespace {

struct Socket {
    int fd = -1;
    ~Socket() {
        if (fd >= 0) ::close(fd);
    }
};

Diagnostics failure(const std::string& interface, std::string message) {
    Diagnostics d;
    d.emplace(Severity::error, "sim-interface", std::move(message), interface, {});
    return d;
}

}  // namespace

Diagnostics serve_interface(Line& line, const std::string& interface, const std::atomic<bool>& stop,
                            const std::function<void()>& ready, ServeStats* stats) {
    const unsigned index = ::if_nametoindex(interface.c_str());
    if (interface.empty() || interface.size() >= IFNAMSIZ || index == 0)
        return failure(interface, "no network interface '" + interface + "'");
    Socket socket;
    // Bound to EtherType 0x88A4 only, so the socket sees neither other traffic nor the frames it
    // sends itself.
    socket.fd = ::socket(AF_PACKET, SOCK_RAW, htons(esc::ethertype));
    if (socket.fd < 0) {
        const int error = errno;
        if (error == EPERM || error == EACCES)
            return failure(interface, "no permission to open a raw socket (needs CAP_NET_RAW: run as root, give the "
                                      "binary the capability, or run it in a user and network namespace)");
        return failure(interface, std::string("cannot open a raw socket: ") + std::strerror(error));
    }
    sockaddr_ll address{};
    address.sll_family = AF_PACKET;
    address.sll_protocol = htons(esc::ethertype);
    address.sll_ifindex = static_cast<int>(index);
    if (::bind(socket.fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0)
        return failure(interface, std::string("cannot bind to '") + interface + "': " + std::strerror(errno));

    if (ready) ready();
    std::array<std::uint8_t, 2048> frame{};
    const auto start = std::chrono::steady_clock::now();
    while (!stop.load()) {
        pollfd waiting{socket.fd, POLLIN, 0};
        const int ready_count = ::poll(&waiting, 1, 100);
        if (ready_count < 0) {
            if (errno == EINTR) continue;
            return failure(interface, std::string("poll: ") + std::strerror(errno));
        }
        if (ready_count == 0) continue;
        sockaddr_ll from{};
        socklen_t from_length = sizeof from;
        const ssize_t received = ::recvfrom(socket.fd, frame.data(), frame.size(), MSG_TRUNC,
                                            reinterpret_cast<sockaddr*>(&from), &from_length);
        if (received < 0) {
            if (errno == EINTR || errno == EAGAIN) continue;
            return failure(interface, std::string("receive: ") + std::strerror(errno));
        }
        if (from.sll_pkttype == PACKET_OUTGOING) continue;
        const auto size = static_cast<std::size_t>(received);
        // A frame larger than the buffer was cut (MSG_TRUNC gives its real length): not trusted.
        if (size > frame.size() || size < esc::ethernet_header_bytes) {
            if (stats) ++stats->dropped;
            continue;
        }
        const std::uint16_t type = static_cast<std::uint16_t>(frame[12] << 8 | frame[13]);
        if (type != esc::ethertype) continue;
        const auto now = std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - start);
        const esc::FrameOutcome outcome =
            line.process(std::span<std::uint8_t>(frame.data() + esc::ethernet_header_bytes, size - esc::ethernet_header_bytes),
                         static_cast<std::uint64_t>(now.count()));
        if (outcome != esc::FrameOutcome::answered) {
            if (stats) ++stats->dropped;
            continue;
        }
        // An ESC marks a frame it processed: the locally administered bit of the source address.
        frame[6] |= 0x02;
        sockaddr_ll to{};
        to.sll_family = AF_PACKET;
        to.sll_protocol = htons(esc::ethertype);
        to.sll_ifindex = static_cast<int>(index);
        to.sll_halen = 6;
        std::memcpy(to.sll_addr, frame.data(), 6);
        if (::sendto(socket.fd, frame.data(), size, 0, reinterpret_cast<const sockaddr*>(&to), sizeof to) < 0) {
            if (errno == EINTR || errno == ENOBUFS || errno == EAGAIN) continue;
            return failure(interface, std::string("send: ") + std::strerror(errno));
        }
        if (stats) ++stats->answered;
    }
    return {};
}

}  // namespace esi::sim
