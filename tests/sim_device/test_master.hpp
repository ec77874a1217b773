#pragma once
// The test's master: AL state requests, the mailbox (header and counter) and SDO transfers the
// way SOEM's ecx_SDOread/ecx_SDOwrite run them, over a FakeEsc and a slave stack polled after
// every access, as the emulator polls it after every frame.

#include <cstdint>
#include <optional>
#include <vector>

#include "esi/esc/pdi.hpp"
#include "esi/model/ethercat_info.hpp"
#include "esi/sii/build.hpp"
#include "sim_device/fake_esc.hpp"

namespace esi::sim::test_bench {

struct SdoResult {
    std::uint32_t abort = 0;
    std::vector<std::uint8_t> data;
};

class TestMaster {
public:
    TestMaster(FakeEsc& esc, esc::SlaveStack& slave, const EtherCATInfo& info, const Device& device);

    void poll(int times = 1);
    // Writes AL control, lets the slave react, returns AL status.
    std::uint16_t request_state(std::uint16_t control);
    [[nodiscard]] std::uint16_t al_status() const { return esc_.u16(0x0130); }
    [[nodiscard]] std::uint16_t al_status_code() const { return esc_.u16(0x0134); }

    // SM0/SM1 as the SII says (what SOEM does in ecx_config_init).
    void configure_mailbox();
    // SM n (a process-data SM of the SII) with `length` bytes, enabled when length > 0.
    void configure_process_sm(unsigned n, std::uint16_t length);
    // INIT -> PREOP with the mailbox configured; true when the slave is in PREOP.
    bool to_preop();

    // One mailbox request (payload after the header) and the whole answer buffer, or nothing
    // when the slave did not answer within a few polls.
    std::optional<std::vector<std::uint8_t>> exchange(std::uint8_t type, const std::vector<std::uint8_t>& payload,
                                                      std::optional<std::uint8_t> counter = std::nullopt);
    std::optional<std::vector<std::uint8_t>> read_answer();
    void write_request(std::uint8_t type, const std::vector<std::uint8_t>& payload, std::optional<std::uint8_t> counter);

    SdoResult upload(std::uint16_t index, std::uint8_t subindex, bool complete = false);
    std::uint32_t download(std::uint16_t index, std::uint8_t subindex, const std::vector<std::uint8_t>& data,
                           bool complete = false);
    // A download that always goes segmented after an initiate frame carrying no data.
    std::uint32_t download_segmented(std::uint16_t index, std::uint8_t subindex, const std::vector<std::uint8_t>& data);

    [[nodiscard]] const sii::SyncManagers* sii_sms() const { return image_.image.sync_managers(); }
    [[nodiscard]] std::uint16_t mailbox_out_size() const { return image_.image.header.standard_receive_size; }
    [[nodiscard]] std::uint16_t mailbox_in_size() const { return image_.image.header.standard_send_size; }
    FakeEsc& esc() { return esc_; }

private:
    FakeEsc& esc_;
    esc::SlaveStack& slave_;
    sii::BuildResult image_;
    std::uint8_t counter_ = 0;
};

}  // namespace esi::sim::test_bench
