// ESI XML -> model. One pass over a pugixml DOM built from the UTF-8 text; every typed field is
// read by name, everything else is kept verbatim in Extras with its position.

#include "esi/xml/reader.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <new>
#include <pugixml.hpp>
#include <sstream>
#include <system_error>

#include "esi/encoding.hpp"
#include "esi/number.hpp"
#include "xml/well_formed.hpp"
#include "xml/xinclude.hpp"

namespace esi {

namespace {

// Element and attribute names are compared with literals about ten times per element. This
// compares the length, then a memcmp whose length is known at compile time, which the compiler
// turns into a load or two; string_view's operator== was an out-of-line call plus a memcmp call.
// (always_inline: GCC otherwise keeps some instances out of line, a call per compare.)
template <std::size_t N>
[[gnu::always_inline]] inline bool is(std::string_view name, const char (&literal)[N]) {
    return name.size() == N - 1 && std::memcmp(name.data(), literal, N - 1) == 0;
}

class Reader {
public:
    // `buffer` is the copy of the source text pugixml parsed in place.
    Reader(const SourceText& source, std::string_view buffer, Diagnostics& diagnostics, const ReadOptions& options)
        : source_(source), buffer_(buffer), cursor_(source), diagnostics_(diagnostics), options_(options) {}

    EsiDocument read_document(const pugi::xml_node root);

private:
    // ---- positions and diagnostics ------------------------------------------------------
    // Where an element starts: the '<' before its name. Parsed in place, the name lies in our
    // buffer at its offset in the text; one name() call finds it, where offset_debug() and
    // type() cost two calls and ~45 instructions for every element read.
    SourcePos pos_of(const pugi::xml_node element) {
        const auto name = reinterpret_cast<std::uintptr_t>(element.name());
        const auto begin = reinterpret_cast<std::uintptr_t>(buffer_.data());
        if (name < begin || name >= begin + buffer_.size()) return {};  // not from the parse
        const std::size_t offset = name - begin;
        return cursor_.position_of(offset > 0 ? offset - 1 : 0);
    }

    void report(Severity severity, std::string rule, std::string message, SourcePos pos) {
        diagnostics_.emplace(severity, std::move(rule), std::move(message), source_.path(), pos);
    }

    // ---- scalar values -------------------------------------------------------------------
    // An element's character data. With parse_embed_pcdata it is the element's own value: one
    // call instead of the three of text().get(), which only differs for text that is not
    // embedded (CDATA, text after a comment or a child) and is asked then.
    static const char* pcdata(const pugi::xml_node n) {
        const char* value = n.value();
        return *value ? value : n.text().get();
    }
    static std::string text_of(const pugi::xml_node node) { return std::string(trim(pcdata(node))); }

    // Where a scalar was read from: named ("Sm@StartAddress", or the element's name) and located
    // only when the value is bad. Building that name and position for every number used to cost
    // a string allocation and a position lookup per attribute, most of them thrown away.
    struct ValueSite {
        pugi::xml_node element;
        pugi::xml_attribute attribute = {};
        std::string_view label = {};  // used instead of the element/attribute names when set
    };
    static std::string describe(const ValueSite& site) {
        if (!site.label.empty()) return std::string(site.label);
        if (site.attribute) return std::string(site.element.name()) + "@" + site.attribute.name();
        return site.element.name();
    }

    std::optional<Number> number(std::string_view text, const ValueSite& site) {
        const ParsedNumber parsed = parse_number(text);
        if (!parsed.ok()) {
            report(Severity::error, "xml-number-format",
                   describe(site) + ": '" + excerpt(trim(text)) + "' is not a number (" + std::string(to_string(parsed.error)) +
                       "); ESI numbers are decimal or #x hex",
                   pos_of(site.element));
            return std::nullopt;
        }
        if (parsed.syntax == NumberSyntax::c_hex) {
            report(Severity::warning, "xml-hex-prefix",
                   describe(site) + ": '" + excerpt(trim(text)) + "' uses the C prefix 0x; ESI hex numbers are written #x",
                   pos_of(site.element));
        }
        return parsed.value;
    }
    std::optional<Number> number(const pugi::xml_node n) { return number(pcdata(n), ValueSite{n}); }

    template <class T>
    std::optional<T> integer(std::string_view text, const ValueSite& site) {
        const std::optional<Number> n = number(text, site);
        if (!n) return std::nullopt;
        if constexpr (std::is_signed_v<T>) {
            const auto v = n->as_int64();
            if (!v || *v < std::numeric_limits<T>::min() || *v > std::numeric_limits<T>::max()) {
                report(Severity::error, "xml-number-range", describe(site) + ": " + format_decimal(*n) + " is out of range",
                       pos_of(site.element));
                return std::nullopt;
            }
            return static_cast<T>(*v);
        } else {
            const auto v = n->as_uint64();
            if (!v || *v > std::numeric_limits<T>::max()) {
                report(Severity::error, "xml-number-range",
                       describe(site) + ": " + format_decimal(*n) + " is out of range (0.." +
                           std::to_string(std::numeric_limits<T>::max()) + ")",
                       pos_of(site.element));
                return std::nullopt;
            }
            return static_cast<T>(*v);
        }
    }

    std::optional<std::uint32_t> u32(const pugi::xml_attribute a, const pugi::xml_node owner) {
        return integer<std::uint32_t>(a.value(), ValueSite{owner, a});
    }
    std::optional<std::int32_t> i32(const pugi::xml_attribute a, const pugi::xml_node owner) {
        return integer<std::int32_t>(a.value(), ValueSite{owner, a});
    }
    std::optional<std::uint32_t> u32(const pugi::xml_node n) { return integer<std::uint32_t>(pcdata(n), ValueSite{n}); }
    std::optional<std::int32_t> i32(const pugi::xml_node n) { return integer<std::int32_t>(pcdata(n), ValueSite{n}); }
    std::optional<std::int64_t> i64(const pugi::xml_node n) { return integer<std::int64_t>(pcdata(n), ValueSite{n}); }
    std::optional<std::uint64_t> u64(const pugi::xml_node n) { return integer<std::uint64_t>(pcdata(n), ValueSite{n}); }

