#pragma once
// The SDO transfer protocol of the CoE server (ETG.1000.6 5.6.2, after CiA 301 7.2.4):
// initiate upload and download, expedited (up to 4 bytes in the request or response), normal
// (the size and as much data as the mailbox holds) and segmented (the rest in segments with
// alternating toggle bit), each with the complete-access flag. One transfer at a time, as a
// device's server runs it; what the bytes may do is ObjectAccess's decision.

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "sim/sdo_access.hpp"

namespace esi::sim {

class SdoServer {
public:
    explicit SdoServer(ObjectAccess& access) : access_(access) {}

    // `request` is the SDO part of a CoE SDO request (after the 2-byte CoE header); the result is
    // the SDO part of the response, empty when none is due (an abort from the master).
    // `room` is how many bytes the response may take after the CoE header.
    [[nodiscard]] std::vector<std::uint8_t> handle(std::span<const std::uint8_t> request, AlState state, std::size_t room);
    // Drops a transfer in progress (AL state INIT, mailbox reset).
    void reset();

private:
    struct Upload {
        std::uint16_t index = 0;
        std::uint8_t subindex = 0;
        std::vector<std::uint8_t> data;
        std::size_t offset = 0;
        std::uint8_t toggle = 0;
    };
    struct Download {
        std::uint16_t index = 0;
        std::uint8_t subindex = 0;
        bool complete = false;
        std::vector<std::uint8_t> data;
        std::size_t size = 0;  // announced
        std::uint8_t toggle = 0;
    };

    std::vector<std::uint8_t> initiate_upload(std::span<const std::uint8_t> request, AlState state, std::size_t room);
    std::vector<std::uint8_t> upload_segment(std::span<const std::uint8_t> request, std::size_t room);
    std::vector<std::uint8_t> initiate_download(std::span<const std::uint8_t> request, AlState state);
    std::vector<std::uint8_t> download_segment(std::span<const std::uint8_t> request, AlState state);

    ObjectAccess& access_;
    std::optional<Upload> upload_;
    std::optional<Download> download_;
};

// An SDO abort transfer request (command 0x80) for index:subindex with the code.
[[nodiscard]] std::vector<std::uint8_t> sdo_abort_frame(std::uint16_t index, std::uint8_t subindex, std::uint32_t code);

}  // namespace esi::sim
