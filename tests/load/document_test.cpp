// One input file as a document: the format follows the content, not the file name.

#include <gtest/gtest.h>

#include "esi/load/document.hpp"
#include "support/test_support.hpp"

namespace {

using esi::DocumentFormat;
using esi::document_format;

TEST(DocumentFormat, XmlStartsWithAnAngleBracket) {
    EXPECT_EQ(document_format("<?xml version=\"1.0\"?><EtherCATInfo/>", "x.yaml"), DocumentFormat::esi_xml);
    EXPECT_EQ(document_format("\xEF\xBB\xBF  \r\n<EtherCATInfo/>", "x"), DocumentFormat::esi_xml);
    EXPECT_EQ(document_format(std::string("\xFF\xFE<\0E\0", 6), "x"), DocumentFormat::esi_xml);      // UTF-16LE with BOM
    EXPECT_EQ(document_format(std::string("\0 \0<\0E", 6), "x.yml"), DocumentFormat::esi_xml);      // UTF-16BE, no BOM
}

TEST(DocumentFormat, AnythingElseIsAYamlSource) {
    EXPECT_EQ(document_format("vendor: { id: 1 }\n", "device.xml"), DocumentFormat::yaml_source);
    EXPECT_EQ(document_format("# a comment <not xml>\nvendor: {}\n", "x"), DocumentFormat::yaml_source);
    EXPECT_EQ(document_format("\xEF\xBB\xBF---\n", "x"), DocumentFormat::yaml_source);
}

TEST(DocumentFormat, AnEmptyFileGoesByItsName) {
    EXPECT_EQ(document_format("", "device.yaml"), DocumentFormat::yaml_source);
    EXPECT_EQ(document_format(" \n\t", "device.yml"), DocumentFormat::yaml_source);
    EXPECT_EQ(document_format("", "device.xml"), DocumentFormat::esi_xml);
}

TEST(LoadDocument, AYamlSourceUnderAnXmlNameIsReadAsYaml) {
    esi::test::TempDir dir;
    const auto sample = esi::test::read_text(esi::test::source_dir() / "samples" / "digital-io-8.yaml");
    esi::test::write_text(dir / "device.xml", sample);
    const esi::LoadedDocument loaded = esi::load_document_file(dir / "device.xml");
    EXPECT_EQ(loaded.format, DocumentFormat::yaml_source);
    EXPECT_TRUE(loaded.usable());
    ASSERT_TRUE(loaded.document);
    EXPECT_FALSE(loaded.document->infos.at(0).devices.empty());
}

TEST(LoadDocument, AnEsiFileIsUsableDespiteRuleFindingsButAYamlSourceWithErrorsIsNot) {
    const esi::LoadedDocument esi_file =
        esi::load_document_file(esi::test::source_dir() / "samples" / "esi" / "example-digital-io.xml");
    EXPECT_EQ(esi_file.format, DocumentFormat::esi_xml);
    EXPECT_TRUE(esi_file.usable());

    const esi::LoadedDocument broken = esi::load_document("vendor: { id: 1, name: x }\ndevices: []\n", "broken.yaml");
    EXPECT_EQ(broken.format, DocumentFormat::yaml_source);
    EXPECT_TRUE(broken.diagnostics.has_errors());
    EXPECT_FALSE(broken.usable());
}

TEST(LoadDocument, AMissingFileIsAnIoError) {
    const esi::LoadedDocument loaded = esi::load_document_file("/nonexistent/device.xml");
    EXPECT_FALSE(loaded.usable());
    ASSERT_EQ(loaded.diagnostics.size(), 1u);
    EXPECT_EQ(loaded.diagnostics.items()[0].rule, "io-error");
}

}  // namespace
