// Speed of esi-diff (issue 4 §5): diffs the two largest revisions of one catalogue in the corpus
// and prints the diff time next to the time to read both files. Target: the diff costs less than
// reading. Also prints the same figures for every other revision pair of the corpus.
//
//   ./build/bench/diff_revisions [OLD.xml NEW.xml] [--repeat N] [--diff-only]
//
// --diff-only skips the read timing (for profiling the differ with perf).
//
// Without files, the pairs come from ../shared/corpus/esi/MANIFEST.tsv ("revision pair with X"
// where both files are present). Times are the median of N runs (default 15).

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "esi/diff/diff.hpp"
#include "esi/xml/reader.hpp"

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct Pair {
    fs::path old_path;
    fs::path new_path;
    std::uintmax_t bytes = 0;
};

// Pairs named in the manifest's notes ("revision pair with <file>"), both files present, each once.
std::vector<Pair> manifest_pairs(const fs::path& dir) {
    std::vector<Pair> out;
    std::ifstream in(dir / "MANIFEST.tsv");
    std::string line;
    std::getline(in, line);
    const std::string marker = "revision pair with ";
    while (std::getline(in, line)) {
        std::vector<std::string> cols;
        std::stringstream s(line);
        std::string col;
        while (std::getline(s, col, '\t')) cols.push_back(col);
        if (cols.size() < 7) continue;
        const auto at = cols[6].find(marker);
        if (at == std::string::npos) continue;
        std::string other = cols[6].substr(at + marker.size());
        other = other.substr(0, other.find_first_of(" ;"));
        const fs::path a = dir / cols[0];
        const fs::path b = dir / other;
        if (!fs::exists(a) || !fs::exists(b)) continue;
        Pair p{a, b, fs::file_size(a) + fs::file_size(b)};
        if (p.new_path.filename() < p.old_path.filename()) std::swap(p.old_path, p.new_path);  // dated names sort old first
        const bool seen = std::any_of(out.begin(), out.end(),
                                      [&](const Pair& q) { return q.old_path == p.old_path && q.new_path == p.new_path; });
        if (!seen) out.push_back(p);
    }
    std::sort(out.begin(), out.end(), [](const Pair& x, const Pair& y) { return x.bytes > y.bytes; });
    return out;
}

template <class F>
double median_ms(int repeat, F&& f) {
    std::vector<double> times;
    for (int i = 0; i < repeat; ++i) {
        const auto start = Clock::now();
        f();
        times.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    }
    std::sort(times.begin(), times.end());
    return times[times.size() / 2];
}

struct Figures {
    double read_ms = 0;
    double diff_ms = 0;
    std::size_t changes = 0;
    bool ok = false;
};

Figures measure(const Pair& p, int repeat, bool diff_only) {
    Figures f;
    esi::ReadOptions options;
    options.keep_source = false;
    esi::ReadResult a = esi::read_esi_file(p.old_path, options);
    esi::ReadResult b = esi::read_esi_file(p.new_path, options);
    if (!a.document || !b.document) return f;
    f.ok = true;
    if (!diff_only)
        f.read_ms = median_ms(repeat, [&] {
            const auto x = esi::read_esi_file(p.old_path, options);
            const auto y = esi::read_esi_file(p.new_path, options);
            if (!x.document || !y.document) std::fputs("read failed\n", stderr);
        });
    f.diff_ms = median_ms(repeat, [&] { f.changes = esi::diff_documents(*a.document, *b.document).changes.size(); });
    return f;
}

}  // namespace

int main(int argc, char** argv) {
    int repeat = 15;
    bool diff_only = false;
    std::vector<std::string> files;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--repeat" && i + 1 < argc)
            repeat = std::max(1, std::atoi(argv[++i]));
        else if (arg == "--diff-only")
            diff_only = true;
        else
            files.push_back(arg);
    }

    std::vector<Pair> pairs;
    if (files.size() == 2) {
        pairs.push_back({files[0], files[1], fs::file_size(files[0]) + fs::file_size(files[1])});
    } else {
        const fs::path dir = fs::path(ESI_SHARED_DIR) / "corpus" / "esi";
        if (!fs::is_directory(dir)) {
            std::printf("diff_revisions: %s not found; give OLD.xml NEW.xml\n", dir.string().c_str());
            return 0;
        }
        pairs = manifest_pairs(dir);
    }
    if (pairs.empty()) {
        std::printf("diff_revisions: no revision pair found\n");
        return 0;
    }

    std::printf(
        "esi-diff speed: median of %d runs; read = reading and parsing both files; diff = diff_documents on the two models\n\n",
        repeat);
    std::printf("%-72s %9s %10s %10s %8s %8s\n", "pair (old -> new)", "KiB", "read ms", "diff ms", "diff/rd", "changes");
    bool first = true;
    for (const Pair& p : pairs) {
        const Figures f = measure(p, repeat, diff_only);
        std::string name = p.old_path.filename().string() + " -> " + p.new_path.filename().string();
        if (name.size() > 72) name = name.substr(0, 69) + "...";
        if (!f.ok) {
            std::printf("%-72s unreadable\n", name.c_str());
            continue;
        }
        std::printf("%-72s %9.0f %10.3f %10.3f %8.2f %8zu%s\n", name.c_str(), static_cast<double>(p.bytes) / 1024.0, f.read_ms,
                    f.diff_ms, f.diff_ms / f.read_ms, f.changes, first ? "  <- largest pair" : "");
        if (first)
            std::printf("%-72s %s\n", "",
                        f.diff_ms < f.read_ms ? "target met: the diff costs less than reading"
                                              : "TARGET MISSED: the diff costs more than reading");
        first = false;
    }
    return 0;
}
