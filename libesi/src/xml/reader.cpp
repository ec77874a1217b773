// ESI XML -> model. One pass over a pugixml DOM built from the UTF-8 text; every typed field is
// read by name, everything else is kept verbatim in Extras with its position. This file holds
// the document: decoding, parsing, the roots, EtherCATInfo, vendor and groups, and the verbatim
// store; reader_context.hpp lists the files that read the other elements.

#include "esi/xml/reader.hpp"

#include "esi/io/read_file.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <new>
#include <pugixml.hpp>
#include <system_error>

#include "esi/encoding.hpp"
#include "xml/reader_context.hpp"
#include "esi/xml/foreign_root.hpp"
#include "esi/xml/well_formed.hpp"
#include "esi/xml/xinclude.hpp"
#include "xml/namespace_prefixes.hpp"

namespace esi {

namespace xml_reader {

void Reader::verbatim(XmlElement& e, const pugi::xml_node n, std::string_view after, std::size_t depth) {
    e.name = n.name();
    e.after = after;
    e.pos = pos_of(n);
    if (pugi::xml_attribute first = n.first_attribute()) {
        // Counted first: grown one by one, the vector moved its strings at every doubling.
        std::size_t count = 0;
        for (pugi::xml_attribute a = first; a; a = a.next_attribute()) ++count;
        e.attributes.reserve(count);
        for (pugi::xml_attribute a = first; a; a = a.next_attribute()) e.attributes.push_back({a.name(), a.value()});
    }
    if (depth >= options_.max_verbatim_depth) {
        if (!depth_reported_) {
            report(Severity::error, "xml-nesting-depth",
                   "elements nested deeper than " + std::to_string(options_.max_verbatim_depth) + " levels are not kept",
                   e.pos);
            depth_reported_ = true;
        }
        return;
    }
    std::size_t elements = 0;  // reserved up front: an XmlElement is 152 bytes to move on growth
    for (pugi::xml_node c = n.first_child(); c; c = c.next_sibling()) elements += c.name()[0] != '\0';
    e.children.reserve(elements);
    std::string_view previous;
    for (pugi::xml_node c = n.first_child(); c; c = c.next_sibling()) {
        const pugi::xml_node_type type = c.type();
        if (type == pugi::node_pcdata || type == pugi::node_cdata) {
            e.text += c.value();
        } else if (type == pugi::node_element) {
            const std::string_view name = c.name();
            verbatim(e.children.emplace_back(), c, previous, depth + 1);
            previous = name;
        }
    }
    // parse_embed_pcdata stores the text that comes before any child element in the
    // element's own value, not as a child: it is the start of the text (mixed content).
    // Most kept elements hold only that text: it is assigned, not inserted before nothing.
    if (const char* embedded = n.value(); embedded[0] != '\0') {
        if (e.text.empty()) e.text.assign(embedded);
        else e.text.insert(0, embedded);
    }
}

bool Reader::read_image(Images& images, const pugi::xml_node c, std::string_view name) {
    if (is(name, "ImageData16x14")) images.image_data16x14 = hex(c);
    else if (is(name, "Image16x14")) {
        images.image16x14 = text_of(c);
        images.image16x14_pos = pos_of(c);
    } else if (is(name, "ImageFile16x14")) images.image_file16x14 = text_of(c);
    else return false;
    return true;
}

EsiDocument Reader::read_document(const pugi::xml_node root) {
    EsiDocument doc;
    doc.root_pos = pos_of(root);
    const std::string_view name = root.name();
    if (is(name, "EtherCATInfo")) {
        doc.kind = DocumentKind::ethercat_info;
        read_info(doc.infos.emplace_back(), root);
    } else if (is(name, "EtherCATModule")) {
        doc.kind = DocumentKind::ethercat_module;
        read_info(doc.infos.emplace_back(), root);
    } else if (is(name, "EtherCATInfoList")) {
        doc.kind = DocumentKind::ethercat_info_list;
        for (pugi::xml_attribute a = root.first_attribute(); a; a = a.next_attribute()) keep(doc.root_extras, a);
        for_children(root, [&](const pugi::xml_node c, std::string_view n, std::string_view previous) {
            if (is(n, "EtherCATInfo")) read_info(doc.infos.emplace_back(), c);
            else keep(doc.root_extras, c, previous);
        });
    } else if (is(name, "EtherCATDict")) {
        doc.kind = DocumentKind::ethercat_dict;
        for (pugi::xml_attribute a = root.first_attribute(); a; a = a.next_attribute()) {
            if (is(a.name(), "Version")) doc.dict_version = a.value();
            else keep(doc.root_extras, a);
        }
        for_children(root, [&](const pugi::xml_node c, std::string_view n, std::string_view previous) {
            if (is(n, "Dictionary") && !doc.dictionary) read_dictionary(doc.dictionary.emplace(), c);
            else keep(doc.root_extras, c, previous);
        });
    } else if (is(name, "EtherCATDiag")) {
        // Diagnosis messages (EtherCATDiag.xsd): an ETG root that describes no device.
        doc.kind = DocumentKind::ethercat_diag;
        for (pugi::xml_attribute a = root.first_attribute(); a; a = a.next_attribute()) keep(doc.root_extras, a);
        for_children(root, [&](const pugi::xml_node c, std::string_view, std::string_view previous) { keep(doc.root_extras, c, previous); });
    } else {
        doc.kind = DocumentKind::unknown;
        const std::string_view local = name.substr(name.find(':') == std::string_view::npos ? 0 : name.find(':') + 1);
        if (const std::optional<ForeignDocument> foreign = recognise_foreign_root(local))
            report(Severity::error, "xml-unknown-root",
                   "not an ESI file (" + std::string(foreign->what) + ", root element <" + std::string(name) +
                       ">); ESI files describe devices and start with EtherCATInfo",
                   doc.root_pos);
        else
            report(Severity::error, "xml-unknown-root",
                   "root element <" + std::string(name) +
                       "> is not an ESI root (EtherCATInfo, EtherCATInfoList, EtherCATModule, EtherCATDict or EtherCATDiag)",
                   doc.root_pos);
    }
    return doc;
}

void Reader::read_info(EtherCATInfo& info, const pugi::xml_node n) {
    info.pos = pos_of(n);
    for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute()) {
        if (is(a.name(), "Version")) info.version = a.value();
        else keep(info.extras, a);
    }
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (is(name, "Vendor")) {
            read_vendor(info.vendor.emplace(), c);
        } else if (is(name, "Descriptions")) {
            info.has_descriptions = true;
            info.descriptions_pos = pos_of(c);
            for (pugi::xml_attribute a = c.first_attribute(); a; a = a.next_attribute()) keep(info.descriptions_extras, a);
            for_children(c, [&](const pugi::xml_node d, std::string_view dn, std::string_view dprev) {
                if (is(dn, "Groups")) {
                    for_children(d, [&](const pugi::xml_node g, std::string_view gn, std::string_view) {
                        if (is(gn, "Group")) read_group(info.groups.emplace_back(), g);
                    });
                } else if (is(dn, "Devices")) {
                    reserve_for(info.devices, d, "Device");
                    for_children(d, [&](const pugi::xml_node dev, std::string_view devn, std::string_view) {
                        if (!is(devn, "Device")) return;
                        read_device(info.devices.emplace_back(), dev);
                        release(d, dev);
                    });
                } else if (is(dn, "Modules")) {
                    info.has_modules = true;
                    for_children(d, [&](const pugi::xml_node m, std::string_view mn, std::string_view) {
                        if (!is(mn, "Module")) return;
                        read_module(info.modules.emplace_back(), m);
                        release(d, m);
                    });
                } else {
                    keep(info.descriptions_extras, d, dprev);
                }
            });
        } else if (is(name, "Modules")) {  // EtherCATModule root
            info.has_modules = true;
            for_children(c, [&](const pugi::xml_node m, std::string_view mn, std::string_view) {
                if (!is(mn, "Module")) return;
                read_module(info.modules.emplace_back(), m);
                release(c, m);
            });
        } else {
            keep(info.extras, c, previous);
        }
    });
}

