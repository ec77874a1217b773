// The protocol layer's mailbox facts: abort code and mailbox error texts (ETG.1000.6 Table 41,
// ETG.1000.4 mailbox error reply).

#include <gtest/gtest.h>

#include "esi/ethercat/mailbox.hpp"

namespace esi::ethercat {
namespace {

TEST(SdoAborts, KnownCodesHaveTheirTextUnknownOnesSaySo) {
    EXPECT_EQ(sdo_abort_text(sdo_abort::object_missing), "the object does not exist in the object dictionary");
    EXPECT_EQ(sdo_abort_text(sdo_abort::subindex_missing), "sub-index does not exist");
    EXPECT_EQ(sdo_abort_text(sdo_abort::device_state),
              "data cannot be transferred or stored to the application because of the present device state");
    EXPECT_EQ(sdo_abort_text(0x12345678), "unknown abort code");
}

TEST(MailboxErrors, KnownDetailsHaveTheirTextUnknownOnesSaySo) {
    EXPECT_EQ(mailbox_error_text(mailbox_error::service_not_supported), "service in the mailbox protocol not supported");
    EXPECT_EQ(mailbox_error_text(mailbox_error::invalid_size), "length of the data inconsistent");
    EXPECT_EQ(mailbox_error_text(0x0042), "unknown mailbox error");
}

}  // namespace
}  // namespace esi::ethercat
