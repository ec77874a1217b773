// A hostile master: random frames, and valid frames with random bytes changed, through a line of
// ESCs with a firmware polled after each, never crash, never change a frame's size and never
// grow the EEPROM past what its address bytes reach. (The fuzz target explores further; this runs
// in every test run, under the sanitizers in CI.)

#include <gtest/gtest.h>

#include <random>

#include "esi/ethercat/registers.hpp"
#include "sim_esc/frame_builder.hpp"

namespace esi::test {
namespace {

using esc::Command;

// A firmware that answers AL control and echoes a mailbox back, driving the PDI side as well.
class EchoStack final : public esc::SlaveStack {
public:
    void poll(esc::Pdi& pdi) override {
        std::uint8_t control[2]{};
        pdi.read(ethercat::reg::al_control, control);
        pdi.write(ethercat::reg::al_status, std::span<const std::uint8_t>(control, 1));
        std::uint8_t mailbox[16]{};
        pdi.read(0x1000, mailbox);
        pdi.write(0x1080, mailbox);
        pdi.write(0x1400, mailbox);
        pdi.read(0x1100, mailbox);
    }
};

TEST(HostileFrames, RandomAndMutatedFramesNeverCrashOrResizeTheFrame) {
    std::mt19937 random(20);
    esc::Esc a(eeprom_image(0x05)), b(eeprom_image(0x05));
    EchoStack stack;
    FrameBuilder setup;
    setup.add(Command::bwr, 0, ethercat::reg::sm0,
              {0x00, 0x10, 16, 0, 0x26, 0, 1, 0, 0x80, 0x10, 16, 0, 0x22, 0, 1, 0, 0x00, 0x11, 4, 0, 0x64, 0, 1, 0});
    auto payload = setup.bytes();
    ASSERT_EQ(run(payload, {&a, &b}), esc::FrameOutcome::answered);

    FrameBuilder valid;
    valid.add(Command::fpwr, 0, 0x1000, std::vector<std::uint8_t>(16, 0x11));
    valid.add(Command::lrw, 0, 0, std::vector<std::uint8_t>(8, 0));
    valid.add(Command::apwr, 0, ethercat::reg::eeprom_control, {0x01, 0x02, 0x00, 0x10, 0x00, 0x00});
    valid.add(Command::brw, 0, 0x0600, std::vector<std::uint8_t>(32, 0xFF));
    const auto template_frame = valid.bytes();

    for (int i = 0; i < 20000; ++i) {
        std::vector<std::uint8_t> frame;
        if (i % 2) {
            frame.resize(random() % 300);
            for (auto& byte : frame) byte = static_cast<std::uint8_t>(random());
            if (frame.size() >= 2 && i % 4 == 1) frame[1] = static_cast<std::uint8_t>((frame[1] & 0x0F) | 0x10);
        } else {
            frame = template_frame;
            for (int k = 0; k < 4; ++k) frame[random() % frame.size()] = static_cast<std::uint8_t>(random());
        }
        const std::size_t size = frame.size();
        (void)run(frame, {&a, &b}, 1000u * static_cast<unsigned>(i));
        ASSERT_EQ(frame.size(), size);
        stack.poll(a);
        stack.poll(b);
    }
    EXPECT_LE(a.eeprom().size(), 0x20000u);
    EXPECT_LE(b.eeprom().size(), 0x20000u);
}

}  // namespace
}  // namespace esi::test
