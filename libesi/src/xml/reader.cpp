// ESI XML -> model. One pass over the UTF-8 text (xml/tree_parser.hpp) checks it and builds an
// element tree a subtree at a time; every typed field is read by name, everything else is kept
// verbatim in Extras with its position. This file holds the document: decoding, parsing, the
// roots, EtherCATInfo, vendor and groups, and the verbatim store; reader_context.hpp lists the
// files that read the other elements.

#include "esi/xml/reader.hpp"

#include "esi/io/read_file.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <new>
#include <system_error>

#include "esi/encoding.hpp"
#include "esi/xml/foreign_root.hpp"
#include "xml/namespace_prefixes.hpp"
#include "xml/reader_context.hpp"
#include "xml/tree_parser.hpp"
#include "xml/xinclude_check.hpp"

namespace esi {

namespace xml_reader {

void Reader::verbatim(XmlElement& e, const Element n, std::string_view after, std::size_t depth) {
    set(e.name, n.name());
    set(e.after, after);
    e.pos = pos_of(n);
    if (const auto attributes = n.attributes(); !attributes.empty()) {
        e.attributes.reserve(attributes.size());
        for (const Attr& a : attributes) e.attributes.push_back({std::string(a.name), std::string(a.value)});
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
    for (Element c = n.first_child(); c; c = c.next_sibling()) elements += c.kind() == xml_tree::NodeKind::element;
    e.children.reserve(elements);
    std::string_view previous;
    for (Element c = n.first_child(); c; c = c.next_sibling()) {
        if (c.kind() != xml_tree::NodeKind::element) {
            e.text += c.value();
        } else {
            const std::string_view name = c.name();
            verbatim(e.children.emplace_back(), c, previous, depth + 1);
            previous = name;
        }
    }
    // An element's own text is the text before its first child (mixed content): the start of the
    // text. Most kept elements hold only that text: it is assigned, not inserted before nothing.
    if (n.node().has_value) {
        if (e.text.empty()) set(e.text, n.value());
        else e.text.insert(0, n.value());
    }
}

bool Reader::read_image(Images& images, const Element c, std::string_view name) {
    if (is(name, "ImageData16x14")) images.image_data16x14 = hex(c);
    else if (is(name, "Image16x14")) {
        text(images.image16x14, c);
        images.image16x14_pos = pos_of(c);
    } else if (is(name, "ImageFile16x14")) text(images.image_file16x14, c);
    else return false;
    return true;
}

EsiDocument Reader::read_document(const Element root) {
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
        for (const Attr& a : root.attributes()) keep(doc.root_extras, a);
        stream_children(root, [&](const Element c, std::string_view n, std::string_view previous) {
            if (is(n, "EtherCATInfo")) read_info(doc.infos.emplace_back(), c);
            else if (expanded(c)) keep(doc.root_extras, c, previous);
        });
    } else if (is(name, "EtherCATDict")) {
        doc.kind = DocumentKind::ethercat_dict;
        for (const Attr& a : root.attributes()) {
            if (is(a.name, "Version")) doc.dict_version = a.value;
            else keep(doc.root_extras, a);
        }
        stream_children(root, [&](const Element c, std::string_view n, std::string_view previous) {
            if (!expanded(c)) return;
            if (is(n, "Dictionary") && !doc.dictionary) read_dictionary(doc.dictionary.emplace(), c);
            else keep(doc.root_extras, c, previous);
        });
    } else if (is(name, "EtherCATDiag")) {
        // Diagnosis messages (EtherCATDiag.xsd): an ETG root that describes no device.
        doc.kind = DocumentKind::ethercat_diag;
        for (const Attr& a : root.attributes()) keep(doc.root_extras, a);
        stream_children(root, [&](const Element c, std::string_view, std::string_view previous) {
            if (expanded(c)) keep(doc.root_extras, c, previous);
        });
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

// EtherCATInfo (or an EtherCATModule root), streamed: a catalogue's devices and modules are read
// one at a time.
void Reader::read_info(EtherCATInfo& info, const Element n) {
    info.pos = pos_of(n);
    for (const Attr& a : n.attributes()) {
        if (is(a.name, "Version")) info.version = a.value;
        else keep(info.extras, a);
    }
    stream_children(n, [&](const Element c, std::string_view name, std::string_view previous) {
        if (is(name, "Vendor")) {
            if (expanded(c)) read_vendor(info.vendor.emplace(), c);
        } else if (is(name, "Descriptions")) {
            info.has_descriptions = true;
            info.descriptions_pos = pos_of(c);
            for (const Attr& a : c.attributes()) keep(info.descriptions_extras, a);
            stream_children(c, [&](const Element d, std::string_view dn, std::string_view dprev) {
                if (is(dn, "Groups")) {
                    if (!expanded(d)) return;
                    for_children(d, [&](const Element g, std::string_view gn, std::string_view) {
                        if (is(gn, "Group")) read_group(info.groups.emplace_back(), g);
                    });
                } else if (is(dn, "Devices")) {
                    stream_children(d, [&](const Element dev, std::string_view devn, std::string_view) {
                        if (is(devn, "Device") && expanded(dev)) read_device(info.devices.emplace_back(), dev);
                    });
                } else if (is(dn, "Modules")) {
                    info.has_modules = true;
                    read_modules(info, d);
                } else if (expanded(d)) {
                    keep(info.descriptions_extras, d, dprev);
                }
            });
        } else if (is(name, "Modules")) {  // EtherCATModule root
            info.has_modules = true;
            read_modules(info, c);
        } else if (expanded(c)) {
            keep(info.extras, c, previous);
        }
    });
}

void Reader::read_modules(EtherCATInfo& info, const Element n) {
    stream_children(n, [&](const Element m, std::string_view mn, std::string_view) {
        if (is(mn, "Module") && expanded(m)) read_module(info.modules.emplace_back(), m);
    });
}

void Reader::read_vendor(Vendor& v, const Element n) {
    v.pos = pos_of(n);
    for (const Attr& a : n.attributes()) {
        const std::string_view an = a.name;
        if (is(an, "UniqueName")) v.unique_name = a.value;
        else if (is(an, "FileVersion")) v.file_version = a.value;
        else keep(v.extras, a);
    }
    for_children(n, [&](const Element c, std::string_view name, std::string_view previous) {
        if (is(name, "Id")) {
            v.id = u32(c);
            v.id_pos = pos_of(c);
        } else if (is(name, "Name")) localized(v.names, c);
        else if (is(name, "Comment")) localized(v.comments, c);
        else if (is(name, "URL")) localized(v.urls, c);
        else if (is(name, "DescriptionURL")) text(v.description_url, c);
        else if (!read_image(v.images, c, name)) keep(v.extras, c, previous);
    });
}

void Reader::read_group(Group& g, const Element n) {
    g.pos = pos_of(n);
    for (const Attr& a : n.attributes()) {
        const std::string_view an = a.name;
        if (is(an, "SortOrder")) g.sort_order = i32(a, n);
        else if (is(an, "ParentGroup")) g.parent_group = a.value;
        else keep(g.extras, a);
    }
    for_children(n, [&](const Element c, std::string_view name, std::string_view previous) {
        if (is(name, "Type")) {
            text(g.type, c);
            g.type_pos = pos_of(c);
        } else if (is(name, "Name")) localized(g.names, c);
        else if (is(name, "Comment")) localized(g.comments, c);
        else if (!read_image(g.images, c, name)) keep(g.extras, c, previous);
    });
}

}  // namespace xml_reader

namespace {

using xml_reader::Reader;

}  // namespace

ReadResult read_esi(std::string_view bytes, std::string path, const ReadOptions& options) {
    return read_esi_owned(std::string(bytes), std::move(path), options);
}

namespace {

// The text to read, decoded, and what the decoding found.
struct Decoded {
    std::shared_ptr<SourceText> source;
    SourceEncoding encoding = SourceEncoding::utf8;
    std::size_t first_invalid_offset = std::string::npos;
    std::string declared;
};

Decoded decoded_string(std::string bytes, const std::string& path) {
    DecodedText decoded = decode_xml_bytes_owned(std::move(bytes));
    return {std::make_shared<SourceText>(path, std::move(decoded.utf8)), decoded.encoding, decoded.first_invalid_offset,
            std::move(decoded.declared)};
}

ReadResult read_decoded(Decoded decoded, const std::string& path, const ReadOptions& options);

// Reading holds the text, the tree of the largest element read at once and the model: for dense
// markup several times the file, so a file near the input limit can exhaust a machine's memory.
// That is an unreadable input (io-error), never an abort.
template <class Decode>
ReadResult read_guarded(std::size_t size, const std::string& path, const ReadOptions& options, Decode&& decode) {
    try {
        return read_decoded(decode(), path, options);
    } catch (const std::bad_alloc&) {
        ReadResult result;
        result.diagnostics.emplace(Severity::error, "io-error",
                                   "not enough memory to read this file (" + std::to_string(size >> 20) + " MiB of XML)", path,
                                   SourcePos{});
        return result;
    }
}

}  // namespace

ReadResult read_esi_owned(std::string bytes_in, std::string path, const ReadOptions& options) {
    const std::size_t size = bytes_in.size();
    return read_guarded(size, path, options, [&] { return decoded_string(std::move(bytes_in), path); });
}

namespace {

ReadResult read_decoded(Decoded decoded, const std::string& path, const ReadOptions& options) {
    ReadResult result;
    const std::shared_ptr<SourceText> source = std::move(decoded.source);
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

    // NUL bytes are never valid XML characters (and end a C string early).
    if (const auto nul = source->text().find('\0'); nul != std::string::npos) {
        result.diagnostics.emplace(Severity::error, "xml-syntax", "not well-formed: NUL character in the document", path,
                                   source->position_of(nul));
        return result;
    }

    // One pass over the text checks it and builds the element tree, a subtree at a time, while
    // the reader takes each into the model. What the reading finds is kept apart until the pass
    // has reached the end: a document that turns out not to be well-formed gets the xml-syntax
    // error alone, as if nothing had been read.
    xml_tree::Tree tree;
    xml_tree::TreeParser parser(source->text(), decoded.encoding, tree);
    parser.release_behind(source.get());
    Diagnostics xinclude;
    Diagnostics prefixes;
    Diagnostics read;
    EsiDocument doc;
    if (const xml_tree::Element root = parser.root()) {
        // Undeclared namespace prefixes are looked for at the start tags with a prefixed name;
        // XInclude elements at every start tag once the namespace is declared (most files never
        // declare it).
        UndeclaredPrefixCheck prefix_check(*source, parser, root, prefixes);
        if (parser.last_tag_prefixed()) prefix_check.start_tag(root);
        parser.observe(nullptr, &prefix_check);
        const XIncludeCheck xinclude_check(*source, parser, root, xinclude);
        Reader reader(*source, parser, read, options);
        doc = reader.read_document(root);
        parser.finish();
        parser.observe(nullptr, nullptr);
        parser.observe_namespaces(nullptr);
    }
    if (const auto& fault = parser.fault()) {
        result.diagnostics.emplace(Severity::error, "xml-syntax", "not well-formed: " + fault->message, path,
                                   source->position_of(fault->offset));
        return result;
    }
    source->adopt_line_starts(parser.take_line_starts());
    source->adopt_comments(parser.take_comments());
    // A DOCTYPE has no place in an ESI file (the ETG schema defines the format) and is the
    // vehicle of entity-expansion bombs and external entities. It is never processed: entities
    // are not expanded, external ones are never fetched, and references stay as written.
    if (const auto doctype = parser.doctype_declaration()) {
        result.diagnostics.emplace(Severity::warning, "xml-doctype",
                                   doctype->declares_entities
                                       ? "the DOCTYPE declares entities; they are not expanded and external ones are not "
                                         "fetched, so &name; references stay as written"
                                       : "the DOCTYPE is ignored; ESI files are defined by the ETG schema, not a DTD",
                                   path, source->position_of(doctype->offset));
    }
    result.diagnostics.append(std::move(xinclude));
    result.diagnostics.append(std::move(prefixes));
    result.diagnostics.append(std::move(read));
    doc.path = path;
    doc.encoding = decoded.encoding;
    if (options.keep_source) doc.source = source;
    result.document = std::move(doc);
    return result;
}

}  // namespace

// A UTF-8 file is read in place: the bytes as read are the text.
ReadResult read_esi_file(const std::filesystem::path& path, const ReadOptions& options) {
    std::string error;
    std::optional<FileBytes> bytes = read_file_buffer(path, error);
    const std::string name = path.string();
    if (!bytes) {
        ReadResult result;
        result.diagnostics.emplace(Severity::error, "io-error", "cannot read file: " + error, name, SourcePos{});
        return result;
    }
    const std::size_t size = bytes->size();
    return read_guarded(size, name, options, [&] {
        if (std::optional<Utf8InPlace> in_place = utf8_in_place(bytes->view()))
            return Decoded{std::make_shared<SourceText>(name, std::move(*bytes), in_place->offset), in_place->encoding, std::string::npos,
                           std::move(in_place->declared)};
        DecodedText other = decode_xml_bytes(bytes->view());
        *bytes = FileBytes();
        return Decoded{std::make_shared<SourceText>(name, std::move(other.utf8)), other.encoding, other.first_invalid_offset,
                       std::move(other.declared)};
    });
}

}  // namespace esi