    std::optional<bool> boolean(std::string_view text, const ValueSite& site) {
        const auto b = parse_boolean(text);
        if (!b)
            report(Severity::error, "xml-boolean-format",
                   describe(site) + ": '" + excerpt(trim(text)) + "' is not a boolean (true, false, 1 or 0)", pos_of(site.element));
        return b;
    }
    std::optional<bool> boolean(const pugi::xml_attribute a, const pugi::xml_node owner) { return boolean(a.value(), ValueSite{owner, a}); }
    std::optional<bool> boolean(const pugi::xml_node n) { return boolean(pcdata(n), ValueSite{n}); }

    HexData hex(const pugi::xml_node n) {
        HexData out;
        out.pos = pos_of(n);
        const std::string_view raw = trim(pcdata(n));
        const auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
        // Hex data is almost never split over lines. The test for a blank is two compares per
        // byte (only bytes up to ' ' can be one); find_first_of(" \t\n\r") searched the set
        // for every byte, some 500 instructions per DefaultData.
        if (std::none_of(raw.begin(), raw.end(), [&](char c) { return static_cast<unsigned char>(c) <= ' ' && is_space(c); })) {
            out.text.assign(raw);
            return out;
        }
        out.text.reserve(raw.size());
        for (char c : raw)
            if (!is_space(c)) out.text.push_back(c);
        return out;
    }

    LocalizedText localized(const pugi::xml_node n) {
        LocalizedText t;
        t.text = text_of(n);
        t.pos = pos_of(n);
        for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute()) {
            if (is(a.name(), "LcId")) t.lcid = integer<std::uint32_t>(a.value(), ValueSite{n, a, "LcId"});
        }
        return t;
    }

    // ---- verbatim store ------------------------------------------------------------------
    void verbatim(XmlElement& e, const pugi::xml_node n, std::string_view after, std::size_t depth) {
        e.name = n.name();
        e.after = after;
        e.pos = pos_of(n);
        for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute()) e.attributes.push_back({a.name(), a.value()});
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
        if (n.value()[0] != '\0') e.text.insert(0, n.value());
    }

    void keep(Extras& extras, const pugi::xml_node n, std::string_view after) {
        verbatim(extras.elements.emplace_back(), n, after, 1);
    }
    static void keep(Extras& extras, const pugi::xml_attribute a) { extras.attributes.push_back({a.name(), a.value()}); }

    // Iterates element children, tracking the name of the previous element for Extras.after.
    // (pugixml is a shared library: every node access is a call. Walking with first_child /
    // next_sibling and taking each name once costs four calls and one strlen per child; the
    // range-for over children() cost seven calls and two.)
    // Element children are the ones with a name: with the parse options used, an element's
    // other children are character data (pcdata, cdata), which has none; comments, processing
    // instructions and declarations are not parsed. So the name tells without a type() call.
    template <class F>
    void for_children(const pugi::xml_node n, F&& f) {
        std::string_view previous;
        for (pugi::xml_node c = n.first_child(); c; c = c.next_sibling()) {
            const std::string_view name = c.name();
            if (name.empty()) continue;
            f(c, name, previous);
            previous = name;
        }
    }

    // Reserves room for the children named `name` about to be read into `items`: large model
    // elements (an Object is about 1 KB) are then neither moved while the vector grows nor
    // left with up to half of its capacity unused.
    template <class T>
    static void reserve_for(std::vector<T>& items, const pugi::xml_node n, const char* name) {
        std::size_t count = 0;
        for (pugi::xml_node c = n.child(name); c; c = c.next_sibling(name)) ++count;
        items.reserve(items.size() + count);
    }

    void missing(std::string_view parent, std::string_view child, SourcePos pos) {
        report(Severity::error, "xml-missing-element", std::string(parent) + " has no " + std::string(child) + " element", pos);
    }

    // ---- model elements ------------------------------------------------------------------
    void read_info(EtherCATInfo& out, const pugi::xml_node n);
    void read_vendor(Vendor& out, const pugi::xml_node n);
    void read_group(Group& out, const pugi::xml_node n);
    void read_device(Device& out, const pugi::xml_node n);
    void read_identity(DeviceIdentity& out, const pugi::xml_node n);
    void read_sm(SyncManager& out, const pugi::xml_node n);
    void read_fmmu(Fmmu& out, const pugi::xml_node n);
    void read_su(SyncUnit& out, const pugi::xml_node n);
    void read_pdo(Pdo& out, const pugi::xml_node n, PdoDirection direction);
    void read_entry(PdoEntry& out, const pugi::xml_node n);
    void read_mailbox(Mailbox& out, const pugi::xml_node n);
    void read_init_cmd(InitCmd& out, const pugi::xml_node n);
    void read_coe(CoeProtocol& out, const pugi::xml_node n);
    void read_dc(Dc& out, const pugi::xml_node n);
    void read_op_mode(DcOpMode& out, const pugi::xml_node n);
    DcTime read_dc_time(const pugi::xml_node n);
    void read_eeprom(Eeprom& out, const pugi::xml_node n);
    void read_profile(Profile& out, const pugi::xml_node n);
    void read_dictionary(Dictionary& out, const pugi::xml_node n);
    void read_data_type(DataType& out, const pugi::xml_node n);
    void read_type_sub_item(DataTypeSubItem& out, const pugi::xml_node n);
    void read_object(Object& out, const pugi::xml_node n);
    void read_object_info(ObjectInfo& out, const pugi::xml_node n, std::size_t depth);
    void read_flags(ObjectFlags& out, const pugi::xml_node n);
    void read_module(Module& out, const pugi::xml_node n);
    void read_slots(Slots& out, const pugi::xml_node n);
    void read_slot(Slot& out, const pugi::xml_node n);
    bool read_image(Images& images, const pugi::xml_node c, std::string_view name);

