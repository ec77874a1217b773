// esi-lint throughput on the real corpus, side by side with bare pugixml parsing:
//   1. bare pugixml parse (MB/s), 2. read into the model, 3. read + all rules on one thread,
//   4. wall time of `esi-lint -j <cores>` over the whole corpus and its peak memory,
//   5. issue 25's target pair as processes: `esi-lint -j1 --format json` over the corpus files
//      against `lint_stage bare` over the same files, run in turn, CPU time (user + system) of
//      each from wait4, and the ratio of the medians.
// Each figure is the median of several runs. Usage: lint_corpus [CORPUS_DIR] [RUNS]

#include <pugixml.hpp>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "esi/io/read_file.hpp"
#include "esi/lint/lint.hpp"

extern char** environ;

namespace {

struct Input {
    std::filesystem::path path;
    std::string bytes;
};

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// CPU time of this process: on a machine shared with other jobs, wall time includes the time
// spent waiting for a core, CPU time does not (it is still inflated by the neighbours' use of
// the caches, but far less).
double cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

struct Timing {
    double wall = 0;  // median seconds
    double cpu = 0;
};

Timing time_runs(int runs, const std::function<void()>& f) {
    std::vector<double> walls;
    std::vector<double> cpus;
    for (int i = 0; i < runs; ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        const double c0 = cpu_seconds();
        f();
        cpus.push_back(cpu_seconds() - c0);
        walls.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    return {median(walls), median(cpus)};
}

struct ChildRun {
    double wall = -1;  // seconds
    double cpu = -1;   // user + system seconds
    double peak = -1;  // max RSS, MB
};

// Runs a command with its output to /dev/null.
ChildRun run_measured(std::vector<std::string> argv) {
    std::vector<char*> args;
    for (auto& a : argv) args.push_back(a.data());
    args.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", 0x1 /*O_WRONLY*/, 0);
    const auto t0 = std::chrono::steady_clock::now();
    pid_t pid = 0;
    if (posix_spawn(&pid, args[0], &actions, nullptr, args.data(), environ) != 0) return {};
    int status = 0;
    rusage usage{};
    wait4(pid, &status, 0, &usage);
    posix_spawn_file_actions_destroy(&actions);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const auto seconds = [](const timeval& t) { return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) * 1e-6; };
    return {wall, seconds(usage.ru_utime) + seconds(usage.ru_stime), static_cast<double>(usage.ru_maxrss) / 1024.0};
}

}  // namespace

