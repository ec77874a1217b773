// Fuzz target: the ESI writer as the reader's inverse. For any input the reader makes a document
// of, the written XML must be well-formed (read again without an xml-syntax error) and writing
// that document again must give the same bytes: write(read(write(read(x)))) == write(read(x)),
// the writer's documented contract (esi/xml/writer.hpp, docs/esi-writer.md).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "esi/xml/reader.hpp"
#include "esi/xml/writer.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    const esi::ReadResult first = esi::read_esi(bytes, "fuzz.xml", {.keep_source = false});
    if (!first.document) return 0;
    const std::string written = esi::write_esi(*first.document);
    const esi::ReadResult second = esi::read_esi(written, "written.xml", {.keep_source = false});
    if (!second.document) {
        std::fprintf(stderr, "the writer's output is not readable XML:\n%s\n", written.c_str());
        for (const auto& d : second.diagnostics) std::fprintf(stderr, "  %s\n", d.message.c_str());
        std::abort();
    }
    const std::string again = esi::write_esi(*second.document);
    if (again != written) {
        std::fprintf(stderr, "not idempotent:\n--- first\n%s\n--- second\n%s\n", written.c_str(), again.c_str());
        std::abort();
    }
    return 0;
}
