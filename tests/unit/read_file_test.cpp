// Reading a file whole: read_file_buffer (the ESI reader's, which reads a UTF-8 file in place and
// relies on the NUL byte after the bytes) gives the bytes read_file_bytes gives, for an empty file,
// a small one, one larger than the first read's chunk, and refuses a directory and a file over the
// limit with a message.

#include <gtest/gtest.h>

#include <string>

#include "esi/io/read_file.hpp"
#include "support/test_support.hpp"

namespace {

TEST(ReadFile, TheBufferHoldsTheBytesFollowedByANul) {
    esi::test::TempDir dir;
    for (const std::string& bytes : {std::string(), std::string("<a/>"), std::string(200000, 'x') + "\xEF\xBB\xBF", std::string(700000, 'y')}) {
        const auto file = dir / "f.xml";
        esi::test::write_text(file, bytes);
        std::string error;
        const std::optional<esi::FileBytes> buffer = esi::read_file_buffer(file, error);
        ASSERT_TRUE(buffer) << error;
        EXPECT_EQ(buffer->view(), bytes);
        EXPECT_EQ(buffer->view().data()[buffer->size()], '\0');
        const std::optional<std::string> string = esi::read_file_bytes(file, error);
        ASSERT_TRUE(string) << error;
        EXPECT_EQ(*string, bytes);
    }
}

// From esi::map_from_bytes on, a file is mapped: the same bytes and the NUL after them, also when
// the file fills its last page exactly (the NUL is then on a page of its own); bytes whose memory
// was let go read as they did.
TEST(ReadFile, ABigFileIsMappedAndStaysReadableAfterItsPagesAreLetGo) {
    esi::test::TempDir dir;
    const auto size = static_cast<std::size_t>(esi::map_from_bytes);  // a multiple of any page size
    for (const std::size_t n : {size, size + 1234}) {
        std::string bytes(n, 'x');
        for (std::size_t i = 0; i < n; i += 4093) bytes[i] = static_cast<char>('a' + i % 26);
        const auto file = dir / "big.xml";
        esi::test::write_text(file, bytes);
        std::string error;
        std::optional<esi::FileBytes> buffer = esi::read_file_buffer(file, error);
        ASSERT_TRUE(buffer) << error;
        EXPECT_TRUE(buffer->mapped());
        EXPECT_EQ(buffer->view(), bytes);
        EXPECT_EQ(buffer->view().data()[n], '\0');
        buffer->release(0, n);
        EXPECT_EQ(buffer->view(), bytes);
        const esi::FileBytes moved = std::move(*buffer);
        EXPECT_EQ(moved.view(), bytes);
    }
}

TEST(ReadFile, ADirectoryAndAFileOverTheLimitAreRefused) {
    esi::test::TempDir dir;
    std::string error;
    EXPECT_FALSE(esi::read_file_buffer(dir.path(), error));
    EXPECT_EQ(error, "is a directory");
    const auto file = dir / "big.xml";
    esi::test::write_text(file, std::string(2000, 'x'));
    EXPECT_FALSE(esi::read_file_buffer(file, error, 1000));
    EXPECT_NE(error.find("the input size limit"), std::string::npos) << error;
}

}  // namespace
