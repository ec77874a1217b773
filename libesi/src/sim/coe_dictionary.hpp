#pragma once
// The object dictionary as the device's firmware holds it at run time: every object with its
// sub-entries, their CoE data types, sizes, access rights per AL state and current values. The
// SDO server, SDO Information and the process image all work on this one table.

#include <cstdint>
#include <string>
#include <vector>

#include "esi/data_types.hpp"
#include "esi/ethercat/al_state.hpp"

namespace esi::sim {

// AL states as the AL control and status registers code them: the protocol layer's.
using AlState = ethercat::AlState;

// Object access bits of an SDO Information entry description (ETG.1000.6 5.6.3.6.3).
namespace access_bit {
inline constexpr std::uint16_t read_preop = 0x0001;
inline constexpr std::uint16_t read_safeop = 0x0002;
inline constexpr std::uint16_t read_op = 0x0004;
inline constexpr std::uint16_t write_preop = 0x0008;
inline constexpr std::uint16_t write_safeop = 0x0010;
inline constexpr std::uint16_t write_op = 0x0020;
inline constexpr std::uint16_t rx_mappable = 0x0040;
inline constexpr std::uint16_t tx_mappable = 0x0080;
inline constexpr std::uint16_t backup = 0x0100;
inline constexpr std::uint16_t setting = 0x0200;
inline constexpr std::uint16_t read_all = read_preop | read_safeop | read_op;
inline constexpr std::uint16_t write_all = write_preop | write_safeop | write_op;
}  // namespace access_bit

// Object codes of an object description (ETG.1000.6 5.6.3.5.2).
namespace object_code {
inline constexpr std::uint8_t var = 7;
inline constexpr std::uint8_t array = 8;
inline constexpr std::uint8_t record = 9;
}  // namespace object_code

struct CoeEntry {
    std::uint8_t subindex = 0;
    std::string name;
    std::uint16_t data_type = 0;          // CoE data type code (0 when the type is not basic)
    const BasicType* basic = nullptr;     // nullptr when the type is not basic
    std::uint32_t bit_size = 0;
    std::uint32_t bit_offset = 0;         // within the object's complete-access stream
    std::uint16_t access = 0;             // access_bit
    std::vector<std::uint8_t> value;      // ceil(bit_size / 8) bytes, little-endian
    std::vector<std::uint8_t> default_value;

    [[nodiscard]] bool readable(AlState state) const;
    [[nodiscard]] bool writable(AlState state) const;
    [[nodiscard]] bool readable_somewhere() const { return (access & access_bit::read_all) != 0; }
    [[nodiscard]] bool writable_somewhere() const { return (access & access_bit::write_all) != 0; }
    // Strings and octet strings may be written shorter than their size.
    [[nodiscard]] bool variable_length() const;
    [[nodiscard]] std::size_t byte_size() const { return (bit_size + 7u) / 8u; }
    // The value as an unsigned number (the first 8 bytes, little-endian).
    [[nodiscard]] std::uint64_t unsigned_value() const;
    void set_unsigned(std::uint64_t number);
};

struct CoeObject {
    std::uint16_t index = 0;
    std::uint8_t code = object_code::var;
    std::uint16_t data_type = 0;
    std::string name;
    std::vector<CoeEntry> entries;  // sorted by sub-index; an ARRAY or RECORD starts at sub-index 0
    bool from_model = true;         // false: derived here, the model's Dictionary has no such object

    [[nodiscard]] CoeEntry* entry(std::uint32_t subindex);
    [[nodiscard]] const CoeEntry* entry(std::uint32_t subindex) const;
    [[nodiscard]] std::uint8_t max_subindex() const;
    // Bits of the complete-access stream from `first` (0 or 1) to the end of the last entry.
    [[nodiscard]] std::uint32_t complete_bits(std::uint8_t first) const;
};

class CoeDictionary {
public:
    [[nodiscard]] CoeObject* find(std::uint32_t index);
    [[nodiscard]] const CoeObject* find(std::uint32_t index) const;
    // Adds an object, keeping the table sorted by index; an object already there is kept.
    CoeObject& add(CoeObject object);
    [[nodiscard]] const std::vector<CoeObject>& objects() const { return objects_; }
    [[nodiscard]] std::vector<CoeObject>& objects() { return objects_; }
    // Every value back to its default (a device's power-on state).
    void reset_values();

private:
    std::vector<CoeObject> objects_;  // sorted by index; lookups are binary searches
};

// Copies `bits` bits from `source` at bit `from` to `target` at bit `to` (LSB first, as
// EtherCAT lays out process data and complete-access streams).
void copy_bits(const std::uint8_t* source, std::size_t from, std::uint8_t* target, std::size_t to, std::size_t bits);

}  // namespace esi::sim
