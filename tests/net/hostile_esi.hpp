#pragma once
// A small, complete ESI device for the esi-net hostile-input tests, with the values the tests
// make hostile as text (the attribute or element content exactly as written in the file).

#include <string>

namespace esi::test {

struct HostileDevice {
    std::string type = "Hostile";
    std::string name = "Hostile device";
    std::string vendor_id = "#x00000ABC";
    std::string product_code = "#x00001002";
    std::string revision = "#x00000001";
    std::string rx_bit_len = "8";
    std::string entry_name = "Out";
    std::string sm_start = "#x1000";
    std::string second_device_product_code = "#x00002002";  // a second device of the same file
    bool coe = false;  // a CoE mailbox (SM0/SM1), so that the network can give start-up SDOs

    [[nodiscard]] std::string xml() const;
};

}  // namespace esi::test
