// The process-data watchdog (0x0400, 0x0420, 0x0440, 0x0442): rewound by the master's writes into
// an SM with the watchdog trigger bit, run out when the writes stop, on the frames' clock.

#include <gtest/gtest.h>

#include "esi/ethercat/registers.hpp"
#include "sim_esc/frame_builder.hpp"

namespace esi::test {
namespace {

using esc::Command;

constexpr std::uint64_t ms = 1'000'000;

std::vector<std::uint8_t> sm_config(std::uint16_t start, std::uint16_t length, std::uint8_t control) {
    return {static_cast<std::uint8_t>(start), static_cast<std::uint8_t>(start >> 8), static_cast<std::uint8_t>(length),
            static_cast<std::uint8_t>(length >> 8), control, 0, 1, 0};
}

// One datagram in one frame at `time_ns`; returns the working counter.
std::uint16_t send(esc::Esc& a, Command command, std::uint16_t address, std::vector<std::uint8_t> data, std::uint64_t time_ns) {
    FrameBuilder f;
    f.add(command, 0, address, std::move(data));
    auto payload = f.bytes();
    EXPECT_EQ(run(payload, {&a}, time_ns), esc::FrameOutcome::answered);
    return f.wkc(payload, 0);
}

// An ESC with SM2 as 3-buffered outputs at 0x1100 (control `control`) and a watchdog of 10 ms
// (the default divider: 100 us per tick).
esc::Esc outputs_esc(std::uint8_t control) {
    esc::Esc a(eeprom_image(0x05));
    EXPECT_EQ(send(a, Command::apwr, ethercat::reg::watchdog_time_process_data, {100, 0}, 0), 1);
    EXPECT_EQ(send(a, Command::apwr, ethercat::reg::sm0 + 16, sm_config(0x1100, 2, control), 0), 1);
    return a;
}

bool expired(const esc::Esc& a) { return !(a.peek8(ethercat::reg::watchdog_status_process_data) & 1); }

TEST(EscWatchdog, PowerOnValuesAreTheDatasheets) {
    esc::Esc a(eeprom_image(0x05));
    EXPECT_EQ(a.peek16(ethercat::reg::watchdog_divider), 0x09C2);
    EXPECT_EQ(a.peek16(ethercat::reg::watchdog_time_pdi), 1000);
    EXPECT_EQ(a.peek16(ethercat::reg::watchdog_time_process_data), 1000);
    EXPECT_FALSE(expired(a));
    EXPECT_EQ(a.peek8(ethercat::reg::watchdog_counter_process_data), 0);
}

TEST(EscWatchdog, WritesWithinTheTimeKeepItAliveAndSilenceExpiresIt) {
    esc::Esc a = outputs_esc(0x64);
    for (std::uint64_t t = 1 * ms; t <= 50 * ms; t += 1 * ms) {  // a 1 ms cycle over five watchdog times
        ASSERT_EQ(send(a, Command::apwr, 0x1100, {1, 2}, t), 1);
        ASSERT_FALSE(expired(a)) << "at " << t / ms << " ms";
    }
    EXPECT_EQ(send(a, Command::aprd, 0x0130, {0, 0}, 59 * ms), 1);  // 9 ms after the last write
    EXPECT_FALSE(expired(a));
    EXPECT_EQ(a.al_event() & ethercat::reg::al_event_watchdog_process_data, 0u);
    EXPECT_EQ(send(a, Command::aprd, ethercat::reg::watchdog_status_process_data, {0xFF, 0xFF}, 60 * ms), 1);  // 10 ms
    EXPECT_TRUE(expired(a));
    EXPECT_EQ(a.peek8(ethercat::reg::watchdog_counter_process_data), 1);
    EXPECT_NE(a.al_event() & ethercat::reg::al_event_watchdog_process_data, 0u);
    // An expiry is counted once, however long the silence lasts.
    EXPECT_EQ(send(a, Command::aprd, 0x0130, {0, 0}, 200 * ms), 1);
    EXPECT_EQ(a.peek8(ethercat::reg::watchdog_counter_process_data), 1);
    // The PDI reading the status acknowledges the event; the status stays until the next write.
    std::uint8_t got[2]{};
    a.read(ethercat::reg::watchdog_status_process_data, got);
    EXPECT_EQ(got[0] & 1, 0);
    EXPECT_EQ(a.al_event() & ethercat::reg::al_event_watchdog_process_data, 0u);
    EXPECT_EQ(send(a, Command::apwr, 0x1100, {3, 4}, 201 * ms), 1);
    EXPECT_FALSE(expired(a));
}

TEST(EscWatchdog, TheExpiryShowsInTheFrameThatFindsIt) {
    esc::Esc a = outputs_esc(0x64);
    ASSERT_EQ(send(a, Command::apwr, 0x1100, {1, 2}, 1 * ms), 1);
    FrameBuilder f;
    f.add(Command::aprd, 0, ethercat::reg::watchdog_status_process_data, {0xFF, 0xFF});
    auto payload = f.bytes();
    ASSERT_EQ(run(payload, {&a}, 30 * ms), esc::FrameOutcome::answered);
    EXPECT_EQ(f.data(payload, 0)[0] & 1, 0);
}

TEST(EscWatchdog, OnlySmsWithTheTriggerBitAreWatched) {
    esc::Esc a = outputs_esc(0x24);  // outputs without the watchdog trigger
    ASSERT_EQ(send(a, Command::apwr, 0x1100, {1, 2}, 1 * ms), 1);
    EXPECT_EQ(send(a, Command::aprd, 0x0130, {0, 0}, 500 * ms), 1);
    EXPECT_FALSE(expired(a));
    EXPECT_EQ(a.peek8(ethercat::reg::watchdog_counter_process_data), 0);
}

TEST(EscWatchdog, TimeZeroDisablesItAndNothingRunsBeforeTheFirstTrigger) {
    esc::Esc a = outputs_esc(0x64);
    EXPECT_EQ(send(a, Command::aprd, 0x0130, {0, 0}, 500 * ms), 1);  // never written: not started
    EXPECT_FALSE(expired(a));
    ASSERT_EQ(send(a, Command::apwr, ethercat::reg::watchdog_time_process_data, {0, 0}, 501 * ms), 1);
    ASSERT_EQ(send(a, Command::apwr, 0x1100, {1, 2}, 502 * ms), 1);
    EXPECT_EQ(send(a, Command::aprd, 0x0130, {0, 0}, 900 * ms), 1);
    EXPECT_FALSE(expired(a));
}

TEST(EscWatchdog, WritingTheErrorCountersClearsTheExpiryCounter) {
    esc::Esc a = outputs_esc(0x64);
    ASSERT_EQ(send(a, Command::apwr, 0x1100, {1, 2}, 1 * ms), 1);
    EXPECT_EQ(send(a, Command::aprd, 0x0130, {0, 0}, 20 * ms), 1);
    ASSERT_EQ(a.peek8(ethercat::reg::watchdog_counter_process_data), 1);
    EXPECT_EQ(send(a, Command::apwr, ethercat::reg::error_counters, {0, 0}, 21 * ms), 1);
    EXPECT_EQ(a.peek8(ethercat::reg::watchdog_counter_process_data), 0);
}

TEST(EscWatchdog, TheMasterCannotWriteTheStatusOrTheCounter) {
    esc::Esc a = outputs_esc(0x64);
    ASSERT_EQ(send(a, Command::apwr, 0x1100, {1, 2}, 1 * ms), 1);
    EXPECT_EQ(send(a, Command::aprd, 0x0130, {0, 0}, 20 * ms), 1);
    EXPECT_EQ(send(a, Command::apwr, ethercat::reg::watchdog_status_process_data, {1, 0, 0}, 21 * ms), 1);
    EXPECT_TRUE(expired(a));
    EXPECT_EQ(a.peek8(ethercat::reg::watchdog_counter_process_data), 1);
}

}  // namespace
}  // namespace esi::test
