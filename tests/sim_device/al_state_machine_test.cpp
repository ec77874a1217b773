// The AL state machine of the model slave: transitions, the checks on the way up and their AL
// status codes (ETG.1000.6 6.4, Table 11).

#include <gtest/gtest.h>

#include "sim_device/sample_device.hpp"

namespace esi::sim::test_bench {
namespace {

constexpr std::uint16_t init = 1, preop = 2, boot = 3, safeop = 4, op = 8, error_bit = 0x10, ack = 0x10;

TEST(AlStateMachine, StartsInInitWithoutError) {
    Bench b("samples/digital-io-8.yaml");
    ASSERT_TRUE(b.ready());
    EXPECT_EQ(b.master->al_status(), init);
    EXPECT_EQ(b.master->al_status_code(), 0);
}

TEST(AlStateMachine, InitToPreopWithTheSiiMailbox) {
    Bench b("samples/digital-io-8.yaml");
    ASSERT_TRUE(b.ready());
    EXPECT_TRUE(b.master->to_preop());
    EXPECT_EQ(b.master->al_status_code(), 0);
}

TEST(AlStateMachine, WrongMailboxLengthIsRefusedWith0x0016) {
    Bench b("samples/digital-io-8.yaml");
    ASSERT_TRUE(b.ready());
    b.master->configure_mailbox();
    const auto& sm = b.master->sii_sms()->items[0];
    b.esc.configure_sm(0, sm.start_address, static_cast<std::uint16_t>(sm.length - 2), sm.control, true);
    EXPECT_EQ(b.master->request_state(preop), init | error_bit);
    EXPECT_EQ(b.master->al_status_code(), 0x0016);
}

TEST(AlStateMachine, DisabledMailboxIsRefusedWith0x0016) {
    Bench b("samples/digital-io-8.yaml");
    ASSERT_TRUE(b.ready());
    b.master->configure_mailbox();
    const auto& sm = b.master->sii_sms()->items[1];
    b.esc.configure_sm(1, sm.start_address, sm.length, sm.control, false);
    EXPECT_EQ(b.master->request_state(preop), init | error_bit);
    EXPECT_EQ(b.master->al_status_code(), 0x0016);
}

TEST(AlStateMachine, ErrorStaysUntilAcknowledged) {
    Bench b("samples/digital-io-8.yaml");
    ASSERT_TRUE(b.ready());
    EXPECT_EQ(b.master->request_state(op), init | error_bit);  // INIT -> OP does not exist
    EXPECT_EQ(b.master->al_status_code(), 0x0011);
    b.master->configure_mailbox();
    // Without the acknowledge bit the request for a higher state is not acted on.
    EXPECT_EQ(b.master->request_state(preop), init | error_bit);
    EXPECT_EQ(b.master->request_state(preop | ack), preop);
    EXPECT_EQ(b.master->al_status_code(), 0);
}

TEST(AlStateMachine, InvalidTransitionsGive0x0011) {
    Bench b("samples/digital-io-8.yaml");
    ASSERT_TRUE(b.ready());
    EXPECT_EQ(b.master->request_state(safeop), init | error_bit);
    EXPECT_EQ(b.master->al_status_code(), 0x0011);
    EXPECT_EQ(b.master->request_state(init | ack), init);
    ASSERT_TRUE(b.master->to_preop());
    EXPECT_EQ(b.master->request_state(op), preop | error_bit);
    EXPECT_EQ(b.master->al_status_code(), 0x0011);
}

TEST(AlStateMachine, UnknownStateGives0x0012) {
    Bench b("samples/digital-io-8.yaml");
    ASSERT_TRUE(b.ready());
    EXPECT_EQ(b.master->request_state(5), init | error_bit);
    EXPECT_EQ(b.master->al_status_code(), 0x0012);
    EXPECT_EQ(b.master->request_state(0x0F), init | error_bit);
    EXPECT_EQ(b.master->al_status_code(), 0x0012);
}

TEST(AlStateMachine, BootNeedsTheBootstrapMailbox) {
    Bench b("samples/digital-io-8.yaml");  // declares a bootstrap mailbox at 0x1000/0x1080
    ASSERT_TRUE(b.ready());
    b.esc.configure_sm(0, 0x1000, 128, 0x26, true);
    b.esc.configure_sm(1, 0x1080, 128, 0x22, true);
    EXPECT_EQ(b.master->request_state(boot), boot);
    EXPECT_EQ(b.master->request_state(preop), boot | error_bit);  // BOOT -> PREOP does not exist
    EXPECT_EQ(b.master->al_status_code(), 0x0011);
    EXPECT_EQ(b.master->request_state(init | ack), init);
}

// The sample's process data: 1 byte of outputs on SM2, 1 byte of inputs on SM3.
TEST(AlStateMachine, SafeopNeedsProcessDataSmsOfTheMappedLength) {
    Bench b("samples/digital-io-8.yaml");
    ASSERT_TRUE(b.ready());
    ASSERT_TRUE(b.master->to_preop());
    b.master->configure_process_sm(2, 2);
    b.master->configure_process_sm(3, 1);
    EXPECT_EQ(b.master->request_state(safeop), preop | error_bit);
    EXPECT_EQ(b.master->al_status_code(), 0x001D);
    b.master->configure_process_sm(2, 1);
    b.master->configure_process_sm(3, 0);
    EXPECT_EQ(b.master->request_state(safeop | ack), preop | error_bit);
    EXPECT_EQ(b.master->al_status_code(), 0x001E);
    b.master->configure_process_sm(3, 1);
    EXPECT_EQ(b.master->request_state(safeop | ack), safeop);
    EXPECT_EQ(b.master->request_state(op), op);
    EXPECT_EQ(b.master->request_state(safeop), safeop);
    EXPECT_EQ(b.master->request_state(preop), preop);
    EXPECT_EQ(b.master->request_state(init), init);
}

TEST(AlStateMachine, ProcessDataSmAtAnotherAddressGives0x0017) {
    Bench b("samples/digital-io-8.yaml");
    ASSERT_TRUE(b.ready());
    ASSERT_TRUE(b.master->to_preop());
    const auto& sm2 = b.master->sii_sms()->items[2];
    b.esc.configure_sm(2, static_cast<std::uint16_t>(sm2.start_address + 0x100), 1, sm2.control, true);
    b.master->configure_process_sm(3, 1);
    EXPECT_EQ(b.master->request_state(safeop), preop | error_bit);
    EXPECT_EQ(b.master->al_status_code(), 0x0017);
}

TEST(AlStateMachine, DcActivationTheDeviceDoesNotOfferGives0x0030) {
    Bench b("samples/digital-io-8.yaml");  // op modes: free run 0x0000 and SYNC0 0x0300
    ASSERT_TRUE(b.ready());
    ASSERT_TRUE(b.master->to_preop());
    b.master->configure_process_sm(2, 1);
    b.master->configure_process_sm(3, 1);
    b.esc.master_write_u16(0x0980, 0x0700);  // SYNC0 and SYNC1
    EXPECT_EQ(b.master->request_state(safeop), preop | error_bit);
    EXPECT_EQ(b.master->al_status_code(), 0x0030);
    b.esc.master_write_u16(0x0980, 0x0300);  // SYNC0, but no cycle time
    EXPECT_EQ(b.master->request_state(safeop | ack), preop | error_bit);
    EXPECT_EQ(b.master->al_status_code(), 0x0035);
    b.esc.master_write_u16(0x09A0, 0x4240);
    b.esc.master_write_u16(0x09A2, 0x000F);  // 1 ms
    EXPECT_EQ(b.master->request_state(safeop | ack), safeop);
}

TEST(AlStateMachine, DeviceIdentificationShowsTheAlias) {
    Bench b("samples/digital-io-8.yaml");
    ASSERT_TRUE(b.ready());
    b.esc.master_write_u16(0x0012, 0x1234);
    EXPECT_EQ(b.master->request_state(init | 0x20), init | 0x20);
    EXPECT_EQ(b.master->al_status_code(), 0x1234);
}

}  // namespace
}  // namespace esi::sim::test_bench
