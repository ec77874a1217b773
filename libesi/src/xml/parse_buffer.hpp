#pragma once
// The copy of a document's text that pugixml parses in place (it writes string terminators and
// unescaped text into it). The SourceText stays as written, for quoting lines, finding
// suppressions and schema validation, so reading holds the text twice; to keep that from adding
// a whole file size to the peak of a big catalogue (issue 10), the reader gives back the pages
// of the elements it has read into the model and released from the DOM, and the copy shrinks
// while the model grows.

#include <cstddef>
#include <string_view>

namespace esi::xml_reader {

class ParseBuffer {
public:
    // Copies `text`; throws std::bad_alloc when there is no memory for it. With `give_back_pages`
    // the copy lies on pages of its own, which give_back() can return; that costs a page fault
    // per page, which a heap allocation (reusing the memory of the previous file) mostly avoids,
    // so it is worth it for big documents only.
    ParseBuffer(std::string_view text, bool give_back_pages);
    ~ParseBuffer();
    ParseBuffer(const ParseBuffer&) = delete;
    ParseBuffer& operator=(const ParseBuffer&) = delete;

    [[nodiscard]] char* data() { return data_; }
    [[nodiscard]] std::size_t size() const { return size_; }
    [[nodiscard]] std::string_view view() const { return {data_, size_}; }

    // Gives back the memory pages that lie wholly within bytes [begin, end): nothing may read
    // those bytes afterwards (on Linux they read as zeros). Bytes outside the range keep their
    // content. Ranges are expected in document order: what lies before the end of a range
    // already given back is skipped. Without `give_back_pages`, or where pages cannot be given
    // back, this does nothing.
    void give_back(std::size_t begin, std::size_t end);

private:
    char* data_ = nullptr;
    std::size_t size_ = 0;
    std::size_t capacity_ = 0;       // bytes mapped (or allocated), at least one
    bool mapped_ = false;            // on pages of its own (else from the heap)
    std::size_t given_back_end_ = 0;  // offset up to which pages have been given back
};

}  // namespace esi::xml_reader
