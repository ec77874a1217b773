// SII build speed: reads the corpus catalogue with the most devices, builds the SII image of
// every device, decodes and checks each image again, and prints devices per second next to the
// time it took to read the file. Figures only; nothing here fails.
//
//   ./build/bench/sii_build [CATALOGUE.xml]

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "esi/sii/build.hpp"
#include "esi/sii/check.hpp"
#include "esi/sii/decode.hpp"
#include "esi/xml/reader.hpp"

// Results are added up here so that the compiler cannot drop the measured work.
std::size_t sii_bench_sink = 0;

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// The EtherCATInfo file MANIFEST.tsv credits with the most devices ("N Device" in its notes).
std::filesystem::path largest_catalogue(const std::filesystem::path& corpus) {
    std::ifstream in(corpus / "MANIFEST.tsv");
    const std::regex devices_re(R"((\d+) Device)");
    std::string line, best;
    long most = -1;
    while (std::getline(in, line)) {
        if (line.find("root=EtherCATInfo ") == std::string::npos) continue;
        std::smatch m;
        if (!std::regex_search(line, m, devices_re)) continue;
        const long n = std::stol(m[1].str());
        if (n > most) {
            most = n;
            best = line.substr(0, line.find('\t'));
        }
    }
    return best.empty() ? std::filesystem::path{} : corpus / best;
}

}  // namespace

int main(int argc, char** argv) {
    std::filesystem::path file;
    if (argc > 1) {
        file = argv[1];
    } else {
        const std::filesystem::path corpus = std::filesystem::path(ESI_SHARED_DIR) / "corpus" / "esi";
        if (!std::filesystem::is_directory(corpus)) {
            std::printf("sii_build: %s not present; benchmark skipped\n", corpus.string().c_str());
            return 0;
        }
        file = largest_catalogue(corpus);
        if (file.empty()) {
            std::printf("sii_build: no EtherCATInfo catalogue in %s; benchmark skipped\n", corpus.string().c_str());
            return 0;
        }
    }

    const auto read_start = Clock::now();
    const esi::ReadResult read = esi::read_esi_file(file, {.keep_source = false});
    const double read_s = seconds_since(read_start);
    if (!read.document) {
        std::printf("sii_build: %s could not be read\n", file.string().c_str());
        return 0;
    }
    std::size_t devices = 0;
    for (const auto& info : read.document->infos) devices += info.devices.size();
    if (devices == 0) {
        std::printf("sii_build: %s has no device\n", file.string().c_str());
        return 0;
    }

    // Each figure repeats whole rounds over the catalogue until a second has passed, so that
    // small catalogues and a busy machine still give stable figures.
    struct Rate {
        double devices_per_second = 0;
        double ms_per_round = 0;
    };
    auto measure = [&](auto&& per_device) {
        std::size_t done = 0, rounds = 0;
        const auto start = Clock::now();
        do {
            for (const auto& info : read.document->infos)
                for (const auto& device : info.devices) {
                    per_device(info, device);
                    ++done;
                }
            ++rounds;
        } while (seconds_since(start) < 1.0);
        const double s = seconds_since(start);
        return Rate{static_cast<double>(done) / s, s * 1e3 / static_cast<double>(rounds)};
    };

    std::size_t over_capacity = 0, image_bytes = 0;
    for (const auto& info : read.document->infos)
        for (const auto& device : info.devices) {
            const esi::sii::BuildResult r = esi::sii::build_image(info, device);
            over_capacity += r.ok() ? 0 : 1;
            image_bytes += r.bytes.size();
        }
    const Rate build = measure([&](const esi::EtherCATInfo& info, const esi::Device& device) {
        sii_bench_sink += esi::sii::build_image(info, device).bytes.size();
    });
    const Rate round_trip = measure([&](const esi::EtherCATInfo& info, const esi::Device& device) {
        const esi::sii::BuildResult r = esi::sii::build_image(info, device);
        const esi::sii::DecodedImage d = esi::sii::decode_image(r.bytes);
        sii_bench_sink += esi::sii::check_image(info, device, d, file.string(), "image").size();
    });

    std::printf("catalogue         %s (%ju bytes, %zu devices, %zu over capacity, %.1f KiB of images)\n",
                file.filename().string().c_str(), static_cast<std::uintmax_t>(std::filesystem::file_size(file)), devices,
                over_capacity, static_cast<double>(image_bytes) / 1024.0);
    std::printf("read              %.1f ms\n", read_s * 1e3);
    std::printf("build             %.0f devices/s (%.2f ms for the catalogue)\n", build.devices_per_second, build.ms_per_round);
    std::printf("build+dump+check  %.0f devices/s (%.2f ms for the catalogue)\n", round_trip.devices_per_second,
                round_trip.ms_per_round);
    std::printf("one read of the file takes as long as building %.0f images\n", read_s * build.devices_per_second);
    return 0;
}
