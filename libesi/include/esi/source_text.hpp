#pragma once
// A decoded (UTF-8) source file plus an index of its line starts, so that byte offsets
// from the parser turn into line:column positions and diagnostics can quote the line. The text is
// either a string of its own (decoded from another encoding, or given) or the file's bytes as read
// (a UTF-8 file is its own text: it is not copied); a NUL byte follows it either way.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "esi/io/read_file.hpp"
#include "esi/large_buffer.hpp"
#include "esi/source_pos.hpp"
#include "esi/text_span.hpp"

namespace esi {

// Byte offsets of line starts: 0, then the offset after every '\n'. 32-bit, which halves the
// index of a big file (6 MB for the 1.5 M lines of a 41 MB catalogue): inputs are limited to
// esi::max_input_bytes (256 MiB), and decoding them at most triples that. A text of 4 GiB or more
// would be indexed up to there, its later lines counted as part of the last line indexed.
using LineStartList = std::vector<std::uint32_t, LargeBufferAllocator<std::uint32_t>>;

class SourceText {
public:
    SourceText() = default;
    SourceText(std::string path, std::string utf8);
    // The text is `bytes` from `offset` to its end (a byte-order mark before it is left out).
    SourceText(std::string path, FileBytes bytes, std::size_t offset);
    SourceText(const SourceText&) = delete;
    SourceText& operator=(const SourceText&) = delete;

    [[nodiscard]] const std::string& path() const { return path_; }
    [[nodiscard]] std::string_view text() const { return text_; }
    // Text [from, to) has been read: where the text is a mapped file, its memory may go (the
    // bytes stay readable, from the page cache). The reader calls it behind each device of a big
    // catalogue, so that the file is not resident as a whole next to the model read from it.
    void release_text(std::size_t from, std::size_t to) const {
        if (bytes_.mapped()) {
            const auto skipped = static_cast<std::size_t>(text_.data() - bytes_.view().data());
            bytes_.release(from + skipped, to + skipped);
        }
    }

    // Line and column (both 1-based; the column counts Unicode code points) of a byte offset.
    [[nodiscard]] SourcePos position_of(std::size_t offset) const;
    // Index of the 1-based line holding a byte offset, and the byte offset where a line starts.
    [[nodiscard]] std::uint32_t line_of(std::size_t offset) const;
    [[nodiscard]] std::size_t line_start(std::uint32_t line_number) const { return line_starts()[line_number - 1]; }
    // Code points in [from, to): the column distance between two offsets on one line.
    [[nodiscard]] std::uint32_t code_points(std::size_t from, std::size_t to) const;
    // The text of a 1-based line without its line terminator; empty when out of range.
    [[nodiscard]] std::string_view line(std::uint32_t line_number) const;
    [[nodiscard]] std::size_t line_count() const { return line_starts().size(); }
    // Installs the index of line starts (0, then the offset after every '\n') that a pass over the
    // text already found, instead of a pass of its own on first use; nothing when the index is
    // built already.
    void adopt_line_starts(LineStartList starts) const;
    // The comments of the text ("<!--" to "-->"), as the reader found them; null when unknown (a
    // text no parser read). Inline suppressions are looked for in them only.
    void adopt_comments(std::vector<TextSpan> comments) const { comments_ = std::move(comments), comments_known_ = true; }
    [[nodiscard]] const std::vector<TextSpan>* comments() const { return comments_known_ ? &comments_ : nullptr; }

private:
    friend class PositionCursor;
    using LineStart = LineStartList::value_type;
    // Built on first use, once: the reader's PositionCursor and the quoting of diagnostics'
    // lines share it.
    const LineStartList& line_starts() const;

    std::string path_;
    std::string owned_;  // the text, when it is a string of its own
    FileBytes bytes_;    // the file's bytes, when the text lies in them
    std::string_view text_;
    mutable std::vector<TextSpan> comments_;
    mutable bool comments_known_ = false;
    mutable std::once_flag index_once_;
    mutable LineStartList line_starts_;
};

// Counting helpers over UTF-8 text, eight bytes at a time.
[[nodiscard]] std::size_t count_code_points(std::string_view text);
[[nodiscard]] std::size_t count_newlines(std::string_view text);

using SourceTextPtr = std::shared_ptr<const SourceText>;

// Turns offsets into positions in linear total time when they arrive mostly in increasing
// order (as a document-order walk produces them); a single-line multi-MB file stays linear.
class PositionCursor {
public:
    explicit PositionCursor(const SourceText& source);
    [[nodiscard]] SourcePos position_of(std::size_t offset);

private:
    const SourceText& source_;
    const LineStartList& line_starts_;
    std::size_t line_ = 0;  // index in line_starts_ of the line of the previous offset
    std::size_t last_offset_ = 0;
    std::uint32_t last_column_ = 1;
};

}  // namespace esi
