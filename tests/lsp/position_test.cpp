// LSP positions (UTF-16 code units) over UTF-8 text, and the document store's edits.

#include <gtest/gtest.h>

#include "esi/lsp/document_store.hpp"
#include "esi/lsp/position.hpp"

namespace {

using esi::lsp::Position;

// "aä😀b\nx": a(1 byte,1 unit) ä(2,1) 😀(4,2) b(1,1)
const std::string text = "a\xC3\xA4\xF0\x9F\x98\x80" "b\r\nx";

TEST(LspPosition, Utf16UnitsToBytesAndBack) {
    EXPECT_EQ(esi::lsp::offset_of(text, {0, 0}), 0u);
    EXPECT_EQ(esi::lsp::offset_of(text, {0, 1}), 1u);
    EXPECT_EQ(esi::lsp::offset_of(text, {0, 2}), 3u);
    EXPECT_EQ(esi::lsp::offset_of(text, {0, 4}), 7u);
    EXPECT_EQ(esi::lsp::offset_of(text, {0, 3}), 7u);  // inside the surrogate pair: after the character
    EXPECT_EQ(esi::lsp::offset_of(text, {0, 5}), 8u);
    EXPECT_EQ(esi::lsp::offset_of(text, {0, 99}), 8u);  // past the line end: before "\r\n"
    EXPECT_EQ(esi::lsp::offset_of(text, {1, 0}), 10u);
    EXPECT_EQ(esi::lsp::offset_of(text, {7, 0}), text.size());
    EXPECT_EQ(esi::lsp::position_of(text, std::size_t{7}), (Position{0, 4}));
    EXPECT_EQ(esi::lsp::position_of(text, std::size_t{11}), (Position{1, 1}));
    const esi::lsp::LineIndex index(text);
    for (std::size_t offset : {0u, 1u, 3u, 7u, 8u, 10u, 11u}) {
        EXPECT_EQ(index.position_of(offset), esi::lsp::position_of(text, offset)) << offset;
        EXPECT_EQ(index.offset_of(index.position_of(offset)), offset) << offset;
    }
    // Lint positions count code points from 1: column 4 is the 😀... no, 'b'.
    EXPECT_EQ(index.position_of(esi::SourcePos{1, 4}), (Position{0, 4}));
    EXPECT_EQ(index.position_of(esi::SourcePos{2, 1}), (Position{1, 0}));
}

TEST(LspDocumentStore, IncrementalAndFullChanges) {
    esi::lsp::DocumentStore store;
    store.open("file:///a.xml", "xml", 1, text);
    // Replace ä😀 by "-" and append a line, in one didChange.
    ASSERT_TRUE(store.change("file:///a.xml", 2,
                             {{esi::lsp::Range{{0, 1}, {0, 4}}, "-"}, {esi::lsp::Range{{1, 1}, {1, 1}}, "\ny"}}));
    EXPECT_EQ(*store.find("file:///a.xml")->text, "a-b\r\nx\ny");
    EXPECT_EQ(store.find("file:///a.xml")->version, 2);
    ASSERT_TRUE(store.change("file:///a.xml", 3, {{std::nullopt, "whole"}}));
    EXPECT_EQ(*store.find("file:///a.xml")->text, "whole");
    EXPECT_FALSE(store.change("file:///b.xml", 1, {}));
    store.close("file:///a.xml");
    EXPECT_FALSE(store.find("file:///a.xml"));
}

TEST(LspDocumentStore, FileUris) {
    EXPECT_EQ(esi::lsp::path_of_uri("file:///home/u/a%20b/dev%C3%A4.xml"), "/home/u/a b/dev\xC3\xA4.xml");
    EXPECT_EQ(esi::lsp::path_of_uri("file://localhost/x.xml"), "/x.xml");
    EXPECT_FALSE(esi::lsp::path_of_uri("untitled:Untitled-1"));
    EXPECT_FALSE(esi::lsp::path_of_uri("file://otherhost/x.xml"));
}

}  // namespace
