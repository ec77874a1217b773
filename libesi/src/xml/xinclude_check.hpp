#pragma once
// The ESI reader's xml-xinclude check (esi/xml/xinclude.hpp says why XInclude is refused): every
// start tag of the document from the first that declares the XInclude namespace on (most files
// declare it nowhere, and no element before a declaration can be in it), while the parser's pass
// is at it.

#include "esi/diagnostic.hpp"
#include "esi/source_text.hpp"
#include "esi/xml/xinclude.hpp"
#include "xml/tree_parser.hpp"

namespace esi {

class XIncludeCheck final : public xml_tree::StartTagObserver, public xml_tree::NamespaceObserver {
public:
    // Watches the namespace declarations `parser` reads from now on, and those of `root`, the
    // start tag it has read; checks the root.
    XIncludeCheck(const SourceText& source, xml_tree::TreeParser& parser, xml_tree::Element root, Diagnostics& diagnostics);
    // An xml-xinclude error for an element in the XInclude namespace (an ancestor declares it).
    void start_tag(xml_tree::Element element) override;
    // At the XInclude namespace, asks the parser for every start tag from this one on.
    void declared(std::string_view uri) override;

private:
    const SourceText& source_;
    xml_tree::TreeParser& parser_;
    Diagnostics& diagnostics_;
    bool watching_ = false;
};

}  // namespace esi