    const SourceText& source_;
    std::string_view buffer_;
    PositionCursor cursor_;
    Diagnostics& diagnostics_;
    const ReadOptions& options_;
    bool depth_reported_ = false;
};

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
    } else {
        doc.kind = DocumentKind::unknown;
        report(Severity::error, "xml-unknown-root",
               "root element <" + std::string(name) +
                   "> is not an ESI root (EtherCATInfo, EtherCATInfoList, EtherCATModule or EtherCATDict)",
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
                        if (is(devn, "Device")) read_device(info.devices.emplace_back(), dev);
                    });
                } else if (is(dn, "Modules")) {
                    info.has_modules = true;
                    for_children(d, [&](const pugi::xml_node m, std::string_view mn, std::string_view) {
                        if (is(mn, "Module")) read_module(info.modules.emplace_back(), m);
                    });
                } else {
                    keep(info.descriptions_extras, d, dprev);
                }
            });
        } else if (is(name, "Modules")) {  // EtherCATModule root
            info.has_modules = true;
            for_children(c, [&](const pugi::xml_node m, std::string_view mn, std::string_view) {
                if (is(mn, "Module")) read_module(info.modules.emplace_back(), m);
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

void Reader::read_identity(DeviceIdentity& t, const pugi::xml_node n) {
    t.pos = pos_of(n);
    t.text = text_of(n);
    for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute()) {
        const std::string_view an = a.name();
        if (is(an, "ProductCode")) t.product_code = u32(a, n);
        else if (is(an, "RevisionNo")) t.revision_no = u32(a, n);
        else if (is(an, "SerialNo")) t.serial_no = u32(a, n);
        else if (is(an, "TcCfgModeSafeOp")) t.tc_cfg_mode_safe_op = boolean(a, n);
        else keep(t.extras, a);
    }
    for_children(n, [&](const pugi::xml_node c, std::string_view, std::string_view previous) { keep(t.extras, c, previous); });
}

void Reader::read_device(Device& d, const pugi::xml_node n) {
    d.pos = pos_of(n);
    for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute()) {
        const std::string_view an = a.name();
        if (is(an, "Physics")) d.physics = a.value();
        else if (is(an, "Invisible")) d.invisible = boolean(a, n);
        else keep(d.extras, a);
    }
    bool has_type = false;
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (is(name, "Type")) {
            if (has_type) d.type = {};  // a repeated Type replaces the first
            read_identity(d.type, c);
            has_type = true;
        } else if (is(name, "Name")) d.names.push_back(localized(c));
        else if (is(name, "Comment")) d.comments.push_back(localized(c));
        else if (is(name, "URL")) d.urls.push_back(localized(c));
        else if (is(name, "GroupType")) {
            d.group_type = text_of(c);
            d.group_type_pos = pos_of(c);
        } else if (is(name, "Profile")) read_profile(d.profiles.emplace_back(), c);
        else if (is(name, "Fmmu")) read_fmmu(d.fmmus.emplace_back(), c);
        else if (is(name, "Sm")) read_sm(d.sms.emplace_back(), c);
        else if (is(name, "Su")) read_su(d.sus.emplace_back(), c);
        else if (is(name, "RxPdo")) read_pdo(d.rx_pdos.emplace_back(), c, PdoDirection::rx);
        else if (is(name, "TxPdo")) read_pdo(d.tx_pdos.emplace_back(), c, PdoDirection::tx);
        else if (is(name, "Mailbox")) read_mailbox(d.mailbox.emplace(), c);
        else if (is(name, "Dc")) read_dc(d.dc.emplace(), c);
        else if (is(name, "Slots")) read_slots(d.slots.emplace(), c);
        else if (is(name, "Eeprom")) read_eeprom(d.eeprom.emplace(), c);
        else if (!read_image(d.images, c, name)) keep(d.extras, c, previous);
    });
    if (!has_type) missing("Device", "Type", d.pos);
}

void Reader::read_sm(SyncManager& sm, const pugi::xml_node n) {
    sm.pos = pos_of(n);
    sm.type = text_of(n);
    for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute()) {
        const std::string_view an = a.name();
        if (is(an, "StartAddress")) sm.start_address = u32(a, n);
        else if (is(an, "ControlByte")) sm.control_byte = u32(a, n);
        else if (is(an, "DefaultSize")) sm.default_size = u32(a, n);
        else if (is(an, "MinSize")) sm.min_size = u32(a, n);
        else if (is(an, "MaxSize")) sm.max_size = u32(a, n);
        else if (is(an, "Enable")) sm.enable = u32(a, n);
        else if (is(an, "OneByteMode")) sm.one_byte_mode = boolean(a, n);
        else if (is(an, "Virtual")) sm.is_virtual = boolean(a, n);
        else if (is(an, "Watchdog")) sm.watchdog = boolean(a, n);
        else if (is(an, "OpOnly")) sm.op_only = boolean(a, n);
        else if (is(an, "FixedAssignment")) sm.fixed_assignment = boolean(a, n);
        else keep(sm.extras, a);
    }
    for_children(n, [&](const pugi::xml_node c, std::string_view, std::string_view previous) { keep(sm.extras, c, previous); });
}

void Reader::read_fmmu(Fmmu& f, const pugi::xml_node n) {
    f.pos = pos_of(n);
    f.type = text_of(n);
    for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute()) {
        const std::string_view an = a.name();
        if (is(an, "Sm")) f.sm = u32(a, n);
        else if (is(an, "Su")) f.su = u32(a, n);
        else if (is(an, "OpOnly")) f.op_only = boolean(a, n);
        else keep(f.extras, a);
    }
    for_children(n, [&](const pugi::xml_node c, std::string_view, std::string_view previous) { keep(f.extras, c, previous); });
}

void Reader::read_su(SyncUnit& s, const pugi::xml_node n) {
    s.pos = pos_of(n);
    s.text = text_of(n);
    for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute()) {
        const std::string_view an = a.name();
        if (is(an, "SeparateSu")) s.separate_su = boolean(a, n);
        else if (is(an, "SeparateFrame")) s.separate_frame = boolean(a, n);
        else if (is(an, "DependOnInputState")) s.depend_on_input_state = boolean(a, n);
        else if (is(an, "FrameRepeatSupport")) s.frame_repeat_support = boolean(a, n);
        else keep(s.extras, a);
    }
    for_children(n, [&](const pugi::xml_node c, std::string_view, std::string_view previous) { keep(s.extras, c, previous); });
}

