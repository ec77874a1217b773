// Speed of esi-doc (issue 15): a 1,000-device catalogue synthesised from corpus devices (Beckhoff
// terminal catalogues with their dictionaries, SoE drives with InitCmds and DC modes, simple I/O)
// rendered to its index and 1,000 pages in memory, on one core; then single device pages, the
// largest first. Targets: the catalogue under 5 s, a device page under 50 ms. Writing the files
// is the atomic writer's business and is timed apart.
//
//   ./build/bench/doc_render [devices] [--runs N]
//
// The process pins itself to one CPU. Times are the best of N runs (default 3): on a shared
// machine the minimum is the run least disturbed by other jobs.

#include <sched.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "bench_support.hpp"
#include "esi/doc/datasheet.hpp"
#include "esi/io/atomic_write.hpp"
#include "esi/load/document.hpp"

namespace {

namespace fs = std::filesystem;
using esi::bench::best_of;
using esi::bench::Clock;
using esi::bench::milliseconds;

// Catalogues whose devices make up the synthetic one: large dictionaries (EL3xxx, EL4xxx, EL66xx),
// many PDOs and InitCmds (AX5xxx), many small devices (EL1xxx, EL2xxx, terminals).
const char* const sources[] = {
    "Beckhoff__EL3xxx__dls-ethercat.xml",     "Beckhoff__AX5xxx__dls-ethercat.xml",
    "Beckhoff__EL2xxx__dls-ethercat.xml",     "Beckhoff__EL4xxx__dls-ethercat__2013-03.xml",
    "Beckhoff__EL66xx__dls-ethercat.xml",     "Beckhoff__EL1xxx__dls-ethercat__2011-08.xml",
    "Beckhoff__EtherCAT_Terminals__dls-ethercat.xml", "Beckhoff__EJ7xxx__dls-ethercat.xml",
};

void pin_to_one_cpu() {
    cpu_set_t set;
    CPU_ZERO(&set);
    CPU_SET(0, &set);
    if (sched_setaffinity(0, sizeof set, &set) != 0) std::fprintf(stderr, "doc_render: could not pin to one CPU; times may use more\n");
}

}  // namespace

int main(int argc, char** argv) {
    std::size_t device_count = 1000;
    int runs = 3;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--runs" && i + 1 < argc) runs = std::atoi(argv[++i]);
        else device_count = static_cast<std::size_t>(std::atol(argv[i]));
    }
    pin_to_one_cpu();
    const fs::path corpus = fs::path(ESI_SHARED_DIR) / "corpus" / "esi";

    // The catalogue: devices taken in turn from each source until there are enough; each copy
    // gets its own revision so that it is a distinct device with its own page.
    esi::EsiDocument catalogue;
    catalogue.kind = esi::DocumentKind::ethercat_info;
    catalogue.path = "synthetic-catalogue.xml";
    esi::EtherCATInfo info;
    std::vector<std::vector<esi::Device>> pools;
    std::set<std::string> groups;
    double read_ms = 0;
    std::size_t read_bytes = 0;
    for (const char* name : sources) {
        const fs::path path = corpus / name;
        if (!fs::exists(path)) continue;
        const auto start = Clock::now();
        esi::LoadedDocument loaded = esi::load_document_file(path);
        read_ms += milliseconds(Clock::now() - start);
        read_bytes += fs::file_size(path);
        if (!loaded.usable()) continue;
        for (auto& i : loaded.document->infos) {
            if (!info.vendor && i.vendor) info.vendor = i.vendor;
            for (auto& g : i.groups)
                if (groups.insert(g.type).second) info.groups.push_back(g);
            pools.push_back(std::move(i.devices));
        }
    }
    if (pools.empty()) {
        std::printf("doc_render: no corpus at %s; nothing to measure\n", corpus.string().c_str());
        return 0;
    }
    std::size_t total_objects = 0;
    for (std::size_t k = 0; info.devices.size() < device_count; ++k) {
        const auto& pool = pools[k % pools.size()];
        if (pool.empty()) continue;
        esi::Device d = pool[(k / pools.size()) % pool.size()];
        d.type.revision_no = static_cast<std::uint32_t>(0x10000 + info.devices.size());
        if (const esi::Dictionary* dict = d.dictionary()) total_objects += dict->objects.size();
        info.devices.push_back(std::move(d));
    }
    catalogue.infos.push_back(std::move(info));
    std::printf("catalogue: %zu devices (%zu objects) from %zu corpus files (%.1f MiB read in %.0f ms)\n", device_count, total_objects,
                pools.size(), read_bytes / 1048576.0, read_ms);

    esi::doc::DatasheetOptions options;
    options.template_dirs = esi::doc::template_search_path({}, std::nullopt);

    esi::doc::Datasheets pages;
    const double all_ms = best_of(runs, [&] { pages = esi::doc::render_datasheets(catalogue, "out", options); });
    if (pages.diagnostics.has_errors()) {
        std::printf("doc_render: %s\n", pages.diagnostics.items().front().message.c_str());
        return 1;
    }
    std::size_t bytes = 0;
    for (const auto& f : pages.files) bytes += f.content.size();
    std::printf("render %zu pages: %.0f ms (%.2f ms a page, %.1f MiB of HTML)   target < 5000 ms on one core\n", pages.files.size(), all_ms,
                all_ms / static_cast<double>(pages.files.size()), bytes / 1048576.0);

    {
        const fs::path dir = fs::temp_directory_path() / "esi-doc-bench";
        std::vector<esi::OutputFile> files = pages.files;
        for (auto& f : files) f.path = dir / f.path;
        const auto start = Clock::now();
        const esi::Diagnostics written = esi::write_files_atomically(files);
        std::printf("write %zu files: %.0f ms%s\n", files.size(), milliseconds(Clock::now() - start), written.has_errors() ? " (failed)" : "");
        std::error_code ec;
        fs::remove_all(dir, ec);
    }

    // Single pages: the five largest (index + one device page each, as esi-doc --device writes them).
    std::vector<std::pair<std::size_t, std::size_t>> by_size;  // (page bytes, device position)
    for (std::size_t i = 0; i + 1 < pages.files.size(); ++i) by_size.emplace_back(pages.files[i + 1].content.size(), i);
    std::sort(by_size.rbegin(), by_size.rend());
    double worst = 0;
    for (std::size_t k = 0; k < 5 && k < by_size.size(); ++k) {
        const esi::Device& d = catalogue.infos.front().devices[by_size[k].second];
        esi::doc::DatasheetOptions one = options;
        one.device = esi::DeviceSelector{d.type.product_code.value_or(0), d.type.revision_no};
        const double ms = best_of(runs * 3, [&] { (void)esi::doc::render_datasheets(catalogue, "out", one); });
        const esi::Dictionary* dict = d.dictionary();
        std::printf("  page %-24s %7.1f KiB  %4zu objects  %3zu PDOs  %6.2f ms\n", d.type.text.c_str(), by_size[k].first / 1024.0,
                    dict ? dict->objects.size() : 0, d.rx_pdos.size() + d.tx_pdos.size(), ms);
        worst = std::max(worst, ms);
    }
    std::printf("single device page: worst of the five largest %.2f ms   target < 50 ms\n", worst);
    return 0;
}
