#pragma once
// A sample device loaded for a test, with its model slave on a FakeEsc and a TestMaster.

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "esi/load/document.hpp"
#include "esi/sim/model_slave.hpp"
#include "sim_device/fake_esc.hpp"
#include "sim_device/test_master.hpp"

namespace esi::sim::test_bench {

struct LoadedSample {
    LoadedDocument loaded;
    const EtherCATInfo* info = nullptr;
    const Device* device = nullptr;
};

inline std::unique_ptr<LoadedSample> load_sample(const std::string& relative, std::size_t device_index = 0) {
    auto out = std::make_unique<LoadedSample>();
    out->loaded = load_document_file(std::string(ESI_SOURCE_DIR) + "/" + relative);
    if (!out->loaded.document || out->loaded.document->infos.empty()) return nullptr;
    out->info = &out->loaded.document->infos.front();
    if (device_index >= out->info->devices.size()) return nullptr;
    out->device = &out->info->devices[device_index];
    return out;
}

// Everything a test needs to talk to one simulated device.
struct Bench {
    std::unique_ptr<LoadedSample> sample;
    FakeEsc esc;
    std::unique_ptr<esc::SlaveStack> slave;
    Diagnostics diagnostics;
    std::unique_ptr<TestMaster> master;

    explicit Bench(const std::string& relative, ModelSlaveOptions options = {}) : sample(load_sample(relative)) {
        if (!sample) return;
        slave = make_model_slave(*sample->info, *sample->device, options, diagnostics);
        if (slave) master = std::make_unique<TestMaster>(esc, *slave, *sample->info, *sample->device);
    }
    [[nodiscard]] bool ready() const { return master != nullptr; }
};

// The fixtures' remappable device with its default mapping: 4 output bytes on SM2, 4 input bytes
// on SM3.
constexpr const char* remappable = "tests/sim_device/fixtures/remappable.yaml";

// `n` bytes of `v`, little-endian, as CoE carries values.
inline std::vector<std::uint8_t> le(std::uint64_t v, std::size_t n) {
    std::vector<std::uint8_t> out(n);
    for (std::size_t i = 0; i < n; ++i) out[i] = static_cast<std::uint8_t>(v >> (8 * i));
    return out;
}

inline std::uint16_t sm_start(TestMaster& m, unsigned n) { return m.sii_sms()->items.at(n).start_address; }

// PREOP, both process-data SMs set up for the default mapping, SAFEOP.
inline void to_safeop(TestMaster& m) {
    ASSERT_TRUE(m.to_preop());
    m.configure_process_sm(2, 4);
    m.configure_process_sm(3, 4);
    ASSERT_EQ(m.request_state(4), 4);
}

inline void to_op(TestMaster& m) {
    ASSERT_NO_FATAL_FAILURE(to_safeop(m));
    ASSERT_EQ(m.request_state(8), 8);
}

}  // namespace esi::sim::test_bench
