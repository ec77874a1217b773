#pragma once
// The ESI reader's xml-xinclude check (esi/xml/xinclude.hpp says why XInclude is refused): every
// start tag of the document, while the parser's pass is at it, when the text may hold an XInclude
// element at all (may_hold_xinclude).

#include "esi/diagnostic.hpp"
#include "esi/source_text.hpp"
#include "esi/xml/xinclude.hpp"
#include "xml/tree_parser.hpp"

namespace esi {

class XIncludeCheck final : public xml_tree::StartTagObserver {
public:
    XIncludeCheck(const SourceText& source, Diagnostics& diagnostics) : source_(source), diagnostics_(diagnostics) {}
    // An xml-xinclude error for an element in the XInclude namespace (an ancestor declares it).
    void start_tag(xml_tree::Element element) override;

private:
    const SourceText& source_;
    Diagnostics& diagnostics_;
};

}  // namespace esi
