// Catalogue entries for what the XML front end (and the optional schema check) reports. These
// rules have no check function: the reader emits them while it builds the model.
#include "check/areas.hpp"

namespace esi::rules {

namespace {

constexpr Rule xml_syntax{
    .id = "xml-syntax",
    .default_severity = Severity::error,
    .summary = "The file is not well-formed XML",
    .rationale =
        "A master or configuration tool cannot read a file that is not well-formed XML, and every later check "
        "would be guesswork. The seed manuals' own snippets show the typical faults: an end tag without '>' "
        "(`</Name `), a start tag glued to its value (`<Index#x6060</Index>`) and blanks inside the tag "
        "delimiters (`< Data >`) (servo manuals §6.7.4, §5.2; W3C XML 1.0 §3.1).",
    .bad_example = "<InitCmd><Transition>PS</Transition><Index#x6060</Index></InitCmd>",
    .good_example = "<InitCmd><Transition>PS</Transition><Index>#x6060</Index></InitCmd>",
};

constexpr Rule xml_encoding{
    .id = "xml-encoding",
    .default_severity = Severity::error,
    .summary = "Bytes that are not valid in the file's encoding",
    .rationale =
        "XML parsers must reject bytes that do not decode in the declared (or default UTF-8) encoding; xmllint "
        "stops with 'Input is not proper UTF-8, indicate encoding'. A file written in ISO-8859-1 without an "
        "encoding declaration is the usual cause (IgH-generated bus configurations in the corpus). Declare "
        "encoding=\"ISO-8859-1\" or convert to UTF-8. esi-lint replaces the bad bytes and reads on.",
    .bad_example = "<?xml version=\"1.0\"?> ... Schlie\\xDFer ...",
    .good_example = "<?xml version=\"1.0\" encoding=\"ISO-8859-1\"?> ... Schlie\\xDFer ...",
};

constexpr Rule xml_number_format{
    .id = "xml-number-format",
    .default_severity = Severity::error,
    .summary = "A number that is neither decimal nor #x hex",
    .rationale =
        "ETG.2000 HexDecValue is `[+-]?[0-9]+` or `#x[0-9A-Fa-f]+`. Anything else (`#x0x607F`, `12h`, empty) "
        "is read differently by every master, or not at all (ETG.2000 schema, HexDecValue).",
    .bad_example = "<Index>#x0x607F</Index>",
    .good_example = "<Index>#x607F</Index>",
};

constexpr Rule xml_hex_prefix{
    .id = "xml-hex-prefix",
    .default_severity = Severity::warning,
    .summary = "Hex number written with the C prefix 0x",
    .rationale =
        "ESI hex numbers are written `#x…`; `0x…` is not a valid HexDecValue and strict parsers (and the ETG "
        "schema) reject it. esi-lint accepts it so the rest of the file can be checked (ETG.2000 schema, "
        "HexDecValue; XzuluX/EtherCAT.NET #48 shows parsers that expect one notation only).",
    .bad_example = "<Id>0xF3F</Id>",
    .good_example = "<Id>#xF3F</Id>",
};

constexpr Rule xml_boolean_format{
    .id = "xml-boolean-format",
    .default_severity = Severity::error,
    .summary = "A boolean that is not true, false, 1 or 0",
    .rationale =
        "xs:boolean allows exactly true, false, 1 and 0; tools that accept 'yes' or 'TRUE' differ in what they "
        "make of it (W3C XML Schema Part 2 §3.2.2; synapticon/siitool changelog #18).",
    .bad_example = "<RxPdo Fixed=\"yes\">",
    .good_example = "<RxPdo Fixed=\"true\">",
};

constexpr Rule xml_number_range{
    .id = "xml-number-range",
    .default_severity = Severity::error,
    .summary = "A number outside the range of its field",
    .rationale =
        "Indices, sizes and codes have fixed widths (a ProductCode is 32 bits, a SubIndex 8); a value that does "
        "not fit is truncated differently by each tool (ETG.2000 DeviceType; ETG.1000.6 object addressing).",
    .bad_example = "<Type ProductCode=\"#x1FFFFFFFF\">",
    .good_example = "<Type ProductCode=\"#xFFFFFFFF\">",
};

constexpr Rule xml_missing_element{
    .id = "xml-missing-element",
    .default_severity = Severity::error,
    .summary = "An element the schema requires is missing",
    .rationale =
        "A PDO without Index, an Entry without BitLen or an Object without Index cannot be mapped or addressed; "
        "the ETG schema requires these elements (ETG.2000 PdoType, EntryType, ObjectType).",
    .bad_example = "<RxPdo Sm=\"2\"><Name>Outputs</Name></RxPdo>",
    .good_example = "<RxPdo Sm=\"2\"><Index>#x1600</Index><Name>Outputs</Name></RxPdo>",
};

constexpr Rule xml_unknown_root{
    .id = "xml-unknown-root",
    .default_severity = Severity::error,
    .summary = "The root element is not an ESI root",
    .rationale =
        "An ESI file starts with EtherCATInfo (or EtherCATModule, EtherCATDict, EtherCATInfoList); anything else "
        "is not a device description (ETG.2000 §4; schema files EtherCATInfo.xsd, EtherCATModule.xsd, "
        "EtherCATDict.xsd).",
    .bad_example = "<DeviceInfo>…</DeviceInfo>",
    .good_example = "<EtherCATInfo Version=\"1.17\">…</EtherCATInfo>",
};

constexpr Rule xml_nesting_depth{
    .id = "xml-nesting-depth",
    .default_severity = Severity::error,
    .summary = "Elements nested unreasonably deep",
    .rationale =
        "No ESI element nests more than a few dozen levels; hundreds of levels are a corrupt or hostile file. "
        "Deeper content is not kept so that reading stays bounded in time and memory (see docs/reliability.md).",
    .bad_example = "<VendorSpecific><a><a><a>… (thousands deep)",
    .good_example = "<VendorSpecific><Note>…</Note></VendorSpecific>",
};

constexpr Rule xml_doctype{
    .id = "xml-doctype",
    .default_severity = Severity::warning,
    .summary = "A DOCTYPE declaration, which is ignored",
    .rationale =
        "ESI files are defined by the ETG schema, not a DTD; no vendor file carries a DOCTYPE. A DOCTYPE with "
        "entity declarations is how entity-expansion bombs (\"billion laughs\") and external entities (XXE: "
        "reading local files or URLs) get into an XML reader (OWASP XXE Prevention Cheat Sheet). esi-lint never "
        "processes it: entities are not expanded, nothing is fetched, and `&name;` references stay as written.",
    .bad_example = "<!DOCTYPE EtherCATInfo [<!ENTITY vendor SYSTEM \"file:///etc/passwd\">]>",
    .good_example = "<?xml version=\"1.0\" encoding=\"UTF-8\"?> (no DOCTYPE)",
};

constexpr Rule xml_schema{
    .id = "xml-schema",
    .default_severity = Severity::error,
    .summary = "The file does not validate against the ETG schema (--xsd)",
    .rationale =
        "Reported only with --xsd DIR: libxml2 validates the file against the ETG schema files in DIR "
        "(EtherCATInfo.xsd, EtherCATModule.xsd, EtherCATDict.xsd). Masters and the ETG conformance test tool "
        "expect schema-valid files (ETG.2000; CTT TF-1300).",
    .bad_example = "<Sm StartAddress=\"0x1000\">MBoxOut</Sm>",
    .good_example = "<Sm StartAddress=\"#x1000\">MBoxOut</Sm>",
};

constexpr Rule lint_directive{
    .id = "lint-directive",
    .default_severity = Severity::warning,
    .summary = "A malformed esi-lint comment directive",
    .rationale =
        "Inline directives are `<!-- esi-lint: disable=RULE -->`, `enable=RULE` and `disable-next-line=RULE`; "
        "a misspelt directive or rule id would silently suppress nothing, so it is reported.",
    .bad_example = "<!-- esi-lint: disabel=sm-size-zero -->",
    .good_example = "<!-- esi-lint: disable=sm-size-zero -->",
};

}  // namespace

void add_xml(std::vector<Rule>& out) {
    out.insert(out.end(), {
        xml_syntax,
        xml_encoding,
        xml_number_format,
        xml_hex_prefix,
        xml_boolean_format,
        xml_number_range,
        xml_missing_element,
        xml_unknown_root,
        xml_nesting_depth,
        xml_doctype,
        xml_schema,
        lint_directive,
    });
}

}  // namespace esi::rules
