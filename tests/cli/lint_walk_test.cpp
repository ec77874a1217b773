// esi-lint's directory walk cannot let CI pass silently (issue 14, item 4): a subdirectory that
// cannot be read is an error, a directory without ESI files is an error, and .git/ and CMake
// build trees are not linted.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;
using esi::test::read_text;
using esi::test::run;
using esi::test::TempDir;
using esi::test::tool;
using esi::test::write_text;

std::string sample_text() { return read_text(esi::test::source_dir() / "samples" / "esi" / "example-digital-io.xml"); }
const char* broken = "<EtherCATInfo><Vendor>\n";

// A chain of directories below `root` whose full path is longer than PATH_MAX, so that opening
// the deepest one by its path fails (ENAMETOOLONG) even for root, whom permissions do not stop.
// Made and removed through directory descriptors, as no path reaches it.
class TooDeep {
public:
    explicit TooDeep(const fs::path& root) {
        int fd = ::open(root.c_str(), O_RDONLY | O_DIRECTORY);
        fds_.push_back(fd);
        const std::string name(200, 'd');
        for (int level = 0; level < 24 && fd >= 0; ++level) {
            if (::mkdirat(fd, name.c_str(), 0755) != 0) break;
            fd = ::openat(fd, name.c_str(), O_RDONLY | O_DIRECTORY);
            fds_.push_back(fd);
        }
        if (fd >= 0) {
            const int file = ::openat(fd, "deep.xml", O_WRONLY | O_CREAT, 0644);
            if (file >= 0) ::close(file);
        }
    }
    ~TooDeep() {
        const std::string name(200, 'd');
        ::unlinkat(fds_.back(), "deep.xml", 0);
        for (std::size_t i = fds_.size() - 1; i > 0; --i) {
            ::close(fds_[i]);
            ::unlinkat(fds_[i - 1], name.c_str(), AT_REMOVEDIR);
        }
        ::close(fds_[0]);
    }
    [[nodiscard]] bool made() const { return fds_.size() == 25 && fds_.back() >= 0; }

private:
    std::vector<int> fds_;
};

}  // namespace

TEST(EsiLintWalk, ASubdirectoryThatCannotBeReadIsAnError) {
    TempDir dir;
    write_text(dir / "a.xml", sample_text());
    TooDeep deep(dir.path());
    ASSERT_TRUE(deep.made());
    const auto r = run({tool("esi-lint"), dir.path().string()});
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_NE(r.out.find("cannot read directory"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("[io-error]"), std::string::npos) << r.out;
}

TEST(EsiLintWalk, AnUnreadableSubdirectoryIsAnError) {
    TempDir dir;
    write_text(dir / "a.xml", sample_text());
    write_text(dir / "locked" / "b.xml", broken);
    fs::permissions(dir / "locked", fs::perms::none);
    const bool applies = ::access((dir / "locked").c_str(), R_OK) != 0;
    const auto r = run({tool("esi-lint"), dir.path().string()});
    fs::permissions(dir / "locked", fs::perms::owner_all);
    if (!applies) GTEST_SKIP() << "running as root: permissions do not stop reading (ASubdirectoryThatCannotBeReadIsAnError covers it)";
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_NE(r.out.find("locked: error: cannot read directory"), std::string::npos) << r.out;
}

TEST(EsiLintWalk, AnEmptyDirectoryIsAUsageError) {
    TempDir dir;
    write_text(dir / "notes.txt", "no ESI here");
    const auto r = run({tool("esi-lint"), dir.path().string()});
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_NE(r.out.find("no ESI files (*.xml) in this directory"), std::string::npos) << r.out;
}

TEST(EsiLintWalk, GitAndBuildTreesAreNotWalked) {
    TempDir dir;
    write_text(dir / "devices" / "a.xml", sample_text());
    write_text(dir / ".git" / "objects" / "stale.xml", broken);
    write_text(dir / "out-of-tree" / "CMakeCache.txt", "# CMake build tree\n");
    write_text(dir / "out-of-tree" / "generated" / "esi.xml", broken);
    const auto r = run({tool("esi-lint"), "--format", "json", dir.path().string()});
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_EQ(r.out.find("stale.xml"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("esi.xml"), std::string::npos) << r.out;
    EXPECT_EQ(nlohmann::json::parse(r.out)["summary"]["files"], 1) << r.out;
    // Named on the command line, a build tree is linted: the exclusions are for the walk only.
    EXPECT_EQ(run({tool("esi-lint"), (dir / "out-of-tree").string()}).exit_code, 1);
}
