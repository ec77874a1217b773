// esi-net's output set is replaced whole or not at all: when renaming into place fails part-way
// (here an immutable file), the directory still holds the previous run's set, every file of it
// (issue 27, item 6).

#include <gtest/gtest.h>

#include <map>

#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;

std::map<std::string, std::string> files_in(const fs::path& dir) {
    std::map<std::string, std::string> out;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.is_regular_file()) out[e.path().filename().string()] = esi::test::read_text(e.path());
    return out;
}

// Removes the immutable flag again whatever the test's outcome, so the directory can go.
struct Immutable {
    fs::path file;
    bool set = false;
    explicit Immutable(fs::path f) : file(std::move(f)) {
        set = esi::test::run({"chattr", "+i", file.string()}).exit_code == 0;
    }
    ~Immutable() {
        if (set) (void)esi::test::run({"chattr", "-i", file.string()});
    }
};

TEST(NetOutputSet, AFailedRenameLeavesThePreviousSetWhole) {
    esi::test::TempDir dir;
    const fs::path samples = esi::test::source_dir() / "samples";
    const std::string line = esi::test::read_text(samples / "networks" / "line.yaml");
    auto network = [&](const std::string& master) {
        std::string text = line;
        const std::string from = "name: Line 1,";
        text.replace(text.find(from), from.size(), "name: " + master + ",");
        const std::string esi = "esi: [../";
        for (std::size_t at; (at = text.find(esi)) != std::string::npos;) text.replace(at, esi.size(), "esi: [" + samples.string() + "/");
        for (const std::string f : {", ../modular", ", ../digital", ", ../servo", ", ../encoder"})
            if (auto at = text.find(f); at != std::string::npos) text.replace(at, 5, ", " + samples.string() + "/");
        esi::test::write_text(dir / "n.yaml", text);
    };
    auto build = [&] {
        return esi::test::run({esi::test::tool("esi-net").string(), "--no-cache", "build", (dir / "n.yaml").string(), "-o", (dir / "out").string()});
    };
    network("First");
    const auto first = build();
    ASSERT_EQ(first.exit_code, 0) << first.err;
    const auto before = files_in(dir / "out");
    ASSERT_GE(before.size(), 5u);

    const Immutable frozen(dir / "out" / "process_image.json");
    if (!frozen.set) GTEST_SKIP() << "chattr +i is not available here (needs root on ext4/xfs/btrfs)";
    network("Second");
    const auto second = build();
    EXPECT_EQ(second.exit_code, 1) << second.err;
    EXPECT_EQ(files_in(dir / "out"), before) << second.err;
}

}  // namespace
