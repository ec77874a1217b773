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
    for (const std::string& bytes : {std::string(), std::string("<a/>"), std::string(200000, 'x') + "\xEF\xBB\xBF"}) {
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
