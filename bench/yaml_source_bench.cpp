// The YAML device source front end on a synthetic device with N objects (default 5,000: VARs,
// records and arrays, 8 PDOs a direction mapping some of them):
//   1. the YAML tree alone (libyaml events into esi::yaml::Tree), 2. load_device_source (tree,
//   model, derivation).
// Each figure is the median of several runs on one thread. Usage: yaml_source_bench [OBJECTS] [RUNS]

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "esi/yaml/source.hpp"
#include "esi/yaml/tree.hpp"

namespace {

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

double time_runs(int runs, const std::function<void()>& f) {
    std::vector<double> seconds;
    for (int i = 0; i < runs; ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        f();
        seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    return median(seconds);
}

std::string hex(unsigned v) {
    char b[16];
    std::snprintf(b, sizeof b, "0x%04X", v);
    return b;
}

// Objects from 0x2000 up: every 8th a record of four entries, every 20th an array of 8 UINTs,
// the rest VARs of rotating types; the first 64 VARs are mapped into 8 PDOs a direction.
std::string synthetic_device(unsigned objects) {
    static const char* types[] = {"UINT", "INT", "UDINT", "DINT", "USINT", "SINT", "REAL", "BOOL"};
    std::string y = "vendor: { id: 0x0E4A, name: Bench GmbH }\ngroups: [{ type: G, name: Group }]\ndevices:\n";
    y += "  - type: BENCH\n    name: Synthetic device\n    product_code: 0x1234\n    revision: 1\n    profile: 402\n";
    y += "    mailbox: { size: 256, coe: { sdo_info: true, pdo_assign: true } }\n    objects:\n";
    std::vector<unsigned> rx, tx;
    for (unsigned i = 0; i < objects; ++i) {
        const unsigned index = 0x2000 + i;
        const std::string name = "Object " + std::to_string(i);
        if (i % 8 == 7) {
            y += "      " + hex(index) + ":\n        name: " + name + "\n        entries:\n";
            for (unsigned s = 1; s <= 4; ++s)
                y += "          " + std::to_string(s) + ": { name: Entry " + std::to_string(s) + ", type: UDINT, access: rw, default: " +
                     std::to_string(s) + " }\n";
        } else if (i % 20 == 19) {
            y += "      " + hex(index) + ": { name: " + name + ", type: UINT, array: 8, access: rw }\n";
        } else {
            const char* type = types[i % 8];
            const bool out = (i % 2) == 0;
            y += "      " + hex(index) + ": { name: " + name + ", type: " + type + ", access: " + (out ? "rw" : "ro") +
                 ", pdo: " + (out ? "rx" : "tx") + " }\n";
            if (out && rx.size() < 64) rx.push_back(index);
            if (!out && tx.size() < 64) tx.push_back(index);
        }
    }
    for (const char* dir : {"rxpdo", "txpdo"}) {
        const auto& list = std::string(dir) == "rxpdo" ? rx : tx;
        y += std::string("    ") + dir + ":\n";
        for (unsigned p = 0; p < 8; ++p) {
            y += "      - { index: " + hex((std::string(dir) == "rxpdo" ? 0x1600 : 0x1A00) + p) + ", name: PDO " +
                 std::to_string(p) + ", entries: [";
            for (unsigned e = 0; e < 8 && p * 8 + e < list.size(); ++e) y += (e ? ", " : "") + hex(list[p * 8 + e]);
            y += "] }\n";
        }
    }
    return y;
}

}  // namespace

int main(int argc, char** argv) {
    const unsigned objects = argc > 1 ? static_cast<unsigned>(std::stoul(argv[1])) : 5000;
    const int runs = argc > 2 ? std::stoi(argv[2]) : 7;
    const std::string text = synthetic_device(objects);

    const esi::DeviceSource check = esi::load_device_source(text, "bench.yaml");
    if (!check.document || !check.diagnostics.empty()) {
        std::fprintf(stderr, "the synthetic device does not load cleanly (%zu diagnostics)\n", check.diagnostics.size());
        for (const auto& d : check.diagnostics) std::fprintf(stderr, "%u:%u %s\n", d.pos.line, d.pos.column, d.message.c_str());
        return 1;
    }
    const auto& od = *check.document->infos[0].devices[0].dictionary();

    const double tree_only = time_runs(runs, [&] {
        esi::Diagnostics diagnostics;
        bool empty = false;
        (void)esi::yaml::Tree::parse(text, "bench.yaml", esi::yaml::TreeLimits{}, diagnostics, empty);
    });
    const double full = time_runs(runs, [&] { (void)esi::load_device_source(text, "bench.yaml"); });
    std::printf("synthetic device: %u objects in the source, %zu objects and %zu data types after derivation, %.1f KiB of YAML\n",
                objects, od.objects.size(), od.data_types.size(), static_cast<double>(text.size()) / 1024.0);
    std::printf("YAML tree alone (libyaml)          %8.1f ms\n", tree_only * 1000);
    std::printf("load_device_source (scan+parse+derive) %4.1f ms   (median of %d runs, one thread)\n", full * 1000, runs);
    return 0;
}
