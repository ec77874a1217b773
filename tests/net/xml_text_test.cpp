// The network writers' XML builder escapes through the project's one escaper: a device or PDO
// name with a control character or invalid UTF-8 still gives a well-formed ENI or lcec file.

#include <gtest/gtest.h>

#include <pugixml.hpp>

#include "net/xml_text.hpp"

TEST(NetXmlText, CharactersXmlCannotCarryBecomeReplacementCharacters) {
    esi::net::XmlText xml;
    xml.open("Slave", {{"Name", std::string("Axis\t1\x01")}});
    xml.leaf("Name", std::string("Drive \x02<1>\xFF"));
    const std::string text = xml.finish();
    EXPECT_NE(text.find("Name=\"Axis&#9;1\xEF\xBF\xBD\""), std::string::npos) << text;
    EXPECT_NE(text.find("<Name>Drive \xEF\xBF\xBD&lt;1&gt;\xEF\xBF\xBD</Name>"), std::string::npos) << text;
    pugi::xml_document doc;
    EXPECT_TRUE(doc.load_string(text.c_str()));
    EXPECT_STREQ(doc.child("Slave").attribute("Name").value(), "Axis\t1\xEF\xBF\xBD");
}