void Reader::read_pdo(Pdo& p, const pugi::xml_node n, PdoDirection direction) {
    p.direction = direction;
    p.pos = pos_of(n);
    for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute()) {
        const std::string_view an = a.name();
        if (is(an, "Fixed")) p.fixed = boolean(a, n);
        else if (is(an, "Mandatory")) p.mandatory = boolean(a, n);
        else if (is(an, "Virtual")) p.is_virtual = boolean(a, n);
        else if (is(an, "Sm")) p.sm = u32(a, n);
        else if (is(an, "Su")) p.su = u32(a, n);
        else if (is(an, "PdoOrder")) p.pdo_order = i32(a, n);
        else if (is(an, "OSFac")) p.os_fac = i32(a, n);
        else if (is(an, "OSMin")) p.os_min = i32(a, n);
        else if (is(an, "OSMax")) p.os_max = i32(a, n);
        else if (is(an, "OSIndexInc")) p.os_index_inc = i32(a, n);
        else if (is(an, "OverwrittenByModule")) p.overwritten_by_module = boolean(a, n);
        else if (is(an, "SRA_Parameter")) p.sra_parameter = boolean(a, n);
        else if (is(an, "SafetyPdoType")) p.safety_pdo_type = a.value();
        else if (is(an, "SafetyConnNumber")) p.safety_conn_number = i32(a, n);
        else keep(p.extras, a);
    }
    reserve_for(p.entries, n, "Entry");
    bool has_index = false;
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (is(name, "Index")) {
            has_index = true;
            p.index_pos = pos_of(c);
            const std::optional<std::uint32_t> index = u32(c);
            p.index = index.value_or(0);
            p.index_invalid = !index;
            for (pugi::xml_attribute a = c.first_attribute(); a; a = a.next_attribute()) {
                const std::string_view an = a.name();
                if (is(an, "DependOnSlot")) p.index_depend_on_slot = boolean(a, c);
                else if (is(an, "DependOnSlotGroup")) p.index_depend_on_slot_group = boolean(a, c);
            }
        } else if (is(name, "Name")) p.names.push_back(localized(c));
        else if (is(name, "Exclude")) {
            PdoExclude e;
            e.pos = pos_of(c);
            e.index = u32(c).value_or(0);
            for (pugi::xml_attribute a = c.first_attribute(); a; a = a.next_attribute()) {
                const std::string_view an = a.name();
                if (is(an, "DependOnSlot")) e.depend_on_slot = boolean(a, c);
                else if (is(an, "DependOnSlotGroup")) e.depend_on_slot_group = boolean(a, c);
            }
            p.excludes.push_back(e);
        } else if (is(name, "Entry")) read_entry(p.entries.emplace_back(), c);
        else if (is(name, "ExcludedSm")) {
            if (auto v = u32(c)) p.excluded_sms.push_back(*v);
        } else keep(p.extras, c, previous);
    });
    if (!has_index) missing(n.name(), "Index", p.pos);
}

void Reader::read_entry(PdoEntry& e, const pugi::xml_node n) {
    e.pos = pos_of(n);
    for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute()) {
        const std::string_view an = a.name();
        if (is(an, "Fixed")) e.fixed = boolean(a, n);
        else keep(e.extras, a);
    }
    bool has_index = false;
    bool has_bit_len = false;
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (is(name, "Index")) {
            has_index = true;
            const std::optional<std::uint32_t> index = u32(c);
            e.index = index.value_or(0);
            e.index_invalid = !index;
            e.index_pos = pos_of(c);
            for (pugi::xml_attribute a = c.first_attribute(); a; a = a.next_attribute()) {
                const std::string_view an = a.name();
                if (is(an, "DependOnSlot")) e.index_depend_on_slot = boolean(a, c);
                else if (is(an, "DependOnSlotGroup")) e.index_depend_on_slot_group = boolean(a, c);
            }
        } else if (is(name, "SubIndex")) e.subindex = u32(c);
        else if (is(name, "BitLen")) {
            has_bit_len = true;
            e.bit_len = u32(c).value_or(0);
            e.bit_len_pos = pos_of(c);
        } else if (is(name, "Name")) e.names.push_back(localized(c));
        else if (is(name, "Comment")) e.comment = text_of(c);
        else if (is(name, "DataType")) {
            e.data_type = text_of(c);
            e.data_type_pos = pos_of(c);
            for (pugi::xml_attribute a = c.first_attribute(); a; a = a.next_attribute()) {
                const std::string_view an = a.name();
                if (is(an, "DScale")) e.data_type_dscale = a.value();
                else if (is(an, "SwapData")) e.data_type_swap_data = std::string(trim(a.value()));
            }
        } else keep(e.extras, c, previous);
    });
    if (!has_index) missing("Entry", "Index", e.pos);
    if (!has_bit_len) missing("Entry", "BitLen", e.pos);
}

void Reader::read_init_cmd(InitCmd& cmd, const pugi::xml_node n) {
    cmd.pos = pos_of(n);
    for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute()) {
        const std::string_view an = a.name();
        if (is(an, "Fixed")) cmd.fixed = boolean(a, n);
        else if (is(an, "CompleteAccess")) cmd.complete_access = boolean(a, n);
        else if (is(an, "OverwrittenByModule")) cmd.overwritten_by_module = boolean(a, n);
        else if (is(an, "Chn")) cmd.channel = i32(a, n);
        else keep(cmd.extras, a);
    }
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (is(name, "Transition")) cmd.transitions.push_back(Transition{text_of(c), pos_of(c)});
        else if (is(name, "Index")) {
            cmd.index = u32(c);
            for (pugi::xml_attribute a = c.first_attribute(); a; a = a.next_attribute()) {
                const std::string_view an = a.name();
                if (is(an, "DependOnSlot")) cmd.index_depend_on_slot = boolean(a, c);
                else if (is(an, "DependOnSlotGroup")) cmd.index_depend_on_slot_group = boolean(a, c);
            }
        } else if (is(name, "SubIndex")) cmd.subindex = u32(c);
        else if (is(name, "IDN")) cmd.idn = i64(c);
        else if (is(name, "Type")) cmd.type = i64(c);
        else if (is(name, "Data")) {
            cmd.data = hex(c);
            cmd.has_data = true;
            for (pugi::xml_attribute a = c.first_attribute(); a; a = a.next_attribute())
                if (is(a.name(), "AdaptAutomatically")) cmd.data_adapt_automatically = boolean(a, c);
        } else if (is(name, "Comment")) cmd.comment = text_of(c);
        else keep(cmd.extras, c, previous);
    });
}

