// Building the navigation index of an editor's document (esi::navigate::build_index) and
// answering requests on it, on the largest files of the corpus, a 1 MB slice of one and
// optionally a file given on the command line (a 40 MB catalogue from big_catalogue_rss.sh):
//   navigate_index [FILE...]
// Prints best-of-5 times and the peak RSS; see docs/performance.md.

#include <sys/resource.h>

#include <cstdio>
#include <string>

#include "bench_support.hpp"
#include "esi/encoding.hpp"
#include "esi/io/read_file.hpp"
#include "esi/navigate/navigate.hpp"

namespace {

long peak_rss_kib() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss;
}

void measure(const std::string& label, const std::string& text) {
    using namespace esi::navigate;
    const int runs = text.size() > (16u << 20) ? 2 : 5;
    IndexPtr index;
    const double build = esi::bench::best_of(runs, [&] { index = build_index(text, label); });
    // Requests at the middle of the text: a hover, references of what is there, completion.
    const LineMap lines(text);
    const Position middle = lines.position_of(text.size() / 2);
    const double request = esi::bench::best_of(runs, [&] {
        (void)hover(*index, middle);
        (void)references(*index, middle, true);
        (void)complete(*index, middle);
    });
    const double symbols = esi::bench::best_of(runs, [&] { (void)outline(*index); });
    std::printf("%-50s %7.2f MB  build_index %8.2f ms  hover+refs+complete %6.2f ms  outline %7.2f ms  peak RSS %ld MiB\n",
                label.c_str(), static_cast<double>(text.size()) / 1e6, build, request, symbols, peak_rss_kib() / 1024);
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

// The first `bytes` of a document cut after a whole Device, closed again: a 1 MB file as it
// is found in the corpus (one vendor's catalogue of a few devices).
std::string one_megabyte_of(const std::string& text) {
    const std::size_t cut = text.find("</Device>", 1u << 20);
    if (cut == std::string::npos) return text;
    return text.substr(0, cut + 9) + "\n</Devices></Descriptions></EtherCATInfo>\n";
}

}  // namespace

int main(int argc, char** argv) {
    if (argc > 1) {
        for (int i = 1; i < argc; ++i) measure(argv[i], decoded(argv[i]));
        return 0;
    }
    const auto files = esi::bench::largest_corpus_files(3);
    if (files.empty()) {
        std::printf("navigate_index: the corpus is absent; nothing to measure\n");
        return 0;
    }
    const std::string largest = decoded(files.front());
    measure("1 MB slice of " + files.front().filename().string(), one_megabyte_of(largest));
    for (const auto& file : files) measure(file.filename().string(), decoded(file));
    return 0;
}
