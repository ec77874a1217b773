#include "esi/sii/encode.hpp"

#include "byte_io.hpp"

namespace esi::sii {

std::vector<std::uint8_t> encode_strings(const Strings& strings) {
    ByteWriter w;
    w.u8(static_cast<std::uint8_t>(strings.items.size()));
    for (const auto& s : strings.items) {
        w.u8(static_cast<std::uint8_t>(s.size()));
        w.bytes(s.data(), s.size() & 0xFFu);
    }
    w.pad_to_word(0x00);
    return w.take();
}

std::vector<std::uint8_t> encode_general(const General& g) {
    ByteWriter w;
    w.u8(g.group_idx);
    w.u8(g.image_idx);
    w.u8(g.order_idx);
    w.u8(g.name_idx);
    w.u8(g.reserved_4);
    w.u8(g.coe_details);
    w.u8(g.foe_details);
    w.u8(g.eoe_details);
    w.u8(g.soe_channels);
    w.u8(g.ds402_channels);
    w.u8(g.sysman_class);
    w.u8(g.flags);
    w.u16(static_cast<std::uint16_t>(g.current_on_ebus));
    w.u8(g.group_idx_duplicate);
    w.u8(g.reserved_15);
    w.u16(g.physical_ports);
    w.u16(g.physical_memory_address);
    for (const std::uint8_t b : g.reserved_20) w.u8(b);
    return w.take();
}

std::vector<std::uint8_t> encode_fmmus(const Fmmus& fmmus, std::uint8_t pad) {
    ByteWriter w;
    for (const std::uint8_t u : fmmus.usages) w.u8(u);
    w.pad_to_word(pad);
    return w.take();
}

std::vector<std::uint8_t> encode_sync_managers(const SyncManagers& sms) {
    ByteWriter w;
    for (const auto& sm : sms.items) {
        w.u16(sm.start_address);
        w.u16(sm.length);
        w.u8(sm.control);
        w.u8(sm.status);
        w.u8(sm.enable);
        w.u8(sm.type);
    }
    return w.take();
}

std::vector<std::uint8_t> encode_pdos(const Pdos& pdos) {
    ByteWriter w;
    for (const auto& pdo : pdos.items) {
        w.u16(pdo.index);
        w.u8(static_cast<std::uint8_t>(pdo.entries.size()));
        w.u8(pdo.sync_manager);
        w.u8(pdo.dc_sync);
        w.u8(pdo.name_idx);
        w.u16(pdo.flags);
        for (const auto& e : pdo.entries) {
            w.u16(e.index);
            w.u8(e.subindex);
            w.u8(e.name_idx);
            w.u8(e.data_type);
            w.u8(e.bit_len);
            w.u16(e.flags);
        }
    }
    return w.take();
}

std::vector<std::uint8_t> encode_dc(const DcOpModes& dc) {
    ByteWriter w;
    for (const auto& m : dc.items) {
        w.u32(m.cycle_time0);
        w.u32(m.shift_time0);
        w.u32(m.shift_time1);
        w.u16(static_cast<std::uint16_t>(m.sync1_cycle_factor));
        w.u16(m.assign_activate);
        w.u16(static_cast<std::uint16_t>(m.sync0_cycle_factor));
        w.u8(m.name_idx);
        w.u8(m.desc_idx);
        for (const std::uint8_t b : m.reserved) w.u8(b);
    }
    return w.take();
}

std::vector<std::uint8_t> encode_content(const CategoryContent& content) {
    struct Visitor {
        std::vector<std::uint8_t> operator()(const RawData& raw) const {
            ByteWriter w;
            w.bytes(raw.bytes.data(), raw.bytes.size());
            w.pad_to_word(0x00);
            return w.take();
        }
        std::vector<std::uint8_t> operator()(const Strings& s) const { return encode_strings(s); }
        std::vector<std::uint8_t> operator()(const General& g) const { return encode_general(g); }
        std::vector<std::uint8_t> operator()(const Fmmus& f) const { return encode_fmmus(f); }
        std::vector<std::uint8_t> operator()(const SyncManagers& s) const { return encode_sync_managers(s); }
        std::vector<std::uint8_t> operator()(const Pdos& p) const { return encode_pdos(p); }
        std::vector<std::uint8_t> operator()(const DcOpModes& d) const { return encode_dc(d); }
    };
    return std::visit(Visitor{}, content);
}

std::vector<std::uint8_t> encode_header(const Header& h, bool compute_crc) {
    ByteWriter w;
    w.bytes(h.config_data.data(), h.config_data.size());
    w.u16(compute_crc ? config_crc(h.config_data) : h.checksum);
    w.u32(h.vendor_id);
    w.u32(h.product_code);
    w.u32(h.revision_no);
    w.u32(h.serial_no);
    w.u16(h.execution_delay);
    w.u16(h.port0_delay);
    w.u16(h.port1_delay);
    w.u16(h.reserved_0x13);
    w.u16(h.bootstrap_receive_offset);
    w.u16(h.bootstrap_receive_size);
    w.u16(h.bootstrap_send_offset);
    w.u16(h.bootstrap_send_size);
    w.u16(h.standard_receive_offset);
    w.u16(h.standard_receive_size);
    w.u16(h.standard_send_offset);
    w.u16(h.standard_send_size);
    w.u16(h.mailbox_protocols);
    for (const std::uint16_t r : h.reserved_0x1d) w.u16(r);
    w.u16(h.size);
    w.u16(h.version);
    return w.take();
}

std::size_t encoded_size(const Image& image) {
    std::size_t total = header_bytes + 2;  // header + end marker
    for (const auto& c : image.categories) total += 4 + encode_content(c.content).size();
    return total;
}

std::vector<std::uint8_t> encode_image(const Image& image, std::size_t pad_to_bytes, bool compute_crc) {
    std::vector<std::uint8_t> out = encode_header(image.header, compute_crc);
    ByteWriter w(std::move(out));
    for (const auto& c : image.categories) {
        const std::vector<std::uint8_t> payload = encode_content(c.content);
        w.u16(c.type);
        w.u16(static_cast<std::uint16_t>(payload.size() / 2));
        w.bytes(payload.data(), payload.size());
    }
    w.u16(end_marker);
    out = w.take();
    if (out.size() < pad_to_bytes) out.resize(pad_to_bytes, 0xFF);
    return out;
}

}  // namespace esi::sii
