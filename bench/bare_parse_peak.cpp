// The memory floor for reading an ESI file: pugixml alone, loading the file with the options
// libesi's reader uses, and nothing else. bench/big_catalogue_rss.sh runs it under
// /usr/bin/time next to esi-lint so that esi-lint's peak RSS can be read against it.
//   bare_parse_peak FILE
// Prints the number of elements so that the parse cannot be optimised away.

#include <pugixml.hpp>

#include <cstdio>

namespace {

std::size_t count_elements(const pugi::xml_node& node) {
    std::size_t n = 0;
    for (const pugi::xml_node& child : node.children())
        if (child.type() == pugi::node_element) n += 1 + count_elements(child);
    return n;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: bare_parse_peak FILE\n");
        return 2;
    }
    pugi::xml_document doc;
    // load_file reads the file into one buffer that pugixml parses in place: file size + DOM.
    const pugi::xml_parse_result parsed =
        doc.load_file(argv[1], pugi::parse_default | pugi::parse_embed_pcdata | pugi::parse_doctype, pugi::encoding_auto);
    if (!parsed) {
        std::fprintf(stderr, "bare_parse_peak: %s: %s at offset %td\n", argv[1], parsed.description(), parsed.offset);
        return 1;
    }
    std::printf("bare pugixml parse: %zu elements\n", count_elements(doc));
    return 0;
}