void Reader::read_vendor(Vendor& v, const pugi::xml_node n) {
    v.pos = pos_of(n);
    for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute()) {
        const std::string_view an = a.name();
        if (is(an, "UniqueName")) v.unique_name = a.value();
        else if (is(an, "FileVersion")) v.file_version = a.value();
        else keep(v.extras, a);
    }
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (is(name, "Id")) {
            v.id = u32(c);
            v.id_pos = pos_of(c);
        } else if (is(name, "Name")) v.names.push_back(localized(c));
        else if (is(name, "Comment")) v.comments.push_back(localized(c));
        else if (is(name, "URL")) v.urls.push_back(localized(c));
        else if (is(name, "DescriptionURL")) v.description_url = text_of(c);
        else if (!read_image(v.images, c, name)) keep(v.extras, c, previous);
    });
}

void Reader::read_group(Group& g, const pugi::xml_node n) {
    g.pos = pos_of(n);
    for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute()) {
        const std::string_view an = a.name();
        if (is(an, "SortOrder")) g.sort_order = i32(a, n);
        else if (is(an, "ParentGroup")) g.parent_group = a.value();
        else keep(g.extras, a);
    }
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (is(name, "Type")) {
            g.type = text_of(c);
            g.type_pos = pos_of(c);
        } else if (is(name, "Name")) g.names.push_back(localized(c));
        else if (is(name, "Comment")) g.comments.push_back(localized(c));
        else if (!read_image(g.images, c, name)) keep(g.extras, c, previous);
    });
}

}  // namespace xml_reader

