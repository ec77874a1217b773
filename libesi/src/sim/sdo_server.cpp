// SDO transfers (sdo_server.hpp). Command bytes (ETG.1000.6 5.6.2.1–5.6.2.8): the top three bits
// are the command specifier, bit 4 complete access (initiate) or toggle (segments).

#include "sim/sdo_server.hpp"

#include <algorithm>

#include "esi/ethercat/mailbox.hpp"

namespace esi::sim {

namespace {

namespace cmd = ethercat::sdo_command;

// Bytes of an initiate frame: command, index (2), sub-index, 4 data bytes.
constexpr std::size_t initiate_bytes = 8;
// A segment carries at least 7 data bytes; fewer are padded and counted as unused.
constexpr std::size_t min_segment_data = 7;

std::uint16_t index_of(std::span<const std::uint8_t> r) { return static_cast<std::uint16_t>(r[1] | (r[2] << 8)); }

std::uint32_t u32_at(std::span<const std::uint8_t> r, std::size_t at) {
    return static_cast<std::uint32_t>(r[at]) | (static_cast<std::uint32_t>(r[at + 1]) << 8) |
           (static_cast<std::uint32_t>(r[at + 2]) << 16) | (static_cast<std::uint32_t>(r[at + 3]) << 24);
}

std::vector<std::uint8_t> initiate_frame(std::uint8_t command, std::uint16_t index, std::uint8_t subindex) {
    return {command, static_cast<std::uint8_t>(index), static_cast<std::uint8_t>(index >> 8), subindex, 0, 0, 0, 0};
}

void put_u32(std::vector<std::uint8_t>& f, std::size_t at, std::uint32_t v) {
    for (std::size_t i = 0; i < 4; ++i) f[at + i] = static_cast<std::uint8_t>(v >> (8 * i));
}

}  // namespace

std::vector<std::uint8_t> sdo_abort_frame(std::uint16_t index, std::uint8_t subindex, std::uint32_t code) {
    std::vector<std::uint8_t> f = initiate_frame(ethercat::sdo_abort_command, index, subindex);
    put_u32(f, 4, code);
    return f;
}

void SdoServer::reset() {
    upload_.reset();
    download_.reset();
}

std::vector<std::uint8_t> SdoServer::handle(std::span<const std::uint8_t> request, AlState state, std::size_t room) {
    if (request.empty()) return {};
    const std::uint8_t specifier = request[0] >> 5;
    if (specifier == cmd::abort) {  // the master gives up a transfer; no answer is due
        reset();
        return {};
    }
    // Every SDO frame is at least an initiate frame long (segments are padded to it).
    if (request.size() < initiate_bytes || room < initiate_bytes + 1) {
        reset();
        return sdo_abort_frame(request.size() >= 4 ? index_of(request) : 0, request.size() >= 4 ? request[3] : 0,
                               ethercat::sdo_abort::command_specifier);
    }
    switch (specifier) {
        case cmd::initiate_upload: return initiate_upload(request, state, room);
        case cmd::upload_segment: return upload_segment(request, room);
        case cmd::initiate_download: return initiate_download(request, state);
        case cmd::download_segment: return download_segment(request, state);
        default: reset(); return sdo_abort_frame(index_of(request), request[3], ethercat::sdo_abort::command_specifier);
    }
}

std::vector<std::uint8_t> SdoServer::initiate_upload(std::span<const std::uint8_t> request, AlState state, std::size_t room) {
    reset();
    const std::uint16_t index = index_of(request);
    const std::uint8_t subindex = request[3];
    const bool complete = (request[0] & cmd::complete_access) != 0;
    std::vector<std::uint8_t> data;
    if (const std::uint32_t code = access_.read(index, subindex, complete, state, data); code != ethercat::sdo_abort::none)
        return sdo_abort_frame(index, subindex, code);
    const std::uint8_t ca = complete ? cmd::complete_access : 0;
    if (data.size() <= 4 && !data.empty()) {
        const auto unused = static_cast<std::uint8_t>(4 - data.size());
        std::vector<std::uint8_t> f =
            initiate_frame(static_cast<std::uint8_t>(cmd::byte_of(cmd::response_initiate_upload) | ca | cmd::expedited | cmd::size_indicated | (unused << 2)), index, subindex);
        std::copy(data.begin(), data.end(), f.begin() + 4);
        return f;
    }
    std::vector<std::uint8_t> f = initiate_frame(static_cast<std::uint8_t>(cmd::byte_of(cmd::response_initiate_upload) | ca | cmd::size_indicated), index, subindex);
    put_u32(f, 4, static_cast<std::uint32_t>(data.size()));
    const std::size_t first = std::min(data.size(), room - initiate_bytes);
    f.insert(f.end(), data.begin(), data.begin() + static_cast<std::ptrdiff_t>(first));
    if (first < data.size()) upload_ = Upload{index, subindex, std::move(data), first, 0};
    return f;
}

std::vector<std::uint8_t> SdoServer::upload_segment(std::span<const std::uint8_t> request, std::size_t room) {
    const std::uint8_t toggle = request[0] & cmd::toggle;
    if (!upload_) return sdo_abort_frame(index_of(request), request[3], ethercat::sdo_abort::command_specifier);
    if (toggle != upload_->toggle) {
        const Upload u = *upload_;
        reset();
        return sdo_abort_frame(u.index, u.subindex, ethercat::sdo_abort::toggle_bit);
    }
    Upload& u = *upload_;
    const std::size_t left = u.data.size() - u.offset;
    const std::size_t take = std::min(left, room - 1);
    const bool last = take == left;
    std::uint8_t command = toggle | (last ? 0x01 : 0x00);
    if (take < min_segment_data) command |= static_cast<std::uint8_t>((min_segment_data - take) << 1);
    std::vector<std::uint8_t> f{command};
    f.insert(f.end(), u.data.begin() + static_cast<std::ptrdiff_t>(u.offset),
             u.data.begin() + static_cast<std::ptrdiff_t>(u.offset + take));
    if (take < min_segment_data) f.resize(1 + min_segment_data, 0);
    u.offset += take;
    u.toggle ^= cmd::toggle;
    if (last) upload_.reset();
    return f;
}

std::vector<std::uint8_t> SdoServer::initiate_download(std::span<const std::uint8_t> request, AlState state) {
    reset();
    const std::uint16_t index = index_of(request);
    const std::uint8_t subindex = request[3];
    const std::uint8_t command = request[0];
    const bool complete = (command & cmd::complete_access) != 0;
    const std::size_t limit = access_.write_limit(index, subindex, complete);
    if (command & cmd::expedited) {
        std::size_t size = 4;
        if (command & cmd::size_indicated) size = 4 - ((command >> 2) & 0x03);
        // Without a size, the entry's own size (at most 4) is what the master means.
        else if (limit > 0 && limit < 4) size = limit;
        const std::uint32_t code = access_.write(index, subindex, complete, state, request.subspan(4, size));
        if (code != ethercat::sdo_abort::none) return sdo_abort_frame(index, subindex, code);
        return initiate_frame(cmd::byte_of(cmd::response_initiate_download), index, subindex);
    }
    const std::span<const std::uint8_t> carried = request.subspan(initiate_bytes);
    const std::size_t size = (command & cmd::size_indicated) ? u32_at(request, 4) : carried.size();
    // Existence and access are refused before any segment is buffered; a size past the target's
    // is refused at once, so an absurd length never allocates.
    if (limit == 0) {
        const std::uint32_t code = access_.write(index, subindex, complete, state, {});
        return sdo_abort_frame(index, subindex, code != ethercat::sdo_abort::none ? code : ethercat::sdo_abort::length_too_short);
    }
    if (size > limit) return sdo_abort_frame(index, subindex, ethercat::sdo_abort::length_too_long);
    if (carried.size() >= size) {
        const std::uint32_t code = access_.write(index, subindex, complete, state, carried.first(size));
        if (code != ethercat::sdo_abort::none) return sdo_abort_frame(index, subindex, code);
        return initiate_frame(cmd::byte_of(cmd::response_initiate_download), index, subindex);
    }
    Download d{index, subindex, complete, {}, size, 0};
    d.data.reserve(size);
    d.data.assign(carried.begin(), carried.end());
    download_ = std::move(d);
    return initiate_frame(cmd::byte_of(cmd::response_initiate_download), index, subindex);
}

std::vector<std::uint8_t> SdoServer::download_segment(std::span<const std::uint8_t> request, AlState state) {
    const std::uint8_t command = request[0];
    if (!download_) return sdo_abort_frame(0, 0, ethercat::sdo_abort::command_specifier);
    Download& d = *download_;
    if ((command & cmd::toggle) != d.toggle) {
        const Download failed = std::move(d);
        reset();
        return sdo_abort_frame(failed.index, failed.subindex, ethercat::sdo_abort::toggle_bit);
    }
    std::size_t take = request.size() - 1;
    if (take == min_segment_data) take -= (command >> 1) & 0x07;
    if (d.data.size() + take > d.size) {
        const Download failed = std::move(d);
        reset();
        return sdo_abort_frame(failed.index, failed.subindex, ethercat::sdo_abort::length_too_long);
    }
    d.data.insert(d.data.end(), request.begin() + 1, request.begin() + 1 + static_cast<std::ptrdiff_t>(take));
    const std::vector<std::uint8_t> response{static_cast<std::uint8_t>(cmd::byte_of(cmd::response_download_segment) | d.toggle), 0, 0, 0, 0, 0, 0, 0};
    d.toggle ^= cmd::toggle;
    if (!(command & 0x01)) return response;
    const Download done = std::move(d);
    reset();
    if (done.data.size() != done.size) return sdo_abort_frame(done.index, done.subindex, ethercat::sdo_abort::length_mismatch);
    const std::uint32_t code = access_.write(done.index, done.subindex, done.complete, state, done.data);
    if (code != ethercat::sdo_abort::none) return sdo_abort_frame(done.index, done.subindex, code);
    return response;
}

}  // namespace esi::sim
