// Code generation speed: a synthetic device with 5,000 objects (VAR objects of every common
// type plus RECORDs, with defaults and limits, and PDOs mapping part of them) through every
// output kind, in memory (writing files is the atomic writer's business). Prints the time of
// each stage; the target for the whole run is under 200 ms on one core (issue 3, section 5).
//
//   ./build/bench/codegen_5000 [iterations]
//   ./build/bench/codegen_5000 --once    one generation of every output and nothing else, for
//                                        valgrind --tool=callgrind (instruction counts are steadier
//                                        than times on a loaded machine)

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

#include "esi/codegen/generate.hpp"
#include "esi/codegen/model_view.hpp"
#include "esi/codegen/template_lookup.hpp"

namespace {

using Clock = std::chrono::steady_clock;

esi::Object var_object(std::uint32_t index, const char* type, std::uint64_t bits, bool mappable) {
    esi::Object o;
    o.index = index;
    o.names.push_back({"Parameter " + std::to_string(index), 1033, {}});
    o.type = type;
    o.bit_size = bits;
    o.info.emplace();
    o.info->default_value = esi::Number::from_unsigned(index & 0x7F);
    o.info->min_value = esi::Number::from_unsigned(0);
    o.info->max_value = esi::Number::from_unsigned(100);
    o.flags.emplace();
    o.flags->access = "rw";
    if (mappable) o.flags->pdo_mapping = "T";
    return o;
}

esi::EsiDocument synthetic_document(std::size_t object_count) {
    esi::EsiDocument doc;
    doc.kind = esi::DocumentKind::ethercat_info;
    doc.path = "synthetic-5000.xml";
    esi::EtherCATInfo info;
    info.vendor.emplace();
    info.vendor->id = 0x0E4A;
    info.vendor->names.push_back({"Benchmark vendor", 1033, {}});
    esi::Device device;
    device.type.text = "BENCH-5000";
    device.type.product_code = 0x5000;
    device.type.revision_no = 1;
    device.names.push_back({"Benchmark device with 5000 objects", 1033, {}});
    esi::Profile profile;
    profile.dictionary.emplace();
    esi::Dictionary& dict = *profile.dictionary;

    // A RECORD type with four entries, used by every fifth object.
    esi::DataType record;
    record.name = "DT_REC";
    record.bit_size = 112;
    const char* types[] = {"USINT", "UINT", "DINT", "REAL"};
    const std::uint64_t sizes[] = {8, 16, 32, 32};
    std::uint64_t offset = 16;
    esi::DataTypeSubItem count;
    count.subindex = 0;
    count.name = "Number of entries";
    count.type = "USINT";
    count.bit_size = 8;
    record.sub_items.push_back(count);
    for (std::uint32_t k = 0; k < 4; ++k) {
        esi::DataTypeSubItem item;
        item.subindex = k + 1;
        item.name = "Field " + std::to_string(k + 1);
        item.type = types[k];
        item.bit_size = sizes[k];
        item.bit_offset = offset;
        offset += sizes[k];
        record.sub_items.push_back(item);
    }
    dict.data_types.push_back(record);

    const char* var_types[] = {"UINT", "DINT", "USINT", "UDINT", "INT", "REAL", "BOOL", "LINT"};
    const std::uint64_t var_sizes[] = {16, 32, 8, 32, 16, 32, 1, 64};
    for (std::size_t k = 0; k < object_count; ++k) {
        const std::uint32_t index = 0x2000 + static_cast<std::uint32_t>(k);
        if (k % 5 == 4) {
            esi::Object o;
            o.index = index;
            o.names.push_back({"Record " + std::to_string(k), 1033, {}});
            o.type = "DT_REC";
            o.bit_size = 112;
            o.flags.emplace();
            o.flags->access = "ro";
            dict.objects.push_back(std::move(o));
        } else {
            dict.objects.push_back(var_object(index, var_types[k % 8], var_sizes[k % 8], k < 64));
        }
    }
    device.profiles.push_back(std::move(profile));

    auto sm = [](const char* type, std::uint32_t address, std::uint32_t control, std::uint32_t size) {
        esi::SyncManager s;
        s.type = type;
        s.start_address = address;
        s.control_byte = control;
        s.default_size = size;
        s.enable = 1;
        return s;
    };
    device.sms = {sm("MBoxOut", 0x1000, 0x26, 128), sm("MBoxIn", 0x1080, 0x22, 128), sm("Outputs", 0x1100, 0x64, 0),
                  sm("Inputs", 0x1400, 0x20, 0)};
    // Four TxPDOs mapping the first 64 objects.
    for (std::uint32_t p = 0; p < 4; ++p) {
        esi::Pdo pdo;
        pdo.direction = esi::PdoDirection::tx;
        pdo.index = 0x1A00 + p;
        pdo.sm = 3;
        pdo.names.push_back({"Inputs " + std::to_string(p), 1033, {}});
        for (std::uint32_t e = 0; e < 16; ++e) {
            const std::size_t k = p * 16 + e;
            if (k % 5 == 4) continue;
            esi::PdoEntry entry;
            entry.index = 0x2000 + static_cast<std::uint32_t>(k);
            entry.bit_len = static_cast<std::uint32_t>(var_sizes[k % 8]);
            entry.data_type = var_types[k % 8];
            entry.names.push_back({"Value " + std::to_string(k), 1033, {}});
            pdo.entries.push_back(entry);
        }
        device.tx_pdos.push_back(std::move(pdo));
    }
    device.mailbox.emplace();
    device.mailbox->coe.emplace();
    info.devices.push_back(std::move(device));
    doc.infos.push_back(std::move(info));
    return doc;
}

double ms_since(Clock::time_point start) { return std::chrono::duration<double, std::milli>(Clock::now() - start).count(); }

// CPU time of this process: on a shared machine wall time also counts other processes' turns.
double cpu_ms() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) / 1e6;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    const bool once = argc > 1 && std::string(argv[1]) == "--once";
    const int iterations = argc > 1 && !once ? std::max(1, std::atoi(argv[1])) : 5;
    const esi::EsiDocument doc = synthetic_document(5000);

    esi::codegen::GenerateOptions options;
    options.output_dir = "out";
    options.template_dirs = esi::codegen::template_search_path({}, std::nullopt);

    if (once) {
        const auto result = esi::codegen::generate_outputs(doc, options);
        std::size_t bytes = 0;
        for (const auto& f : result.files) bytes += f.content.size();
        std::printf("codegen_5000 --once: %zu files, %zu bytes, %zu errors\n", result.files.size(), bytes,
                    result.diagnostics.count(esi::Severity::error));
        return result.diagnostics.has_errors() ? 1 : 0;
    }

    std::vector<double> view_ms, total_ms, view_cpu, total_cpu;
    std::size_t bytes = 0, files = 0, errors = 0;
    for (int i = 0; i < iterations; ++i) {
        auto start = Clock::now();
        double cpu = cpu_ms();
        const auto view = esi::codegen::model_view_json(doc);
        view_ms.push_back(ms_since(start));
        view_cpu.push_back(cpu_ms() - cpu);

        start = Clock::now();
        cpu = cpu_ms();
        const auto result = esi::codegen::generate_outputs(doc, options);
        total_ms.push_back(ms_since(start));
        total_cpu.push_back(cpu_ms() - cpu);
        bytes = 0;
        for (const auto& f : result.files) bytes += f.content.size();
        files = result.files.size();
        errors = result.diagnostics.count(esi::Severity::error);
        if (i == 0)
            for (const auto& d : result.diagnostics) std::fprintf(stderr, "%s: %s\n", d.rule.c_str(), d.message.c_str());
    }
    std::printf("codegen_5000: 5000 objects, %zu files, %zu bytes, %zu errors\n", files, bytes, errors);
    std::printf("  JSON view (--dump-model text):  median %8.1f ms wall, %8.1f ms CPU\n", median(view_ms), median(view_cpu));
    std::printf("  all outputs (view + render):    median %8.1f ms wall, %8.1f ms CPU  (%d runs; target < 200 ms)\n", median(total_ms),
                median(total_cpu), iterations);

    for (const auto& kind : esi::codegen::output_kinds()) {
        esi::codegen::GenerateOptions one = options;
        one.only = {kind.name};
        std::vector<double> t, c;
        for (int i = 0; i < iterations; ++i) {
            const auto start = Clock::now();
            const double cpu = cpu_ms();
            const auto r = esi::codegen::generate_outputs(doc, one);
            t.push_back(ms_since(start));
            c.push_back(cpu_ms() - cpu);
        }
        std::printf("  --only %-8s                 median %8.1f ms wall, %8.1f ms CPU\n", kind.name.c_str(), median(t), median(c));
    }
    return errors == 0 ? 0 : 1;
}