namespace {

using xml_reader::Reader;

std::string describe_parse_error(const pugi::xml_parse_result& result) {
    switch (result.status) {
        case pugi::status_unrecognized_tag: return "not well-formed: unrecognized or malformed tag";
        case pugi::status_bad_start_element: return "not well-formed: malformed start tag";
        case pugi::status_bad_end_element: return "not well-formed: malformed end tag";
        case pugi::status_end_element_mismatch: return "not well-formed: start and end tags do not match";
        case pugi::status_bad_attribute: return "not well-formed: malformed attribute";
        case pugi::status_bad_pcdata: return "not well-formed: malformed character data";
        case pugi::status_bad_cdata: return "not well-formed: malformed CDATA section";
        case pugi::status_bad_comment: return "not well-formed: malformed comment";
        case pugi::status_bad_pi: return "not well-formed: malformed processing instruction or XML declaration";
        case pugi::status_bad_doctype: return "not well-formed: malformed DOCTYPE";
        case pugi::status_no_document_element: return "not well-formed: no root element";
        default: return std::string("not well-formed: ") + result.description();
    }
}

SourcePos error_position(const SourceText& source, const pugi::xml_parse_result& result) {
    auto offset = static_cast<std::size_t>(result.offset < 0 ? 0 : result.offset);
    offset = std::min(offset, source.text().size());
    // A malformed tag is reported where the parser gave up, which may be past the blanks after
    // it (`</Name ⏎ <`); point at the '<' that opened the broken tag instead, as users look there.
    if (result.status == pugi::status_bad_end_element || result.status == pugi::status_bad_start_element) {
        const auto open = source.text().rfind('<', offset > 0 ? offset - 1 : 0);
        if (open != std::string::npos) offset = open;
    }
    return source.position_of(offset);
}

}  // namespace

ReadResult read_esi(std::string_view bytes, std::string path, const ReadOptions& options) {
    return read_esi_owned(std::string(bytes), std::move(path), options);
}

namespace {
ReadResult read_unguarded(std::string bytes_in, std::string path, const ReadOptions& options);
}  // namespace

// Reading holds the text twice and pugixml's tree (64 bytes an element), up to ten times the
// file for dense markup: a file near the input limit can exhaust a machine's memory. That is an
// unreadable input (io-error), never an abort.
ReadResult read_esi_owned(std::string bytes_in, std::string path, const ReadOptions& options) {
    const std::size_t size = bytes_in.size();
    try {
        return read_unguarded(std::move(bytes_in), path, options);
    } catch (const std::bad_alloc&) {
        ReadResult result;
        result.diagnostics.emplace(Severity::error, "io-error",
                                   "not enough memory to read this file (" + std::to_string(size >> 20) + " MiB of XML)", path,
                                   SourcePos{});
        return result;
    }
}