void Reader::read_coe(CoeProtocol& coe, const pugi::xml_node n) {
    coe.pos = pos_of(n);
    for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute()) {
        const std::string_view an = a.name();
        if (is(an, "SdoInfo")) coe.sdo_info = boolean(a, n);
        else if (is(an, "PdoAssign")) coe.pdo_assign = boolean(a, n);
        else if (is(an, "PdoConfig")) coe.pdo_config = boolean(a, n);
        else if (is(an, "PdoUpload")) coe.pdo_upload = boolean(a, n);
        else if (is(an, "CompleteAccess")) coe.complete_access = boolean(a, n);
        else if (is(an, "SegmentedSdo")) coe.segmented_sdo = boolean(a, n);
        else if (is(an, "DiagHistory")) coe.diag_history = boolean(a, n);
        else if (is(an, "SdoUploadWithMaxLength")) coe.sdo_upload_with_max_length = boolean(a, n);
        else if (is(an, "TimeDistribution")) coe.time_distribution = boolean(a, n);
        else if (is(an, "ModuleOD")) coe.module_od = boolean(a, n);
        else if (is(an, "EdsFile")) coe.eds_file = a.value();
        else if (is(an, "DS402Channels")) coe.ds402_channels = i32(a, n);
        else keep(coe.extras, a);
    }
    reserve_for(coe.init_cmds, n, "InitCmd");
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (is(name, "InitCmd")) read_init_cmd(coe.init_cmds.emplace_back(), c);
        else keep(coe.extras, c, previous);
    });
}

void Reader::read_mailbox(Mailbox& m, const pugi::xml_node n) {
    m.pos = pos_of(n);
    for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute()) {
        const std::string_view an = a.name();
        if (is(an, "DataLinkLayer")) m.data_link_layer = boolean(a, n);
        else if (is(an, "RealTimeMode")) m.real_time_mode = boolean(a, n);
        else keep(m.extras, a);
    }
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (is(name, "CoE")) {
            read_coe(m.coe.emplace(), c);
        } else if (is(name, "EoE")) {
            EoeProtocol eoe;
            eoe.pos = pos_of(c);
            for (pugi::xml_attribute a = c.first_attribute(); a; a = a.next_attribute()) {
                const std::string_view an = a.name();
                if (is(an, "IP")) eoe.ip = boolean(a, c);
                else if (is(an, "MAC")) eoe.mac = boolean(a, c);
                else if (is(an, "TimeStamp")) eoe.time_stamp = boolean(a, c);
                else keep(eoe.extras, a);
            }
            for_children(c, [&](const pugi::xml_node cc, std::string_view cn, std::string_view prev) {
                if (is(cn, "InitCmd")) read_init_cmd(eoe.init_cmds.emplace_back(), cc);
                else keep(eoe.extras, cc, prev);
            });
            m.eoe = std::move(eoe);
        } else if (is(name, "SoE")) {
            SoeProtocol soe;
            soe.pos = pos_of(c);
            for (pugi::xml_attribute a = c.first_attribute(); a; a = a.next_attribute()) {
                const std::string_view an = a.name();
                if (is(an, "ChannelCount")) soe.channel_count = i32(a, c);
                else if (is(an, "DriveFollowsBit3Support")) soe.drive_follows_bit3_support = boolean(a, c);
                else keep(soe.extras, a);
            }
            for_children(c, [&](const pugi::xml_node cc, std::string_view cn, std::string_view prev) {
                if (is(cn, "InitCmd")) read_init_cmd(soe.init_cmds.emplace_back(), cc);
                else keep(soe.extras, cc, prev);
            });
            m.soe = std::move(soe);
        } else if (is(name, "AoE")) {
            AoeProtocol aoe;
            aoe.pos = pos_of(c);
            for (pugi::xml_attribute a = c.first_attribute(); a; a = a.next_attribute()) {
                const std::string_view an = a.name();
                if (is(an, "AdsRouter")) aoe.ads_router = boolean(a, c);
                else if (is(an, "GenerateOwnNetId")) aoe.generate_own_net_id = boolean(a, c);
                else if (is(an, "InitializeOwnNetId")) aoe.initialize_own_net_id = boolean(a, c);
                else keep(aoe.extras, a);
            }
            for_children(c, [&](const pugi::xml_node cc, std::string_view cn, std::string_view prev) {
                if (is(cn, "InitCmd")) read_init_cmd(aoe.init_cmds.emplace_back(), cc);
                else keep(aoe.extras, cc, prev);
            });
            m.aoe = std::move(aoe);
        } else if (is(name, "FoE") || is(name, "VoE")) {
            PlainProtocol p;
            p.pos = pos_of(c);
            for (pugi::xml_attribute a = c.first_attribute(); a; a = a.next_attribute()) keep(p.extras, a);
            for_children(c, [&](const pugi::xml_node cc, std::string_view, std::string_view prev) { keep(p.extras, cc, prev); });
            (is(name, "FoE") ? m.foe : m.voe) = std::move(p);
        } else {
            keep(m.extras, c, previous);
        }
    });
}

DcTime Reader::read_dc_time(const pugi::xml_node n) {
    DcTime t;
    t.pos = pos_of(n);
    t.value = i64(n).value_or(0);
    for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute()) {
        const std::string_view an = a.name();
        if (is(an, "Factor")) t.factor = i32(a, n);
        else if (is(an, "Input")) t.input = boolean(a, n);
        else if (is(an, "OutputDelayTime")) t.output_delay_time = i32(a, n);
        else if (is(an, "InputDelayTime")) t.input_delay_time = i32(a, n);
    }
    return t;
}

