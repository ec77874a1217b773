#pragma once
// The SII EEPROM image as structured data: the fixed header and an ordered list of categories,
// each with its decoded content. The builder produces one of these from a device; the decoder
// produces one from bytes; encode_image (encode.hpp) turns one into bytes.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "esi/sii/layout.hpp"

namespace esi::sii {

// Words 0x00-0x3F.
struct Header {
    std::array<std::uint8_t, config_area_bytes> config_data{};  // words 0-6 as bytes
    std::uint16_t checksum = 0;                                  // word 7 as stored (low byte: CRC-8)
    std::uint32_t vendor_id = 0;
    std::uint32_t product_code = 0;
    std::uint32_t revision_no = 0;
    std::uint32_t serial_no = 0;
    std::uint16_t execution_delay = 0;
    std::uint16_t port0_delay = 0;
    std::uint16_t port1_delay = 0;
    std::uint16_t reserved_0x13 = 0;
    std::uint16_t bootstrap_receive_offset = 0;
    std::uint16_t bootstrap_receive_size = 0;
    std::uint16_t bootstrap_send_offset = 0;
    std::uint16_t bootstrap_send_size = 0;
    std::uint16_t standard_receive_offset = 0;  // SM0, MBoxOut (master -> slave)
    std::uint16_t standard_receive_size = 0;
    std::uint16_t standard_send_offset = 0;     // SM1, MBoxIn (slave -> master)
    std::uint16_t standard_send_size = 0;
    std::uint16_t mailbox_protocols = 0;
    std::array<std::uint16_t, 0x21> reserved_0x1d{};  // words 0x1D-0x3D
    std::uint16_t size = 0;                           // word 0x3E: KiBit - 1
    std::uint16_t version = 1;

    [[nodiscard]] std::uint16_t config_word(std::size_t index) const {  // index 0..6
        return static_cast<std::uint16_t>(config_data[2 * index] | (config_data[2 * index + 1] << 8));
    }
    [[nodiscard]] std::uint64_t eeprom_bytes() const { return eeprom_bytes_from_size_word(size); }
};

// Category 10: the strings, index 1 first. Bytes as stored (the builder writes ISO-8859-1 when
// the text allows it, as the Beckhoff images do).
struct Strings {
    std::vector<std::string> items;
    friend bool operator==(const Strings&, const Strings&) = default;
};

// Category 30, 32 bytes (ETG.2010 Table 4).
struct General {
    std::uint8_t group_idx = 0;
    std::uint8_t image_idx = 0;
    std::uint8_t order_idx = 0;
    std::uint8_t name_idx = 0;
    std::uint8_t reserved_4 = 0;  // IgH reads a physical layer here; Beckhoff/SOES write values
    std::uint8_t coe_details = 0;
    std::uint8_t foe_details = 0;
    std::uint8_t eoe_details = 0;
    std::uint8_t soe_channels = 0;
    std::uint8_t ds402_channels = 0;
    std::uint8_t sysman_class = 0;
    std::uint8_t flags = 0;
    std::int16_t current_on_ebus = 0;  // mA; negative: the device feeds the E-Bus
    std::uint8_t group_idx_duplicate = 0;  // byte 14, ETG.2010: the group index again
    std::uint8_t reserved_15 = 0;
    std::uint16_t physical_ports = 0;      // bytes 16-17, 4 bits per port
    std::uint16_t physical_memory_address = 0;
    std::array<std::uint8_t, 12> reserved_20{};
    friend bool operator==(const General&, const General&) = default;

    [[nodiscard]] std::uint8_t port(unsigned number) const {
        return static_cast<std::uint8_t>((physical_ports >> (4 * number)) & 0x0F);
    }
};

// Category 40: one usage byte per FMMU.
struct Fmmus {
    std::vector<std::uint8_t> usages;
    friend bool operator==(const Fmmus&, const Fmmus&) = default;
};

struct SyncManagerRecord {
    std::uint16_t start_address = 0;
    std::uint16_t length = 0;
    std::uint8_t control = 0;
    std::uint8_t status = 0;
    std::uint8_t enable = 0;
    std::uint8_t type = 0;
    friend bool operator==(const SyncManagerRecord&, const SyncManagerRecord&) = default;
};

// Category 41.
struct SyncManagers {
    std::vector<SyncManagerRecord> items;
    friend bool operator==(const SyncManagers&, const SyncManagers&) = default;
};

struct PdoEntryRecord {
    std::uint16_t index = 0;
    std::uint8_t subindex = 0;
    std::uint8_t name_idx = 0;
    std::uint8_t data_type = 0;  // CoE code, one byte (ETG.2010 Table 14)
    std::uint8_t bit_len = 0;
    std::uint16_t flags = 0;
    friend bool operator==(const PdoEntryRecord&, const PdoEntryRecord&) = default;
};

struct PdoRecord {
    std::uint16_t index = 0;
    std::uint8_t sync_manager = pdo_no_sync_manager;
    std::uint8_t dc_sync = 0;
    std::uint8_t name_idx = 0;
    std::uint16_t flags = 0;
    std::vector<PdoEntryRecord> entries;  // the entry count byte is entries.size()
    friend bool operator==(const PdoRecord&, const PdoRecord&) = default;
};

// Categories 50 (TxPDO) and 51 (RxPDO).
struct Pdos {
    std::vector<PdoRecord> items;
    friend bool operator==(const Pdos&, const Pdos&) = default;
};

// One DC operation mode, 24 bytes (ETG.2010 Table 12).
struct DcOpModeRecord {
    std::uint32_t cycle_time0 = 0;
    std::uint32_t shift_time0 = 0;
    std::uint32_t shift_time1 = 0;
    std::int16_t sync1_cycle_factor = 0;
    std::uint16_t assign_activate = 0;
    std::int16_t sync0_cycle_factor = 0;
    std::uint8_t name_idx = 0;
    std::uint8_t desc_idx = 0;
    std::array<std::uint8_t, 4> reserved{};
    friend bool operator==(const DcOpModeRecord&, const DcOpModeRecord&) = default;
};

// Category 60.
struct DcOpModes {
    std::vector<DcOpModeRecord> items;
    friend bool operator==(const DcOpModes&, const DcOpModes&) = default;
};

// Any other category, or one that could not be decoded: the payload as stored.
struct RawData {
    std::vector<std::uint8_t> bytes;
    friend bool operator==(const RawData&, const RawData&) = default;
};

using CategoryContent = std::variant<RawData, Strings, General, Fmmus, SyncManagers, Pdos, DcOpModes>;

struct Category {
    std::uint16_t type = 0;
    CategoryContent content;
    // Filled by the decoder: where the category header sits and the length word as stored.
    std::uint32_t offset = 0;
    std::uint16_t declared_words = 0;
};

struct Image {
    Header header;
    std::vector<Category> categories;  // in image order, without the end marker

    // The first category of a type, nullptr when absent.
    [[nodiscard]] const Category* find(std::uint16_t type) const;
    // Typed access to the first category of the matching type when it decoded cleanly.
    [[nodiscard]] const Strings* strings() const;
    [[nodiscard]] const General* general() const;
    [[nodiscard]] const Fmmus* fmmus() const;
    [[nodiscard]] const SyncManagers* sync_managers() const;
    [[nodiscard]] const Pdos* pdos(std::uint16_t type) const;  // category::tx_pdo or rx_pdo
    [[nodiscard]] const DcOpModes* dc() const;
    // String `index` (1-based) of the Strings category; nullopt for 0 or an index past the end.
    [[nodiscard]] std::optional<std::string> string_at(std::uint8_t index) const;
};

}  // namespace esi::sii