namespace {

ReadResult read_unguarded(std::string bytes_in, std::string path, const ReadOptions& options) {
    ReadResult result;
    DecodedText decoded = decode_xml_bytes_owned(std::move(bytes_in));
    auto source = std::make_shared<SourceText>(path, std::move(decoded.utf8));
    result.source = source;

    if (decoded.first_invalid_offset != std::string::npos) {
        const bool utf16 = decoded.encoding == SourceEncoding::utf16le || decoded.encoding == SourceEncoding::utf16be;
        const SourcePos pos = source->position_of(decoded.first_invalid_offset);
        result.diagnostics.emplace(Severity::error, "xml-encoding",
                                   utf16 ? "input is not valid UTF-16 (lone surrogate or odd length); the bad units were replaced"
                                         : "input is not valid " + std::string(to_string(decoded.encoding)) +
                                               (decoded.declared.empty() ? " and declares no encoding" : "") +
                                               "; the bad bytes were replaced with U+FFFD",
                                   path, pos);
    }

    // NUL bytes end pugixml's strings early and are never valid XML characters.
    if (const auto nul = source->text().find('\0'); nul != std::string::npos) {
        result.diagnostics.emplace(Severity::error, "xml-syntax", "not well-formed: NUL character in the document", path,
                                   source->position_of(nul));
        return result;
    }

    // pugixml parses a copy in place (as load_buffer would copy it itself): the SourceText stays
    // as written, for quoting lines and finding suppressions. In a big document the reader gives
    // the copy's pages back as it goes (ReadOptions::release_elements_from_bytes).
    const bool releasing = source->text().size() >= options.release_elements_from_bytes;
    xml_reader::ParseBuffer buffer(source->text(), releasing);
    pugi::xml_document xml;
    // No comments or processing instructions in the tree (for_children relies on it); text before
    // an element's first child is stored in the element itself. A DOCTYPE is kept as a node (pugixml
    // accepts one only before the root element, never inside it) so that it can be reported below.
    // parse_fragment keeps text after the root element as a node, for the well-formedness check.
    const unsigned parse_options = pugi::parse_default | pugi::parse_embed_pcdata | pugi::parse_doctype | pugi::parse_fragment;
    const pugi::xml_parse_result parsed = xml.load_buffer_inplace(buffer.data(), buffer.size(), parse_options, pugi::encoding_utf8);
    if (!parsed) {
        result.diagnostics.emplace(Severity::error, "xml-syntax", describe_parse_error(parsed), path,
                                   error_position(*source, parsed));
        return result;
    }
    if (const auto fault = find_well_formedness_fault(source->text(), decoded.encoding, xml, buffer.data())) {
        result.diagnostics.emplace(Severity::error, "xml-syntax", "not well-formed: " + fault->message, path,
                                   source->position_of(fault->offset));
        return result;
    }
    // A DOCTYPE has no place in an ESI file (the ETG schema defines the format) and is the
    // vehicle of entity-expansion bombs and external entities. It is never processed: entities
    // are not expanded, external ones are never fetched, and references stay as written.
    for (const pugi::xml_node n : xml.children()) {
        if (n.type() != pugi::node_doctype) continue;
        const std::string_view declaration = n.value();
        std::size_t at = static_cast<std::size_t>(std::max<std::ptrdiff_t>(n.offset_debug(), 0));
        if (const auto open = source->text().rfind("<!", at); open != std::string::npos) at = open;
        const bool entities = declaration.find("<!ENTITY") != std::string_view::npos;
        result.diagnostics.emplace(Severity::warning, "xml-doctype",
                                   entities ? "the DOCTYPE declares entities; they are not expanded and external ones are not "
                                              "fetched, so &name; references stay as written"
                                            : "the DOCTYPE is ignored; ESI files are defined by the ETG schema, not a DTD",
                                   path, source->position_of(at));
    }
    const pugi::xml_node root = xml.document_element();
    if (!root) {
        result.diagnostics.emplace(Severity::error, "xml-syntax", "not well-formed: no root element", path, SourcePos{1, 1});
        return result;
    }
    report_xinclude(*source, xml, buffer.data(), result.diagnostics);
    report_undeclared_prefixes(*source, xml, buffer.data(), result.diagnostics);
    Reader reader(*source, buffer, releasing, result.diagnostics, options);
    EsiDocument doc = reader.read_document(root);
    doc.path = path;
    doc.encoding = decoded.encoding;
    if (options.keep_source) doc.source = source;
    result.document = std::move(doc);
    return result;
}

}  // namespace

ReadResult read_esi_file(const std::filesystem::path& path, const ReadOptions& options) {
    std::string error;
    std::optional<std::string> bytes = read_file_bytes(path, error);
    if (!bytes) {
        ReadResult result;
        result.diagnostics.emplace(Severity::error, "io-error", "cannot read file: " + error, path.string(), SourcePos{});
        return result;
    }
    return read_esi_owned(std::move(*bytes), path.string(), options);
}

}  // namespace esi