int main(int argc, char** argv) {
    const std::filesystem::path dir = argc > 1 ? argv[1] : std::filesystem::path(ESI_SHARED_DIR) / "corpus" / "esi";
    const int runs = argc > 2 ? std::atoi(argv[2]) : 7;
    if (!std::filesystem::is_directory(dir)) {
        std::printf("lint_corpus: %s not present; nothing to measure\n", dir.c_str());
        return 0;
    }
    // esi-lint runs first: posix_spawn starts the child in the parent's address space, and
    // Linux carries that address space's high-water mark into the child's max RSS at exec. Run
    // after the corpus and its models were loaded, the figure was this process's (about 65 MB),
    // not esi-lint's.
    const std::filesystem::path build = std::filesystem::path(argv[0]).parent_path().parent_path();
    const std::filesystem::path esi_lint = build / "cli" / "esi-lint";
    const std::filesystem::path lint_stage = build / "bench" / "lint_stage";
    double lint_wall = -1;
    double lint_peak = 0;
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    if (std::filesystem::exists(esi_lint)) {
        std::vector<double> walls;
        for (int i = 0; i < runs; ++i) {
            const ChildRun run = run_measured({esi_lint.string(), "-j", std::to_string(cores), "--format", "json", "--fail-on", "never",
                                               dir.string()});
            walls.push_back(run.wall);
            lint_peak = std::max(lint_peak, run.peak);
        }
        lint_wall = median(walls);
    }

    std::vector<Input> inputs;
    std::size_t total = 0;
    std::size_t largest = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
        if (e.path().extension() != ".xml") continue;
        std::string error;
        auto bytes = esi::read_file_bytes(e.path(), error);
        if (!bytes) continue;
        total += bytes->size();
        largest = std::max(largest, bytes->size());
        inputs.push_back({e.path(), std::move(*bytes)});
    }
    std::sort(inputs.begin(), inputs.end(), [](const Input& a, const Input& b) { return a.path < b.path; });
    const double mb = static_cast<double>(total) / 1e6;
    std::printf("corpus: %zu files, %.1f MB (largest %.1f MB), median of %d runs\n", inputs.size(), mb,
                static_cast<double>(largest) / 1e6, runs);

    const Timing bare = time_runs(runs, [&] {
        for (const auto& in : inputs) {
            pugi::xml_document doc;
            doc.load_buffer(in.bytes.data(), in.bytes.size());
        }
    });
    const Timing read = time_runs(runs, [&] {
        for (const auto& in : inputs) (void)esi::read_esi(in.bytes, in.path.string());
    });
    std::size_t diagnostics = 0;
    const Timing lint = time_runs(runs, [&] {
        diagnostics = 0;
        for (const auto& in : inputs) diagnostics += esi::lint_bytes(in.bytes, in.path.string(), {}).diagnostics.size();
    });
    std::printf("%-44s %8s    %8s    %8s\n", "", "wall", "MB/s", "CPU");
    std::printf("%-44s %8.1f ms %8.1f    %8.1f ms\n", "bare pugixml parse (1 thread)", bare.wall * 1e3, mb / bare.wall, bare.cpu * 1e3);
    std::printf("%-44s %8.1f ms %8.1f    %8.1f ms\n", "read into the model (1 thread)", read.wall * 1e3, mb / read.wall, read.cpu * 1e3);
    std::printf("%-44s %8.1f ms %8.1f    %8.1f ms  (%zu diagnostics)\n", "lint, all rules (1 thread)", lint.wall * 1e3, mb / lint.wall,
                lint.cpu * 1e3, diagnostics);
    std::printf("%-44s %8.2f             %8.2f\n", "lint throughput / bare parse throughput", bare.wall / lint.wall, bare.cpu / lint.cpu);

    if (lint_wall >= 0) {
        std::printf("%-44s %8.1f ms  (-j %u)\n", "esi-lint whole corpus, wall time", lint_wall * 1e3, cores);
        std::printf("%-44s %8.1f MB  (budget 4 x largest + 30 MB = %.1f MB)\n", "esi-lint peak memory (max RSS)", lint_peak,
                    4.0 * static_cast<double>(largest) / 1048576.0 + 30.0);
    }

    // Issue 25: the whole tool against the bare parse program, both as processes, in turn.
    if (std::filesystem::exists(esi_lint) && std::filesystem::exists(lint_stage)) {
        std::vector<std::string> lint_argv = {esi_lint.string(), "-j1", "--format", "json", "--fail-on", "never"};
        std::vector<std::string> bare_argv = {lint_stage.string(), "bare"};
        for (const auto& in : inputs) {
            lint_argv.push_back(in.path.string());
            bare_argv.push_back(in.path.string());
        }
        run_measured(lint_argv);  // warm the page cache and the binaries
        run_measured(bare_argv);
        std::vector<double> lint_cpu;
        std::vector<double> bare_cpu;
        for (int i = 0; i < runs; ++i) {
            lint_cpu.push_back(run_measured(lint_argv).cpu);
            bare_cpu.push_back(run_measured(bare_argv).cpu);
        }
        const double l = median(lint_cpu);
        const double b = median(bare_cpu);
        std::printf("%-44s %8.1f ms CPU\n", "esi-lint -j1 --format json (process)", l * 1e3);
        std::printf("%-44s %8.1f ms CPU\n", "lint_stage bare (process)", b * 1e3);
        std::printf("%-44s %8.2f  (issue 25 target: 1.5)\n", "esi-lint / bare parse, CPU time", l / b);
    }
    return 0;
}