void Reader::read_op_mode(DcOpMode& m, const pugi::xml_node n) {
    m.pos = pos_of(n);
    for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute()) keep(m.extras, a);
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (is(name, "Name")) m.name = text_of(c);
        else if (is(name, "Desc")) m.desc = text_of(c);
        else if (is(name, "AssignActivate")) {
            m.assign_activate_pos = pos_of(c);
            if (auto v = u32(c)) {
                m.assign_activate = *v;
                m.has_assign_activate = true;
            }
        } else if (is(name, "CycleTimeSync0")) m.cycle_time_sync0 = read_dc_time(c);
        else if (is(name, "ShiftTimeSync0")) m.shift_time_sync0 = read_dc_time(c);
        else if (is(name, "CycleTimeSync1")) m.cycle_time_sync1 = read_dc_time(c);
        else if (is(name, "ShiftTimeSync1")) m.shift_time_sync1 = read_dc_time(c);
        else keep(m.extras, c, previous);
    });
}

void Reader::read_dc(Dc& dc, const pugi::xml_node n) {
    dc.pos = pos_of(n);
    for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute()) {
        const std::string_view an = a.name();
        if (is(an, "UnknownFRMW")) dc.unknown_frmw = boolean(a, n);
        else if (is(an, "Unknown64Bit")) dc.unknown_64bit = boolean(a, n);
        else if (is(an, "ExternalRefClock")) dc.external_ref_clock = boolean(a, n);
        else if (is(an, "PotentialReferenceClock")) dc.potential_reference_clock = boolean(a, n);
        else if (is(an, "TimeLoopControlOnly")) dc.time_loop_control_only = boolean(a, n);
        else keep(dc.extras, a);
    }
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (is(name, "OpMode")) read_op_mode(dc.op_modes.emplace_back(), c);
        else keep(dc.extras, c, previous);
    });
}

void Reader::read_eeprom(Eeprom& e, const pugi::xml_node n) {
    e.pos = pos_of(n);
    for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute()) {
        if (is(a.name(), "AssignToPdi")) e.assign_to_pdi = boolean(a, n);
        else keep(e.extras, a);
    }
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (is(name, "Data")) e.data = hex(c);
        else if (is(name, "ByteSize")) {
            e.byte_size = u32(c);
            e.byte_size_pos = pos_of(c);
        } else if (is(name, "ConfigData")) e.config_data = hex(c);
        else if (is(name, "BootStrap")) e.boot_strap = hex(c);
        else if (is(name, "Category")) {
            EepromCategory cat;
            cat.pos = pos_of(c);
            for (pugi::xml_attribute a = c.first_attribute(); a; a = a.next_attribute()) {
                if (is(a.name(), "PreserveOnlineData")) cat.preserve_online_data = boolean(a, c);
                else keep(cat.extras, a);
            }
            for_children(c, [&](const pugi::xml_node cc, std::string_view cn, std::string_view prev) {
                if (is(cn, "CatNo")) {
                    cat.cat_no = u32(cc).value_or(0);
                    cat.cat_no_pos = pos_of(cc);
                } else if (is(cn, "Data")) cat.data = hex(cc);
                else if (is(cn, "DataString")) cat.data_string = pcdata(cc);
                else if (is(cn, "DataUINT")) cat.data_uint = u64(cc);
                else if (is(cn, "DataUDINT")) cat.data_udint = u64(cc);
                else keep(cat.extras, cc, prev);
            });
            e.categories.push_back(std::move(cat));
        } else keep(e.extras, c, previous);
    });
}

void Reader::read_profile(Profile& p, const pugi::xml_node n) {
    p.pos = pos_of(n);
    for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute()) {
        if (is(a.name(), "Channel")) p.channel = i32(a, n);
        else keep(p.extras, a);
    }
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (is(name, "ProfileNo")) p.profile_no = i32(c);
        else if (is(name, "AddInfo")) p.add_info = i32(c);
        else if (is(name, "DictionaryFile")) p.dictionary_file = text_of(c);
        else if (is(name, "Dictionary")) read_dictionary(p.dictionary.emplace(), c);
        else keep(p.extras, c, previous);
    });
}

void Reader::read_dictionary(Dictionary& d, const pugi::xml_node n) {
    d.pos = pos_of(n);
    for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute()) keep(d.extras, a);
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (is(name, "DataTypes")) {
            reserve_for(d.data_types, c, "DataType");
            for_children(c, [&](const pugi::xml_node t, std::string_view tn, std::string_view) {
                if (is(tn, "DataType")) read_data_type(d.data_types.emplace_back(), t);
            });
        } else if (is(name, "Objects")) {
            reserve_for(d.objects, c, "Object");
            for_children(c, [&](const pugi::xml_node o, std::string_view on, std::string_view) {
                if (is(on, "Object")) read_object(d.objects.emplace_back(), o);
            });
        } else {
            keep(d.extras, c, previous);
        }
    });
}

void Reader::read_data_type(DataType& t, const pugi::xml_node n) {
    t.pos = pos_of(n);
    for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute()) keep(t.extras, a);
    reserve_for(t.sub_items, n, "SubItem");
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (is(name, "Index")) t.index = u32(c);
        else if (is(name, "Name")) {
            t.name = text_of(c);
            t.name_pos = pos_of(c);
        } else if (is(name, "BaseType")) t.base_type = text_of(c);
        else if (is(name, "Comment")) t.comments.push_back(localized(c));
        else if (is(name, "BitSize")) t.bit_size = u64(c).value_or(0);
        else if (is(name, "ArrayInfo")) {
            ArrayInfo ai;
            ai.pos = pos_of(c);
            for_children(c, [&](const pugi::xml_node cc, std::string_view cn, std::string_view) {
                if (is(cn, "LBound")) ai.lower_bound = i64(cc).value_or(0);
                else if (is(cn, "Elements")) ai.elements = i64(cc).value_or(0);
            });
            t.array_info.push_back(ai);
        } else if (is(name, "SubItem")) read_type_sub_item(t.sub_items.emplace_back(), c);
        else if (is(name, "EnumInfo")) {
            EnumValue ev;
            ev.pos = pos_of(c);
            for_children(c, [&](const pugi::xml_node cc, std::string_view cn, std::string_view) {
                if (is(cn, "Text")) ev.texts.push_back(localized(cc));
                else if (is(cn, "Enum")) ev.value = number(cc).value_or(Number{});
                else if (is(cn, "Comment")) ev.comments.push_back(localized(cc));
            });
            t.enums.push_back(std::move(ev));
        } else keep(t.extras, c, previous);
    });
}

