// Building the navigation index of an editor's document (esi::navigate::build_index) and
// answering requests on it: a 1 MB slice of a corpus catalogue, the largest corpus files and a
// 40 MB catalogue merged from the Devices of the corpus catalogues (as big_catalogue_rss.sh
// builds one), or the files given on the command line:
//   navigate_index [FILE...]
// Prints best-of-5 times and the peak RSS; see docs/performance.md.

#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "bench_support.hpp"
#include "esi/encoding.hpp"
#include "esi/io/read_file.hpp"
#include "esi/navigate/navigate.hpp"

namespace {

double cpu_ms() {
    timespec now{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
    return static_cast<double>(now.tv_sec) * 1e3 + static_cast<double>(now.tv_nsec) / 1e6;
}

long peak_rss_kib() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss;
}

void measure(const std::string& label, const std::string& text) {
    using namespace esi::navigate;
    const int runs = text.size() > (16u << 20) ? 2 : 5;
    IndexPtr index;
    // CPU time as well as wall time: on the shared build machine the wall time is mostly waiting.
    double build_cpu = 1e300;
    const double build = esi::bench::best_of(runs, [&] {
        index.reset();
        const double start = cpu_ms();
        index = build_index(text, label);
        build_cpu = std::min(build_cpu, cpu_ms() - start);
    });
    // Requests at the middle of the text: a hover, references of what is there, completion.
    const LineMap lines(text);
    const Position middle = lines.position_of(text.size() / 2);
    const double request = esi::bench::best_of(runs, [&] {
        (void)hover(*index, middle);
        (void)references(*index, middle, true);
        (void)complete(*index, middle);
    });
    const double symbols = esi::bench::best_of(runs, [&] { (void)outline(*index); });
    std::printf("%-46s %6.2f MB  build_index %8.2f ms (CPU %8.2f ms)  hover+refs+complete %6.2f ms  outline %7.2f ms  "
                "peak RSS %ld MiB\n",
                label.c_str(), static_cast<double>(text.size()) / 1e6, build, build_cpu, request, symbols,
                peak_rss_kib() / 1024);
}

std::string decoded(const std::filesystem::path& path) {
    std::string error;
    auto bytes = esi::read_file_bytes(path, error);
    if (!bytes) {
        std::fprintf(stderr, "navigate_index: %s: %s\n", path.c_str(), error.c_str());
        return {};
    }
    return esi::decode_xml_bytes_owned(std::move(*bytes)).utf8;
}

// The first megabyte of a catalogue, cut after a whole Device and closed again: a 1 MB file as
// the corpus has them (one vendor's catalogue of a few devices). Empty when no device ends
// between 1 and 1.25 MB.
std::string one_megabyte_of(const std::string& text) {
    const std::size_t cut = text.find("</Device>", 1u << 20);
    if (cut == std::string::npos || cut > (5u << 20) / 4) return {};
    return text.substr(0, cut + 9) + "\n</Devices></Descriptions></EtherCATInfo>\n";
}

// The Devices of the given catalogues, taken again until the whole reaches `bytes`.
std::string merged_catalogue(const std::vector<std::string>& catalogues, std::size_t bytes) {
    std::string devices;
    while (devices.size() < bytes) {
        const std::size_t before = devices.size();
        for (const std::string& text : catalogues) {
            const std::size_t begin = text.find("<Devices>");
            const std::size_t end = text.rfind("</Devices>");
            if (begin == std::string::npos || end == std::string::npos || end < begin) continue;
            devices.append(text, begin + 9, end - begin - 9);
            if (devices.size() >= bytes) break;
        }
        if (devices.size() == before) return {};
    }
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<EtherCATInfo><Descriptions><Devices>" + devices +
           "</Devices></Descriptions></EtherCATInfo>\n";
}

}  // namespace

int main(int argc, char** argv) {
    if (argc > 1) {
        for (int i = 1; i < argc; ++i) measure(argv[i], decoded(argv[i]));
        return 0;
    }
    const auto files = esi::bench::largest_corpus_files(12);
    if (files.empty()) {
        std::printf("navigate_index: the corpus is absent; nothing to measure\n");
        return 0;
    }
    std::vector<std::string> texts;
    for (const auto& file : files) texts.push_back(decoded(file));
    for (std::size_t i = 0; i < texts.size(); ++i)
        if (const std::string slice = one_megabyte_of(texts[i]); !slice.empty()) {
            measure("1 MB slice of " + files[i].filename().string(), slice);
            break;
        }
    for (std::size_t i = 0; i < 3 && i < texts.size(); ++i) measure(files[i].filename().string(), texts[i]);
    const std::string big = merged_catalogue(texts, 40u * 1000 * 1000);
    texts.clear();
    if (!big.empty()) measure("40 MB catalogue (corpus Devices merged)", big);
    return 0;
}
