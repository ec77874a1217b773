#pragma once
// What the configuration reader (lcec_conf) of each maintained linuxcnc-ethercat fork accepts,
// so that the tests can run lcec.xml files through both without building LinuxCNC. Each fork's
// reader is an expat state machine that stops at the first element it does not expect under
// the current one, at any attribute it does not know and at a value outside its list:
//  - linuxcnc-ethercat/linuxcnc-ethercat, src/lcec_conf.c at 25989c5 (the same rules in its
//    renamed src/ecat_xml.c at 2c9c17a);
//  - sittner/linuxcnc-ethercat, src/conf.c at a19cb23.
// The rules are restated here from those readers (element, parent, attributes, required
// attributes, enumerated values); no code of theirs is used.

#include <string>
#include <vector>

#include <pugixml.hpp>

namespace esi::test {

enum class LcecForkRules { linuxcnc_ethercat, sittner };

// One reason the fork's reader would refuse the file: "line N: <element> <what>".
struct LcecRefusal {
    std::string message;
};

// Every refusal of `document` under `fork`'s rules (empty when the reader accepts it). Unlike
// the reader, which stops at the first, all are listed.
std::vector<LcecRefusal> lcec_refusals(const pugi::xml_document& document, LcecForkRules fork);
std::vector<LcecRefusal> lcec_refusals(const std::string& xml_text, LcecForkRules fork);

}  // namespace esi::test
