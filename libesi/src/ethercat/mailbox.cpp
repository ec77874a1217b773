// Texts of mailbox error details and SDO abort codes (mailbox.hpp).

#include "esi/ethercat/mailbox.hpp"

#include <utility>

namespace esi::ethercat {

namespace {

constexpr std::pair<std::uint16_t, std::string_view> mailbox_errors[] = {
    {0x0001, "syntax of the mailbox header wrong"},
    {0x0002, "mailbox protocol not supported"},
    {0x0003, "channel field contains wrong value"},
    {0x0004, "service in the mailbox protocol not supported"},
    {0x0005, "mailbox protocol header wrong"},
    {0x0006, "length of the received mailbox data too short"},
    {0x0007, "mailbox protocol cannot be processed for lack of resources"},
    {0x0008, "length of the data inconsistent"},
};

// ETG.1000.6 Table 41.
constexpr std::pair<std::uint32_t, std::string_view> aborts[] = {
    {0x05030000, "toggle bit not changed"},
    {0x05040000, "SDO protocol timeout"},
    {0x05040001, "client/server command specifier not valid or unknown"},
    {0x05040005, "out of memory"},
    {0x06010000, "unsupported access to an object"},
    {0x06010001, "attempt to read a write-only object"},
    {0x06010002, "attempt to write a read-only object"},
    {0x06010003, "sub-index cannot be written, sub-index 0 must be 0 for write access"},
    {0x06010004, "complete access not supported for this object"},
    {0x06010005, "object length exceeds the mailbox size"},
    {0x06010006, "object mapped to an RxPDO, SDO download blocked"},
    {0x06020000, "the object does not exist in the object dictionary"},
    {0x06040041, "the object cannot be mapped into the PDO"},
    {0x06040042, "the number and length of the objects to be mapped would exceed the PDO length"},
    {0x06040043, "general parameter incompatibility"},
    {0x06040047, "general internal incompatibility in the device"},
    {0x06060000, "access failed due to a hardware error"},
    {0x06070010, "data type does not match, length of service parameter does not match"},
    {0x06070012, "data type does not match, length of service parameter too high"},
    {0x06070013, "data type does not match, length of service parameter too low"},
    {0x06090011, "sub-index does not exist"},
    {0x06090030, "value range of parameter exceeded"},
    {0x06090031, "value of parameter written too high"},
    {0x06090032, "value of parameter written too low"},
    {0x06090036, "maximum value is less than minimum value"},
    {0x08000000, "general error"},
    {0x08000020, "data cannot be transferred or stored to the application"},
    {0x08000021, "data cannot be transferred or stored to the application because of local control"},
    {0x08000022, "data cannot be transferred or stored to the application because of the present device state"},
    {0x08000023, "object dictionary dynamic generation fails or no object dictionary is present"},
};

}  // namespace

std::string_view mailbox_error_text(std::uint16_t detail) {
    for (const auto& [value, text] : mailbox_errors)
        if (value == detail) return text;
    return "unknown mailbox error";
}

std::string_view sdo_abort_text(std::uint32_t code) {
    for (const auto& [value, text] : aborts)
        if (value == code) return text;
    return "unknown abort code";
}

}  // namespace esi::ethercat
