// esi-net's speed targets (issue 13, "Speed"), on the ESI corpus:
//   1. finding 20 devices in the whole corpus, cold (no cache: every file scanned, the cache
//      written) — under the time of one bare pugixml parse of the corpus, measured alongside;
//   2. the same warm (the cache read, every file only stat'ed) — under 50 ms;
//   3. building a 100-slave network of corpus devices and rendering every output — under 1 s.
// Each figure is the median of RUNS runs (default 5), wall time and CPU time of the process.
// Usage: net_index [CORPUS_ESI_DIR] [RUNS]

#include <pugixml.hpp>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "esi/io/read_file.hpp"
#include "esi/net/library_index.hpp"
#include "esi/net/network.hpp"
#include "esi/net/network_spec.hpp"
#include "esi/net/outputs.hpp"
#include "esi/net/resolve.hpp"

namespace {

namespace fs = std::filesystem;

double cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

struct Timing {
    double wall_ms = 0;
    double cpu_ms = 0;
};

Timing median_of(int runs, const std::function<void()>& before, const std::function<void()>& f) {
    std::vector<double> walls, cpus;
    for (int i = 0; i < runs; ++i) {
        before();
        const auto t0 = std::chrono::steady_clock::now();
        const double c0 = cpu_seconds();
        f();
        cpus.push_back((cpu_seconds() - c0) * 1000);
        walls.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    std::sort(walls.begin(), walls.end());
    std::sort(cpus.begin(), cpus.end());
    return {walls[walls.size() / 2], cpus[cpus.size() / 2]};
}

}  // namespace

int main(int argc, char** argv) {
    const fs::path corpus = argc > 1 ? fs::path(argv[1]) : fs::path(ESI_SHARED_DIR) / "corpus" / "esi";
    const int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 5;
    if (!fs::is_directory(corpus)) {
        std::fprintf(stderr, "net_index: %s not found\n", corpus.c_str());
        return 2;
    }
    std::vector<fs::path> files;
    std::uintmax_t bytes = 0;
    for (const auto& e : fs::directory_iterator(corpus))
        if (e.path().extension() == ".xml") {
            files.push_back(e.path());
            bytes += e.file_size();
        }
    std::sort(files.begin(), files.end());

    // 0. One bare pugixml parse of the corpus, with the reader's parse options.
    const Timing bare = median_of(runs, [] {}, [&] {
        for (const fs::path& f : files) {
            pugi::xml_document doc;
            (void)doc.load_file(f.c_str(), pugi::parse_default | pugi::parse_embed_pcdata | pugi::parse_doctype, pugi::encoding_auto);
        }
    });

    // The 20 devices: every (n/20)-th device of the index, by identity.
    const esi::net::LibraryIndex reference = esi::net::build_library_index({corpus}, {}).index;
    std::vector<esi::net::DeviceQuery> queries;
    for (std::size_t i = 0; i < 20 && !reference.devices.empty(); ++i) {
        const esi::net::IndexedDevice& d = reference.devices[i * reference.devices.size() / 20];
        queries.push_back({std::nullopt, d.vendor_id, d.product_code, d.revision_no});
    }
    std::size_t found = 0;
    auto find_all = [&](const esi::net::IndexOptions& options) {
        const esi::net::IndexResult r = esi::net::build_library_index({corpus}, options);
        found = 0;
        for (const esi::net::DeviceQuery& q : queries) found += esi::net::find_devices(r.index, q).devices.empty() ? 0 : 1;
    };
    const fs::path cache = fs::temp_directory_path() / ("esi-net-bench-" + std::to_string(::getpid()));
    const esi::net::IndexOptions cached{cache};
    const Timing cold = median_of(runs, [&] { fs::remove_all(cache); }, [&] { find_all(cached); });
    const Timing warm = median_of(runs, [] {}, [&] { find_all(cached); });
    fs::remove_all(cache);

    // 100 slaves: drives, couplers and terminals of the corpus, in a line whose ports fit: an
    // Ethernet drive, a coupler to the E-Bus, terminals, and an extension back to Ethernet.
    std::string yaml = "master: { name: bench, cycle_time_us: 1000 }\nslaves:\n";
    const char* devices[] = {
        "{ product_code: 0x00030924, revision: 0x00010420, pdos: [0x1601, 0x1A03] }",          // Elmo
        "{ product_code: 0x044C2C52, revision: 0x00120000 }",                                  // EK1100
        "{ product_code: 0x07D83052, revision: 0x00120000 }",                                  // EL2008
        "{ product_code: 0x04E43052, revision: 0x00120000 }",                                  // EL1252
        "{ device: EK1110 }",                                                                  // EK1110
    };
    for (int i = 0; i < 100; ++i) yaml += std::string("  - ") + devices[i % 5] + "\n";
    const esi::net::NetworkFileResult spec = esi::net::read_network_text(yaml, "bench.yaml");
    const esi::net::LibraryIndex index = esi::net::build_library_index({corpus}, {}).index;
    std::size_t output_bytes = 0, frames = 0;
    bool built_ok = false;
    const Timing network = median_of(runs, [] {}, [&] {
        const esi::net::BuildResult built = esi::net::build_network(*spec.spec, index);
        built_ok = built.network.has_value();
        if (!built_ok) return;
        frames = built.network->image.frames.size();
        output_bytes = 0;
        for (const esi::OutputFile& f : esi::net::network_outputs(*built.network, esi::net::all_output_kinds(), "out"))
            output_bytes += f.content.size();
    });

    std::printf("corpus: %zu files, %.1f MB, %zu devices; median of %d runs\n", files.size(), static_cast<double>(bytes) / 1e6,
                reference.devices.size(), runs);
    std::printf("bare pugixml parse of the corpus     %8.1f ms wall %8.1f ms CPU\n", bare.wall_ms, bare.cpu_ms);
    std::printf("find 20 devices, cold (no cache)     %8.1f ms wall %8.1f ms CPU  (%zu found; target < bare parse: %s)\n", cold.wall_ms,
                cold.cpu_ms, found, cold.cpu_ms < bare.cpu_ms ? "met" : "NOT met");
    std::printf("find 20 devices, warm (cache)        %8.1f ms wall %8.1f ms CPU  (target < 50 ms: %s)\n", warm.wall_ms, warm.cpu_ms,
                warm.wall_ms < 50 ? "met" : "NOT met");
    std::printf("100-slave network, all outputs       %8.1f ms wall %8.1f ms CPU  (%s, %zu frames, %zu bytes; target < 1 s: %s)\n",
                network.wall_ms, network.cpu_ms, built_ok ? "built" : "FAILED", frames, output_bytes, network.wall_ms < 1000 ? "met" : "NOT met");
    return built_ok ? 0 : 1;
}
