// Catalogue entries for what the XML front end (and the optional schema check) reports. These
// rules have no check function: the reader emits them while it builds the model.
#include "check/areas.hpp"

namespace esi::rules {

void add_xml(std::vector<Rule>& out) {
    out.push_back(Rule{
        "xml-syntax", Severity::error, "The file is not well-formed XML",
        "A master or configuration tool cannot read a file that is not well-formed XML, and every later check "
        "would be guesswork. The seed manuals' own snippets show the typical faults: an end tag without '>' "
        "(`</Name `), a start tag glued to its value (`<Index#x6060</Index>`) and blanks inside the tag "
        "delimiters (`< Data >`) (servo manuals §6.7.4, §5.2; W3C XML 1.0 §3.1).",
        "<InitCmd><Transition>PS</Transition><Index#x6060</Index></InitCmd>",
        "<InitCmd><Transition>PS</Transition><Index>#x6060</Index></InitCmd>"});
    out.push_back(Rule{
        "xml-encoding", Severity::error, "Bytes that are not valid in the file's encoding",
        "XML parsers must reject bytes that do not decode in the declared (or default UTF-8) encoding; xmllint "
        "stops with 'Input is not proper UTF-8, indicate encoding'. A file written in ISO-8859-1 without an "
        "encoding declaration is the usual cause (IgH-generated bus configurations in the corpus). Declare "
        "encoding=\"ISO-8859-1\" or convert to UTF-8. esi-lint replaces the bad bytes and reads on.",
        "<?xml version=\"1.0\"?> ... Schlie\\xDFer ...",
        "<?xml version=\"1.0\" encoding=\"ISO-8859-1\"?> ... Schlie\\xDFer ..."});
    out.push_back(Rule{
        "xml-number-format", Severity::error, "A number that is neither decimal nor #x hex",
        "ETG.2000 HexDecValue is `[+-]?[0-9]+` or `#x[0-9A-Fa-f]+`. Anything else (`#x0x607F`, `12h`, empty) "
        "is read differently by every master, or not at all (ETG.2000 schema, HexDecValue).",
        "<Index>#x0x607F</Index>", "<Index>#x607F</Index>"});
    out.push_back(Rule{
        "xml-hex-prefix", Severity::warning, "Hex number written with the C prefix 0x",
        "ESI hex numbers are written `#x…`; `0x…` is not a valid HexDecValue and strict parsers (and the ETG "
        "schema) reject it. esi-lint accepts it so the rest of the file can be checked (ETG.2000 schema, "
        "HexDecValue; XzuluX/EtherCAT.NET #48 shows parsers that expect one notation only).",
        "<Id>0xF3F</Id>", "<Id>#xF3F</Id>"});
    out.push_back(Rule{
        "xml-boolean-format", Severity::error, "A boolean that is not true, false, 1 or 0",
        "xs:boolean allows exactly true, false, 1 and 0; tools that accept 'yes' or 'TRUE' differ in what they "
        "make of it (W3C XML Schema Part 2 §3.2.2; synapticon/siitool changelog #18).",
        "<RxPdo Fixed=\"yes\">", "<RxPdo Fixed=\"true\">"});
    out.push_back(Rule{
        "xml-number-range", Severity::error, "A number outside the range of its field",
        "Indices, sizes and codes have fixed widths (a ProductCode is 32 bits, a SubIndex 8); a value that does "
        "not fit is truncated differently by each tool (ETG.2000 DeviceType; ETG.1000.6 object addressing).",
        "<Type ProductCode=\"#x1FFFFFFFF\">", "<Type ProductCode=\"#xFFFFFFFF\">"});
    out.push_back(Rule{
        "xml-missing-element", Severity::error, "An element the schema requires is missing",
        "A PDO without Index, an Entry without BitLen or an Object without Index cannot be mapped or addressed; "
        "the ETG schema requires these elements (ETG.2000 PdoType, EntryType, ObjectType).",
        "<RxPdo Sm=\"2\"><Name>Outputs</Name></RxPdo>",
        "<RxPdo Sm=\"2\"><Index>#x1600</Index><Name>Outputs</Name></RxPdo>"});
    out.push_back(Rule{
        "xml-unknown-root", Severity::error, "The root element is not an ESI root",
        "An ESI file starts with EtherCATInfo (or EtherCATModule, EtherCATDict, EtherCATInfoList); anything else "
        "is not a device description (ETG.2000 §4; schema files EtherCATInfo.xsd, EtherCATModule.xsd, "
        "EtherCATDict.xsd).",
        "<DeviceInfo>…</DeviceInfo>", "<EtherCATInfo Version=\"1.17\">…</EtherCATInfo>"});
    out.push_back(Rule{
        "xml-nesting-depth", Severity::error, "Elements nested unreasonably deep",
        "No ESI element nests more than a few dozen levels; hundreds of levels are a corrupt or hostile file. "
        "Deeper content is not kept so that reading stays bounded in time and memory (see docs/reliability.md).",
        "<VendorSpecific><a><a><a>… (thousands deep)", "<VendorSpecific><Note>…</Note></VendorSpecific>"});
    out.push_back(Rule{
        "xml-doctype", Severity::warning, "A DOCTYPE declaration, which is ignored",
        "ESI files are defined by the ETG schema, not a DTD; no vendor file carries a DOCTYPE. A DOCTYPE with "
        "entity declarations is how entity-expansion bombs (\"billion laughs\") and external entities (XXE: "
        "reading local files or URLs) get into an XML reader (OWASP XXE Prevention Cheat Sheet). esi-lint never "
        "processes it: entities are not expanded, nothing is fetched, and `&name;` references stay as written.",
        "<!DOCTYPE EtherCATInfo [<!ENTITY vendor SYSTEM \"file:///etc/passwd\">]>",
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?> (no DOCTYPE)"});
    out.push_back(Rule{
        "xml-xinclude", Severity::error, "An XInclude element, which ESI does not know",
        "ETG.2000 defines no inclusion mechanism: masters and configuration tools read xi:include as an unknown "
        "element, not as the content it names (W3C XML Inclusions is an optional layer above XML 1.0). esi-lint "
        "does not resolve it (that would read or fetch other files), and esi-gen would copy the element into "
        "generated ESI and YAML with an href that no longer points anywhere, so the file is refused until the "
        "include is expanded (xmllint --xinclude).",
        "<Dictionary><xi:include xmlns:xi=\"http://www.w3.org/2001/XInclude\" href=\"objects.xml\"/></Dictionary>",
        "<Dictionary><Objects>…</Objects></Dictionary>"});
    out.push_back(Rule{
        "xml-schema", Severity::error, "The file does not validate against the ETG schema (--xsd)",
        "Reported only with --xsd DIR: libxml2 validates the file against the ETG schema files in DIR "
        "(EtherCATInfo.xsd, EtherCATModule.xsd, EtherCATDict.xsd). Masters and the ETG conformance test tool "
        "expect schema-valid files (ETG.2000; CTT TF-1300).",
        "<Sm StartAddress=\"0x1000\">MBoxOut</Sm>", "<Sm StartAddress=\"#x1000\">MBoxOut</Sm>"});
    out.push_back(Rule{
        "lint-directive", Severity::warning, "A malformed esi-lint comment directive",
        "Inline directives are `<!-- esi-lint: disable=RULE -->`, `enable=RULE` and `disable-next-line=RULE`; "
        "a misspelt directive or rule id would silently suppress nothing, so it is reported.",
        "<!-- esi-lint: disabel=sm-size-zero -->", "<!-- esi-lint: disable=sm-size-zero -->"});
}

}  // namespace esi::rules
