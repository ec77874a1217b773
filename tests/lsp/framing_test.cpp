// The framing reader on its own: pieces of any size, garbage, oversize bodies, end of input.

#include <gtest/gtest.h>

#include <cstring>

#include "esi/lsp/framing.hpp"

namespace {

using esi::lsp::Frame;
using esi::lsp::MessageReader;

// Hands out `input` at most `piece` bytes per read.
esi::lsp::ReadSome pieces(std::string input, std::size_t piece) {
    auto state = std::make_shared<std::pair<std::string, std::size_t>>(std::move(input), 0);
    return [state, piece](char* buffer, std::size_t size) -> std::ptrdiff_t {
        const std::size_t n = std::min({piece, size, state->first.size() - state->second});
        std::memcpy(buffer, state->first.data() + state->second, n);
        state->second += n;
        return static_cast<std::ptrdiff_t>(n);
    };
}

TEST(LspFramingReader, MessagesArriveWholeWhateverThePieces) {
    const std::string stream = esi::lsp::frame("{\"a\":1}") + "Content-Length: 7\r\nContent-Type: application/vscode-jsonrpc; charset=utf-8\r\n\r\n{\"b\":2}" +
                               esi::lsp::frame(std::string(200000, 'x'));
    for (const std::size_t piece : {std::size_t{1}, std::size_t{3}, std::size_t{4096}, std::size_t{1} << 20}) {
        MessageReader reader(pieces(stream, piece));
        Frame f = reader.next();
        ASSERT_EQ(f.kind, Frame::Kind::message);
        EXPECT_EQ(f.body, "{\"a\":1}");
        f = reader.next();
        ASSERT_EQ(f.kind, Frame::Kind::message);
        EXPECT_EQ(f.body, "{\"b\":2}");
        f = reader.next();
        ASSERT_EQ(f.kind, Frame::Kind::message);
        EXPECT_EQ(f.body.size(), 200000u);
        EXPECT_EQ(reader.next().kind, Frame::Kind::end_of_input);
    }
}

TEST(LspFramingReader, OversizeBodyIsSkippedNotHeld) {
    const std::string stream = "Content-Length: 5000\r\n\r\n" + std::string(5000, 'y') + esi::lsp::frame("{}");
    MessageReader reader(pieces(stream, 700), 1000);
    const Frame f = reader.next();
    EXPECT_EQ(f.kind, Frame::Kind::oversize);
    EXPECT_TRUE(f.body.empty());
    const Frame next = reader.next();
    ASSERT_EQ(next.kind, Frame::Kind::message);
    EXPECT_EQ(next.body, "{}");
}

TEST(LspFramingReader, GarbageWithoutHeadersIsDroppedInBoundedPieces) {
    const std::string stream = std::string(100000, 'z') + esi::lsp::frame("{\"c\":3}");
    MessageReader reader(pieces(stream, 4096));
    Frame f;
    int bad = 0;
    while ((f = reader.next()).kind == Frame::Kind::bad_header) ++bad;
    EXPECT_GE(bad, 1);
    ASSERT_EQ(f.kind, Frame::Kind::message);
    EXPECT_EQ(f.body, "{\"c\":3}");
}

TEST(LspFramingReader, EndOfInputInsideABody) {
    MessageReader reader(pieces("Content-Length: 10\r\n\r\n{\"a\"", 2));
    EXPECT_EQ(reader.next().kind, Frame::Kind::end_of_input);
    MessageReader negative(pieces("Content-Length: -3\r\n\r\n{}", 100));
    EXPECT_EQ(negative.next().kind, Frame::Kind::bad_header);
}

}  // namespace