void Reader::read_type_sub_item(DataTypeSubItem& s, const pugi::xml_node n) {
    s.pos = pos_of(n);
    for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute()) keep(s.extras, a);
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (is(name, "SubIdx")) s.subindex = u32(c);
        else if (is(name, "Name")) s.name = text_of(c);
        else if (is(name, "DisplayName")) s.display_names.push_back(localized(c));
        else if (is(name, "Type")) s.type = text_of(c);
        else if (is(name, "Comment")) s.comments.push_back(localized(c));
        else if (is(name, "BitSize")) s.bit_size = u64(c).value_or(0);
        else if (is(name, "BitOffs")) s.bit_offset = u64(c).value_or(0);
        else if (is(name, "DefaultString")) s.default_string = pcdata(c);
        else if (is(name, "DefaultData")) s.default_data = hex(c);
        else if (is(name, "MinValue")) s.min_value = number(c);
        else if (is(name, "MaxValue")) s.max_value = number(c);
        else if (is(name, "DefaultValue")) s.default_value = number(c);
        else if (is(name, "Flags")) read_flags(s.flags.emplace(), c);
        else keep(s.extras, c, previous);
    });
}

void Reader::read_flags(ObjectFlags& f, const pugi::xml_node n) {
    f.pos = pos_of(n);
    for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute()) keep(f.extras, a);
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (is(name, "Access")) {
            f.access = text_of(c);
            for (pugi::xml_attribute a = c.first_attribute(); a; a = a.next_attribute()) {
                const std::string_view an = a.name();
                if (is(an, "ReadRestrictions")) f.access_read_restrictions = a.value();
                else if (is(an, "WriteRestrictions")) f.access_write_restrictions = a.value();
            }
        } else if (is(name, "Category")) f.category = text_of(c);
        else if (is(name, "PdoMapping")) f.pdo_mapping = text_of(c);
        else if (is(name, "SafetyMapping")) f.safety_mapping = text_of(c);
        else if (is(name, "Attribute")) f.attribute = u32(c);
        else if (is(name, "Transition")) f.transition = text_of(c);
        else if (is(name, "SdoAccess")) f.sdo_access = text_of(c);
        else if (is(name, "Backup")) f.backup = i32(c);
        else if (is(name, "Setting")) f.setting = i32(c);
        else keep(f.extras, c, previous);
    });
}

void Reader::read_object_info(ObjectInfo& info, const pugi::xml_node n, std::size_t depth) {
    info.pos = pos_of(n);
    for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute()) keep(info.extras, a);
    // Only an object's own Info lists SubItems in practice; the Infos of sub-items are leaves, and
    // counting their children cost a lookup each.
    if (depth == 0) reserve_for(info.sub_items, n, "SubItem");
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (is(name, "DefaultString")) info.default_string = pcdata(c);
        else if (is(name, "MinData")) info.min_data = hex(c);
        else if (is(name, "MaxData")) info.max_data = hex(c);
        else if (is(name, "DefaultData")) info.default_data = hex(c);
        else if (is(name, "MinValue")) info.min_value = number(c);
        else if (is(name, "MaxValue")) info.max_value = number(c);
        else if (is(name, "DefaultValue")) info.default_value = number(c);
        else if (is(name, "DisplayName")) info.display_name = text_of(c);
        else if (is(name, "Unit")) info.unit = u32(c);
        else if (is(name, "SubItem") && depth < 8) {
            ObjectSubItemInfo& sub = info.sub_items.emplace_back();
            sub.pos = pos_of(c);
            bool has_info = false;
            for_children(c, [&](const pugi::xml_node cc, std::string_view cn, std::string_view prev) {
                if (is(cn, "Name")) sub.name = text_of(cc);
                else if (is(cn, "Info")) {
                    if (has_info) sub.info = {};  // a repeated Info replaces the first
                    read_object_info(sub.info, cc, depth + 1);
                    has_info = true;
                } else keep(sub.extras, cc, prev);
            });
        } else keep(info.extras, c, previous);
    });
}

void Reader::read_object(Object& o, const pugi::xml_node n) {
    o.pos = pos_of(n);
    for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute()) keep(o.extras, a);
    bool has_index = false;
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (is(name, "Index")) {
            has_index = true;
            o.index = u32(c).value_or(0);
            o.index_pos = pos_of(c);
            for (pugi::xml_attribute a = c.first_attribute(); a; a = a.next_attribute()) {
                const std::string_view an = a.name();
                if (is(an, "DependOnSlot")) o.index_depend_on_slot = boolean(a, c);
                else if (is(an, "DependOnSlotGroup")) o.index_depend_on_slot_group = boolean(a, c);
                else if (is(an, "OverwrittenByModule")) o.index_overwritten_by_module = boolean(a, c);
            }
        } else if (is(name, "Name")) o.names.push_back(localized(c));
        else if (is(name, "Comment")) o.comments.push_back(localized(c));
        else if (is(name, "Type")) {
            o.type = text_of(c);
            o.type_pos = pos_of(c);
        } else if (is(name, "BitSize")) {
            o.bit_size = u64(c).value_or(0);
            o.bit_size_pos = pos_of(c);
        } else if (is(name, "Info")) read_object_info(o.info.emplace(), c, 0);
        else if (is(name, "Flags")) read_flags(o.flags.emplace(), c);
        else keep(o.extras, c, previous);
    });
    if (!has_index) missing("Object", "Index", o.pos);
}

