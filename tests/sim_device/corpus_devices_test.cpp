// Catalogue devices from the corpus, run from their ESI alone on the model slave: brought to OP
// the way SOEM configures a slave (the device's own CoE InitCmds for IP and PS sent in PREOP) (mailbox from the SII header, the PDO sizes read over CoE from
// 0x1C00, 0x1C1n and the mapping objects, else from the SII's PDO categories), their dictionary
// read completely over SDO (every readable entry answers with its size). Devices that cannot reach OP are listed with the AL status code.

#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>
#include <map>

#include "esi/device_selector.hpp"
#include "esi/model/object_layout.hpp"
#include "esi/sii/build.hpp"
#include "sim_device/sample_device.hpp"

namespace esi::sim::test_bench {
namespace {

namespace fs = std::filesystem;

std::uint64_t le(const std::vector<std::uint8_t>& b) {
    std::uint64_t v = 0;
    for (std::size_t i = 0; i < b.size() && i < 8; ++i) v |= std::uint64_t{b[i]} << (8 * i);
    return v;
}

// The bits SOEM's ecx_readPDOmap finds for SM n over CoE (assignment, then each mapping).
std::optional<std::uint32_t> coe_sm_bits(TestMaster& m, unsigned n) {
    const SdoResult count = m.upload(static_cast<std::uint16_t>(0x1C10 + n), 0);
    if (count.abort) return std::nullopt;
    std::uint32_t bits = 0;
    for (std::uint64_t i = 1; i <= le(count.data); ++i) {
        const SdoResult pdo = m.upload(static_cast<std::uint16_t>(0x1C10 + n), static_cast<std::uint8_t>(i));
        if (pdo.abort) return std::nullopt;
        const auto index = static_cast<std::uint16_t>(le(pdo.data));
        const SdoResult entries = m.upload(index, 0);
        if (entries.abort) return std::nullopt;
        for (std::uint64_t k = 1; k <= le(entries.data); ++k) {
            const SdoResult e = m.upload(index, static_cast<std::uint8_t>(k));
            if (e.abort) return std::nullopt;
            bits += static_cast<std::uint32_t>(le(e.data) & 0xFF);
        }
    }
    return bits;
}

// Brings the device to OP; empty when it got there, else why not.
std::string run_to_op(const EtherCATInfo& info, const Device& device) {
    FakeEsc esc;
    Diagnostics diagnostics;
    auto slave = make_model_slave(info, device, {}, diagnostics);
    if (!slave) return "no slave: " + (diagnostics.begin() == diagnostics.end() ? std::string("?") : diagnostics.begin()->message);
    TestMaster m(esc, *slave, info, device);
    const sii::SyncManagers* sms = m.sii_sms();
    const bool mailbox = m.mailbox_out_size() > 0 && m.mailbox_in_size() > 0 && device.mailbox;
    if (mailbox) {
        m.configure_mailbox();
        if ((m.request_state(2) & 0x1F) != 2) return "PREOP refused, code " + std::to_string(m.al_status_code());
    } else if ((m.request_state(2) & 0x1F) != 2) {
        return "PREOP refused, code " + std::to_string(m.al_status_code());
    }
    // The device's own CoE InitCmds for IP and PS, as a master sends them.
    if (mailbox && device.mailbox->coe)
        for (const InitCmd& cmd : device.mailbox->coe->init_cmds) {
            const bool due = std::any_of(cmd.transitions.begin(), cmd.transitions.end(),
                                         [](const Transition& t) { return t.text == "IP" || t.text == "PS"; });
            const auto data = cmd.data.bytes();
            if (!due || !cmd.index || !data || data->empty() || *cmd.index > 0xFFFF) continue;
            const std::uint32_t abort = m.download(static_cast<std::uint16_t>(*cmd.index),
                                                   static_cast<std::uint8_t>(cmd.subindex.value_or(0)), *data,
                                                   cmd.complete_access.value_or(false));
            if (abort) {
                char what[80];
                std::snprintf(what, sizeof what, "InitCmd 0x%04X:%u refused, abort 0x%08X", static_cast<unsigned>(*cmd.index),
                              static_cast<unsigned>(cmd.subindex.value_or(0)), abort);
                return what;
            }
        }
    if (sms) {
        for (unsigned n = 0; n < sms->items.size(); ++n) {
            const std::uint8_t type = sms->items[n].type;
            if (type != 3 && type != 4) continue;
            std::optional<std::uint32_t> bits;
            // SOEM reads the PDO configuration over CoE only when 0x1C00 lists more than the
            // mailbox SMs.
            if (mailbox && device.mailbox->coe) {
                const SdoResult sm_types = m.upload(0x1C00, 0);
                if (!sm_types.abort && le(sm_types.data) > 2) bits = coe_sm_bits(m, n);
            }
            if (!bits) {
                // SII: the PDOs of the category assigned to this SM.
                bits = 0;
                for (const auto* list : {&device.rx_pdos, &device.tx_pdos})
                    for (const Pdo& p : *list)
                        if (p.sm && *p.sm == n) *bits += static_cast<std::uint32_t>(p.bit_size());
            }
            m.configure_process_sm(n, static_cast<std::uint16_t>((*bits + 7) / 8));
        }
    }
    if ((m.request_state(4) & 0x1F) != 4) return "SAFEOP refused, code " + std::to_string(m.al_status_code());
    if ((m.request_state(8) & 0x1F) != 8) return "OP refused, code " + std::to_string(m.al_status_code());
    // Every readable entry of the dictionary answers with its size.
    if (const Dictionary* dictionary = device.dictionary(); dictionary && mailbox && device.mailbox->coe) {
        const DataTypeIndex types(dictionary);
        std::size_t read = 0;
        for (const Object& object : dictionary->objects) {
            // A bounded share of each dictionary keeps the test's run time small.
            if (object.index > 0xFFFF || ++read > 120) continue;
            for (const ObjectEntry& entry : layout_of(types, object).entries) {
                if (entry.subindex > 255) continue;
                const SdoResult r = m.upload(static_cast<std::uint16_t>(object.index), static_cast<std::uint8_t>(entry.subindex));
                const std::string access = entry.flags && entry.flags->access ? *entry.flags->access : "ro";
                const bool readable_in_op = access != "wo" && !(entry.flags && entry.flags->access_read_restrictions &&
                                                                entry.flags->access_read_restrictions->find("OP") == std::string::npos);
                if (!readable_in_op) continue;
                if (r.abort || r.data.size() != (entry.bit_size + 7) / 8) {
                    char where[64];
                    std::snprintf(where, sizeof where, "0x%04X:%u abort 0x%08X", static_cast<unsigned>(object.index),
                                  static_cast<unsigned>(entry.subindex), r.abort);
                    return std::string("SDO read of ") + where;
                }
            }
        }
    }
    return {};
}

TEST(CorpusDevices, CatalogueDevicesReachOp) {
    const fs::path corpus = fs::path(ESI_SHARED_DIR) / "corpus" / "esi";
    if (!fs::is_directory(corpus)) GTEST_SKIP() << "no corpus at " << corpus << " (the shared data is absent)";
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(corpus))
        if (e.path().extension() == ".xml") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    std::size_t tried = 0, reached = 0;
    std::map<std::string, std::string> failures;
    for (const fs::path& file : files) {
        if (fs::file_size(file) > 600'000) continue;  // keep the test's run time small
        LoadedDocument loaded = load_document_file(file);
        if (!loaded.document) continue;
        const std::vector<const Device*> devices = select_devices(*loaded.document, std::nullopt);
        // The first and the last device of each file.
        const std::size_t step = std::max<std::size_t>(1, devices.size() - 1);
        for (std::size_t i = 0; i < devices.size(); i += step) {
            const Device& device = *devices[i];
            const EtherCATInfo* info = loaded.document->info_of(device);
            if (!info) continue;
            ++tried;
            const std::string why = run_to_op(*info, device);
            if (why.empty()) ++reached;
            else failures[file.filename().string() + " " + device.type.text] = why;
        }
    }
    for (const auto& [device, why] : failures) std::cout << "  not in OP: " << device << ": " << why << "\n";
    std::cout << reached << " of " << tried << " devices reached OP\n";
    EXPECT_GE(reached, 25u);
}

}  // namespace
}  // namespace esi::sim::test_bench