void Reader::read_module(Module& m, const pugi::xml_node n) {
    m.pos = pos_of(n);
    for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute()) keep(m.extras, a);
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (is(name, "Type")) {
            m.type = text_of(c);
            m.type_pos = pos_of(c);
            for (pugi::xml_attribute a = c.first_attribute(); a; a = a.next_attribute()) {
                const std::string_view an = a.name();
                if (is(an, "ModuleIdent")) m.module_ident = u32(a, c).value_or(0);
                else if (is(an, "ModuleClass")) m.module_class = a.value();
                else if (is(an, "ModulePdoGroup")) m.module_pdo_group = i32(a, c);
                else keep(m.type_extras, a);
            }
        } else if (is(name, "Name")) m.names.push_back(localized(c));
        else if (is(name, "RxPdo")) read_pdo(m.rx_pdos.emplace_back(), c, PdoDirection::rx);
        else if (is(name, "TxPdo")) read_pdo(m.tx_pdos.emplace_back(), c, PdoDirection::tx);
        else if (is(name, "Mailbox")) read_mailbox(m.mailbox.emplace(), c);
        else if (is(name, "Profile")) read_profile(m.profile.emplace(), c);
        else if (is(name, "DcOpModeName")) m.dc_op_mode_name = text_of(c);
        else if (!read_image(m.images, c, name)) keep(m.extras, c, previous);
    });
}

void Reader::read_slot(Slot& s, const pugi::xml_node n) {
    s.pos = pos_of(n);
    for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute()) {
        const std::string_view an = a.name();
        if (is(an, "SlotGroup")) s.slot_group = u32(a, n);
        else if (is(an, "MinInstances")) s.min_instances = u32(a, n).value_or(0);
        else if (is(an, "MaxInstances")) s.max_instances = u32(a, n).value_or(0);
        else if (is(an, "SlotPdoIncrement")) s.slot_pdo_increment = u32(a, n);
        else if (is(an, "SlotGroupPdoIncrement")) s.slot_group_pdo_increment = u32(a, n);
        else if (is(an, "SlotIndexIncrement")) s.slot_index_increment = u32(a, n);
        else if (is(an, "SlotGroupIndexIncrement")) s.slot_group_index_increment = u32(a, n);
        else if (is(an, "Default")) s.default_ident = u32(a, n);
        else if (is(an, "Fallback")) s.fallback = u32(a, n);
        else keep(s.extras, a);
    }
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (is(name, "Name")) s.names.push_back(localized(c));
        else if (is(name, "ModuleIdent")) {
            SlotModuleIdent id;
            id.pos = pos_of(c);
            id.value = u32(c).value_or(0);
            for (pugi::xml_attribute a = c.first_attribute(); a; a = a.next_attribute())
                if (is(a.name(), "Default")) id.default_ident = u32(a, c);
            s.module_idents.push_back(id);
        } else if (is(name, "ModuleClass")) {
            SlotModuleClass mc;
            mc.pos = pos_of(c);
            for (pugi::xml_attribute a = c.first_attribute(); a; a = a.next_attribute()) keep(mc.extras, a);
            for_children(c, [&](const pugi::xml_node cc, std::string_view cn, std::string_view prev) {
                if (is(cn, "Class")) mc.class_name = text_of(cc);
                else if (is(cn, "VendorId")) mc.vendor_id = u32(cc);
                else if (is(cn, "Name")) mc.names.push_back(localized(cc));
                else keep(mc.extras, cc, prev);
            });
            s.module_classes.push_back(std::move(mc));
        } else if (!read_image(s.images, c, name)) keep(s.extras, c, previous);
    });
}

void Reader::read_slots(Slots& s, const pugi::xml_node n) {
    s.pos = pos_of(n);
    for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute()) {
        const std::string_view an = a.name();
        if (is(an, "MaxSlotCount")) s.max_slot_count = u32(a, n);
        else if (is(an, "MaxSlotGroupCount")) s.max_slot_group_count = u32(a, n);
        else if (is(an, "SlotPdoIncrement")) s.slot_pdo_increment = u32(a, n);
        else if (is(an, "SlotGroupPdoIncrement")) s.slot_group_pdo_increment = u32(a, n);
        else if (is(an, "SlotIndexIncrement")) s.slot_index_increment = u32(a, n);
        else if (is(an, "SlotGroupIndexIncrement")) s.slot_group_index_increment = u32(a, n);
        else keep(s.extras, a);
    }
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (is(name, "Slot")) read_slot(s.slots.emplace_back(), c);
        else keep(s.extras, c, previous);
    });
}

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
    // as written, for quoting lines and finding suppressions.
    std::string buffer = source->text();
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
    Reader reader(*source, buffer, result.diagnostics, options);
    EsiDocument doc = reader.read_document(root);
    doc.path = path;
    doc.encoding = decoded.encoding;
    if (options.keep_source) doc.source = source;
    result.document = std::move(doc);
    return result;
}

}  // namespace

std::optional<std::string> read_file_bytes(const std::filesystem::path& path, std::string& error, std::uint64_t max_bytes) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) {
        error = "is a directory";
        return std::nullopt;
    }
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) {
        error = std::error_code(errno, std::generic_category()).message();
        return std::nullopt;
    }
    auto too_large = [&] {
        error = "larger than " + std::to_string(max_bytes >> 20) + " MiB, the input size limit";
        std::fclose(file);
        return std::nullopt;
    };
    // A regular file is read into a buffer of its size in one call: growing the string chunk by
    // chunk copied a multi-MB file several times over and left up to twice its size allocated.
    // Whatever the size did not cover (a file that grew, a pipe, a device) is appended in chunks,
    // bounded by max_bytes like the announced size.
    std::string bytes;
    std::error_code size_error;
    const std::uintmax_t size = std::filesystem::file_size(path, size_error);
    if (!size_error && size > max_bytes) return too_large();
    if (!size_error) {
        bytes.resize(static_cast<std::size_t>(size));
        bytes.resize(std::fread(bytes.data(), 1, bytes.size(), file));
    }
    char buffer[1 << 16];
    for (bool more = bytes.size() == size || size_error; more;) {
        const std::size_t n = std::fread(buffer, 1, sizeof buffer, file);
        bytes.append(buffer, n);
        if (bytes.size() > max_bytes) return too_large();
        more = n == sizeof buffer;
    }
    const bool failed = std::ferror(file) != 0;
    std::fclose(file);
    if (failed) {
        error = "read error";
        return std::nullopt;
    }
    return bytes;
}

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
