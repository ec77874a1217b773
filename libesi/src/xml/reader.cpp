// ESI XML -> model. One pass over a pugixml DOM built from the UTF-8 text; every typed field is
// read by name, everything else is kept verbatim in Extras with its position.

#include "esi/xml/reader.hpp"

#include <cstdio>
#include <algorithm>
#include <fstream>
#include <limits>
#include <pugixml.hpp>
#include <sstream>
#include <system_error>

#include "esi/encoding.hpp"
#include "esi/number.hpp"

namespace esi {

namespace {

class Reader {
public:
    Reader(const SourceText& source, Diagnostics& diagnostics, const ReadOptions& options)
        : source_(source), cursor_(source), diagnostics_(diagnostics), options_(options) {}

    EsiDocument read_document(const pugi::xml_node root);

private:
    // ---- positions and diagnostics ------------------------------------------------------
    SourcePos pos_of(const pugi::xml_node node) {
        const std::ptrdiff_t offset = node.offset_debug();
        if (offset < 0) return {};
        // offset_debug points at the element name; report the '<' before it.
        std::size_t at = static_cast<std::size_t>(offset);
        if (node.type() == pugi::node_element && at > 0) --at;
        return cursor_.position_of(at);
    }

    void report(Severity severity, std::string rule, std::string message, SourcePos pos) {
        diagnostics_.emplace(severity, std::move(rule), std::move(message), source_.path(), pos);
    }

    // ---- scalar values -------------------------------------------------------------------
    static std::string text_of(const pugi::xml_node node) { return std::string(trim(node.text().get())); }

    std::optional<Number> number(std::string_view text, std::string_view what, SourcePos pos) {
        const ParsedNumber parsed = parse_number(text);
        if (!parsed.ok()) {
            report(Severity::error, "xml-number-format",
                   std::string(what) + ": '" + excerpt(trim(text)) + "' is not a number (" + std::string(to_string(parsed.error)) +
                       "); ESI numbers are decimal or #x hex",
                   pos);
            return std::nullopt;
        }
        if (parsed.syntax == NumberSyntax::c_hex) {
            report(Severity::warning, "xml-hex-prefix",
                   std::string(what) + ": '" + excerpt(trim(text)) + "' uses the C prefix 0x; ESI hex numbers are written #x",
                   pos);
        }
        return parsed.value;
    }

    template <class T>
    std::optional<T> integer(std::string_view text, std::string_view what, SourcePos pos) {
        const std::optional<Number> n = number(text, what, pos);
        if (!n) return std::nullopt;
        if constexpr (std::is_signed_v<T>) {
            const auto v = n->as_int64();
            if (!v || *v < std::numeric_limits<T>::min() || *v > std::numeric_limits<T>::max()) {
                report(Severity::error, "xml-number-range",
                       std::string(what) + ": " + format_decimal(*n) + " is out of range", pos);
                return std::nullopt;
            }
            return static_cast<T>(*v);
        } else {
            const auto v = n->as_uint64();
            if (!v || *v > std::numeric_limits<T>::max()) {
                report(Severity::error, "xml-number-range",
                       std::string(what) + ": " + format_decimal(*n) + " is out of range (0.." +
                           std::to_string(std::numeric_limits<T>::max()) + ")",
                       pos);
                return std::nullopt;
            }
            return static_cast<T>(*v);
        }
    }

    std::optional<std::uint32_t> u32(const pugi::xml_attribute a, const pugi::xml_node owner) {
        return integer<std::uint32_t>(a.value(), std::string(owner.name()) + "@" + a.name(), pos_of(owner));
    }
    std::optional<std::int32_t> i32(const pugi::xml_attribute a, const pugi::xml_node owner) {
        return integer<std::int32_t>(a.value(), std::string(owner.name()) + "@" + a.name(), pos_of(owner));
    }
    std::optional<std::uint32_t> u32(const pugi::xml_node n) { return integer<std::uint32_t>(n.text().get(), n.name(), pos_of(n)); }
    std::optional<std::int32_t> i32(const pugi::xml_node n) { return integer<std::int32_t>(n.text().get(), n.name(), pos_of(n)); }
    std::optional<std::int64_t> i64(const pugi::xml_node n) { return integer<std::int64_t>(n.text().get(), n.name(), pos_of(n)); }
    std::optional<std::uint64_t> u64(const pugi::xml_node n) { return integer<std::uint64_t>(n.text().get(), n.name(), pos_of(n)); }

    std::optional<bool> boolean(std::string_view text, std::string_view what, SourcePos pos) {
        const auto b = parse_boolean(text);
        if (!b)
            report(Severity::error, "xml-boolean-format",
                   std::string(what) + ": '" + excerpt(trim(text)) + "' is not a boolean (true, false, 1 or 0)", pos);
        return b;
    }
    std::optional<bool> boolean(const pugi::xml_attribute a, const pugi::xml_node owner) {
        return boolean(a.value(), std::string(owner.name()) + "@" + a.name(), pos_of(owner));
    }
    std::optional<bool> boolean(const pugi::xml_node n) { return boolean(n.text().get(), n.name(), pos_of(n)); }

    HexData hex(const pugi::xml_node n) {
        HexData out;
        out.pos = pos_of(n);
        const std::string_view raw = trim(n.text().get());
        if (raw.find_first_of(" \t\n\r") == std::string_view::npos) {
            out.text.assign(raw);
            return out;
        }
        out.text.reserve(raw.size());
        for (char c : raw)
            if (c != ' ' && c != '\t' && c != '\n' && c != '\r') out.text.push_back(c);
        return out;
    }

    LocalizedText localized(const pugi::xml_node n) {
        LocalizedText t;
        t.text = text_of(n);
        t.pos = pos_of(n);
        for (const auto a : n.attributes()) {
            if (std::string_view(a.name()) == "LcId") t.lcid = integer<std::uint32_t>(a.value(), "LcId", t.pos);
        }
        return t;
    }

    // ---- verbatim store ------------------------------------------------------------------
    XmlElement verbatim(const pugi::xml_node n, std::string after, std::size_t depth) {
        XmlElement e;
        e.name = n.name();
        e.after = std::move(after);
        e.pos = pos_of(n);
        for (const auto a : n.attributes()) e.attributes.push_back({a.name(), a.value()});
        if (depth >= options_.max_verbatim_depth) {
            if (!depth_reported_) {
                report(Severity::error, "xml-nesting-depth",
                       "elements nested deeper than " + std::to_string(options_.max_verbatim_depth) + " levels are not kept",
                       e.pos);
                depth_reported_ = true;
            }
            return e;
        }
        std::string previous;
        for (const auto c : n.children()) {
            if (c.type() == pugi::node_pcdata || c.type() == pugi::node_cdata) {
                e.text += c.value();
            } else if (c.type() == pugi::node_element) {
                e.children.push_back(verbatim(c, previous, depth + 1));
                previous = c.name();
            }
        }
        // parse_embed_pcdata stores the text that comes before any child element in the
        // element's own value, not as a child: it is the start of the text (mixed content).
        if (n.value()[0] != '\0') e.text.insert(0, n.value());
        return e;
    }

    void keep(Extras& extras, const pugi::xml_node n, std::string_view after) {
        extras.elements.push_back(verbatim(n, std::string(after), 1));
    }
    static void keep(Extras& extras, const pugi::xml_attribute a) { extras.attributes.push_back({a.name(), a.value()}); }

    // Iterates element children, tracking the name of the previous element for Extras.after.
    template <class F>
    void for_children(const pugi::xml_node n, F&& f) {
        std::string_view previous;
        for (const auto c : n.children()) {
            if (c.type() != pugi::node_element) continue;
            f(c, std::string_view(c.name()), previous);
            previous = c.name();
        }
    }

    void missing(std::string_view parent, std::string_view child, SourcePos pos) {
        report(Severity::error, "xml-missing-element", std::string(parent) + " has no " + std::string(child) + " element", pos);
    }

    // ---- model elements ------------------------------------------------------------------
    EtherCATInfo read_info(const pugi::xml_node n);
    Vendor read_vendor(const pugi::xml_node n);
    Group read_group(const pugi::xml_node n);
    Device read_device(const pugi::xml_node n);
    DeviceIdentity read_identity(const pugi::xml_node n);
    SyncManager read_sm(const pugi::xml_node n);
    Fmmu read_fmmu(const pugi::xml_node n);
    SyncUnit read_su(const pugi::xml_node n);
    Pdo read_pdo(const pugi::xml_node n, PdoDirection direction);
    PdoEntry read_entry(const pugi::xml_node n);
    Mailbox read_mailbox(const pugi::xml_node n);
    InitCmd read_init_cmd(const pugi::xml_node n);
    CoeProtocol read_coe(const pugi::xml_node n);
    Dc read_dc(const pugi::xml_node n);
    DcOpMode read_op_mode(const pugi::xml_node n);
    DcTime read_dc_time(const pugi::xml_node n);
    Eeprom read_eeprom(const pugi::xml_node n);
    Profile read_profile(const pugi::xml_node n);
    Dictionary read_dictionary(const pugi::xml_node n);
    DataType read_data_type(const pugi::xml_node n);
    DataTypeSubItem read_type_sub_item(const pugi::xml_node n);
    Object read_object(const pugi::xml_node n);
    ObjectInfo read_object_info(const pugi::xml_node n, std::size_t depth);
    ObjectFlags read_flags(const pugi::xml_node n);
    Module read_module(const pugi::xml_node n);
    Slots read_slots(const pugi::xml_node n);
    Slot read_slot(const pugi::xml_node n);
    bool read_image(Images& images, const pugi::xml_node c, std::string_view name);

    const SourceText& source_;
    PositionCursor cursor_;
    Diagnostics& diagnostics_;
    const ReadOptions& options_;
    bool depth_reported_ = false;
};

bool Reader::read_image(Images& images, const pugi::xml_node c, std::string_view name) {
    if (name == "ImageData16x14") images.image_data16x14 = hex(c);
    else if (name == "Image16x14") {
        images.image16x14 = text_of(c);
        images.image16x14_pos = pos_of(c);
    } else if (name == "ImageFile16x14") images.image_file16x14 = text_of(c);
    else return false;
    return true;
}

EsiDocument Reader::read_document(const pugi::xml_node root) {
    EsiDocument doc;
    doc.root_pos = pos_of(root);
    const std::string_view name = root.name();
    if (name == "EtherCATInfo") {
        doc.kind = DocumentKind::ethercat_info;
        doc.infos.push_back(read_info(root));
    } else if (name == "EtherCATModule") {
        doc.kind = DocumentKind::ethercat_module;
        doc.infos.push_back(read_info(root));
    } else if (name == "EtherCATInfoList") {
        doc.kind = DocumentKind::ethercat_info_list;
        for (const auto a : root.attributes()) keep(doc.root_extras, a);
        for_children(root, [&](const pugi::xml_node c, std::string_view n, std::string_view previous) {
            if (n == "EtherCATInfo") doc.infos.push_back(read_info(c));
            else keep(doc.root_extras, c, previous);
        });
    } else if (name == "EtherCATDict") {
        doc.kind = DocumentKind::ethercat_dict;
        for (const auto a : root.attributes()) {
            if (std::string_view(a.name()) == "Version") doc.dict_version = a.value();
            else keep(doc.root_extras, a);
        }
        for_children(root, [&](const pugi::xml_node c, std::string_view n, std::string_view previous) {
            if (n == "Dictionary" && !doc.dictionary) doc.dictionary = read_dictionary(c);
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

EtherCATInfo Reader::read_info(const pugi::xml_node n) {
    EtherCATInfo info;
    info.pos = pos_of(n);
    for (const auto a : n.attributes()) {
        if (std::string_view(a.name()) == "Version") info.version = a.value();
        else keep(info.extras, a);
    }
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (name == "Vendor") {
            info.vendor = read_vendor(c);
        } else if (name == "Descriptions") {
            info.has_descriptions = true;
            info.descriptions_pos = pos_of(c);
            for (const auto a : c.attributes()) keep(info.descriptions_extras, a);
            for_children(c, [&](const pugi::xml_node d, std::string_view dn, std::string_view dprev) {
                if (dn == "Groups") {
                    for_children(d, [&](const pugi::xml_node g, std::string_view gn, std::string_view) {
                        if (gn == "Group") info.groups.push_back(read_group(g));
                    });
                } else if (dn == "Devices") {
                    for_children(d, [&](const pugi::xml_node dev, std::string_view devn, std::string_view) {
                        if (devn == "Device") info.devices.push_back(read_device(dev));
                    });
                } else if (dn == "Modules") {
                    info.has_modules = true;
                    for_children(d, [&](const pugi::xml_node m, std::string_view mn, std::string_view) {
                        if (mn == "Module") info.modules.push_back(read_module(m));
                    });
                } else {
                    keep(info.descriptions_extras, d, dprev);
                }
            });
        } else if (name == "Modules") {  // EtherCATModule root
            info.has_modules = true;
            for_children(c, [&](const pugi::xml_node m, std::string_view mn, std::string_view) {
                if (mn == "Module") info.modules.push_back(read_module(m));
            });
        } else {
            keep(info.extras, c, previous);
        }
    });
    return info;
}

Vendor Reader::read_vendor(const pugi::xml_node n) {
    Vendor v;
    v.pos = pos_of(n);
    for (const auto a : n.attributes()) {
        const std::string_view an = a.name();
        if (an == "UniqueName") v.unique_name = a.value();
        else if (an == "FileVersion") v.file_version = a.value();
        else keep(v.extras, a);
    }
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (name == "Id") {
            v.id = u32(c);
            v.id_pos = pos_of(c);
        } else if (name == "Name") v.names.push_back(localized(c));
        else if (name == "Comment") v.comments.push_back(localized(c));
        else if (name == "URL") v.urls.push_back(localized(c));
        else if (name == "DescriptionURL") v.description_url = text_of(c);
        else if (!read_image(v.images, c, name)) keep(v.extras, c, previous);
    });
    return v;
}

Group Reader::read_group(const pugi::xml_node n) {
    Group g;
    g.pos = pos_of(n);
    for (const auto a : n.attributes()) {
        const std::string_view an = a.name();
        if (an == "SortOrder") g.sort_order = i32(a, n);
        else if (an == "ParentGroup") g.parent_group = a.value();
        else keep(g.extras, a);
    }
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (name == "Type") {
            g.type = text_of(c);
            g.type_pos = pos_of(c);
        } else if (name == "Name") g.names.push_back(localized(c));
        else if (name == "Comment") g.comments.push_back(localized(c));
        else if (!read_image(g.images, c, name)) keep(g.extras, c, previous);
    });
    return g;
}

DeviceIdentity Reader::read_identity(const pugi::xml_node n) {
    DeviceIdentity t;
    t.pos = pos_of(n);
    t.text = text_of(n);
    for (const auto a : n.attributes()) {
        const std::string_view an = a.name();
        if (an == "ProductCode") t.product_code = u32(a, n);
        else if (an == "RevisionNo") t.revision_no = u32(a, n);
        else if (an == "SerialNo") t.serial_no = u32(a, n);
        else if (an == "TcCfgModeSafeOp") t.tc_cfg_mode_safe_op = boolean(a, n);
        else keep(t.extras, a);
    }
    for_children(n, [&](const pugi::xml_node c, std::string_view, std::string_view previous) { keep(t.extras, c, previous); });
    return t;
}

Device Reader::read_device(const pugi::xml_node n) {
    Device d;
    d.pos = pos_of(n);
    for (const auto a : n.attributes()) {
        const std::string_view an = a.name();
        if (an == "Physics") d.physics = a.value();
        else if (an == "Invisible") d.invisible = boolean(a, n);
        else keep(d.extras, a);
    }
    bool has_type = false;
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (name == "Type") {
            d.type = read_identity(c);
            has_type = true;
        } else if (name == "Name") d.names.push_back(localized(c));
        else if (name == "Comment") d.comments.push_back(localized(c));
        else if (name == "URL") d.urls.push_back(localized(c));
        else if (name == "GroupType") {
            d.group_type = text_of(c);
            d.group_type_pos = pos_of(c);
        } else if (name == "Profile") d.profiles.push_back(read_profile(c));
        else if (name == "Fmmu") d.fmmus.push_back(read_fmmu(c));
        else if (name == "Sm") d.sms.push_back(read_sm(c));
        else if (name == "Su") d.sus.push_back(read_su(c));
        else if (name == "RxPdo") d.rx_pdos.push_back(read_pdo(c, PdoDirection::rx));
        else if (name == "TxPdo") d.tx_pdos.push_back(read_pdo(c, PdoDirection::tx));
        else if (name == "Mailbox") d.mailbox = read_mailbox(c);
        else if (name == "Dc") d.dc = read_dc(c);
        else if (name == "Slots") d.slots = read_slots(c);
        else if (name == "Eeprom") d.eeprom = read_eeprom(c);
        else if (!read_image(d.images, c, name)) keep(d.extras, c, previous);
    });
    if (!has_type) missing("Device", "Type", d.pos);
    return d;
}

SyncManager Reader::read_sm(const pugi::xml_node n) {
    SyncManager sm;
    sm.pos = pos_of(n);
    sm.type = text_of(n);
    for (const auto a : n.attributes()) {
        const std::string_view an = a.name();
        if (an == "StartAddress") sm.start_address = u32(a, n);
        else if (an == "ControlByte") sm.control_byte = u32(a, n);
        else if (an == "DefaultSize") sm.default_size = u32(a, n);
        else if (an == "MinSize") sm.min_size = u32(a, n);
        else if (an == "MaxSize") sm.max_size = u32(a, n);
        else if (an == "Enable") sm.enable = u32(a, n);
        else if (an == "OneByteMode") sm.one_byte_mode = boolean(a, n);
        else if (an == "Virtual") sm.is_virtual = boolean(a, n);
        else if (an == "Watchdog") sm.watchdog = boolean(a, n);
        else if (an == "OpOnly") sm.op_only = boolean(a, n);
        else if (an == "FixedAssignment") sm.fixed_assignment = boolean(a, n);
        else keep(sm.extras, a);
    }
    for_children(n, [&](const pugi::xml_node c, std::string_view, std::string_view previous) { keep(sm.extras, c, previous); });
    return sm;
}

Fmmu Reader::read_fmmu(const pugi::xml_node n) {
    Fmmu f;
    f.pos = pos_of(n);
    f.type = text_of(n);
    for (const auto a : n.attributes()) {
        const std::string_view an = a.name();
        if (an == "Sm") f.sm = u32(a, n);
        else if (an == "Su") f.su = u32(a, n);
        else if (an == "OpOnly") f.op_only = boolean(a, n);
        else keep(f.extras, a);
    }
    for_children(n, [&](const pugi::xml_node c, std::string_view, std::string_view previous) { keep(f.extras, c, previous); });
    return f;
}

SyncUnit Reader::read_su(const pugi::xml_node n) {
    SyncUnit s;
    s.pos = pos_of(n);
    s.text = text_of(n);
    for (const auto a : n.attributes()) {
        const std::string_view an = a.name();
        if (an == "SeparateSu") s.separate_su = boolean(a, n);
        else if (an == "SeparateFrame") s.separate_frame = boolean(a, n);
        else if (an == "DependOnInputState") s.depend_on_input_state = boolean(a, n);
        else if (an == "FrameRepeatSupport") s.frame_repeat_support = boolean(a, n);
        else keep(s.extras, a);
    }
    for_children(n, [&](const pugi::xml_node c, std::string_view, std::string_view previous) { keep(s.extras, c, previous); });
    return s;
}

Pdo Reader::read_pdo(const pugi::xml_node n, PdoDirection direction) {
    Pdo p;
    p.direction = direction;
    p.pos = pos_of(n);
    for (const auto a : n.attributes()) {
        const std::string_view an = a.name();
        if (an == "Fixed") p.fixed = boolean(a, n);
        else if (an == "Mandatory") p.mandatory = boolean(a, n);
        else if (an == "Virtual") p.is_virtual = boolean(a, n);
        else if (an == "Sm") p.sm = u32(a, n);
        else if (an == "Su") p.su = u32(a, n);
        else if (an == "PdoOrder") p.pdo_order = i32(a, n);
        else if (an == "OSFac") p.os_fac = i32(a, n);
        else if (an == "OSMin") p.os_min = i32(a, n);
        else if (an == "OSMax") p.os_max = i32(a, n);
        else if (an == "OSIndexInc") p.os_index_inc = i32(a, n);
        else if (an == "OverwrittenByModule") p.overwritten_by_module = boolean(a, n);
        else if (an == "SRA_Parameter") p.sra_parameter = boolean(a, n);
        else if (an == "SafetyPdoType") p.safety_pdo_type = a.value();
        else if (an == "SafetyConnNumber") p.safety_conn_number = i32(a, n);
        else keep(p.extras, a);
    }
    bool has_index = false;
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (name == "Index") {
            has_index = true;
            p.index_pos = pos_of(c);
            const std::optional<std::uint32_t> index = u32(c);
            p.index = index.value_or(0);
            p.index_invalid = !index;
            for (const auto a : c.attributes()) {
                const std::string_view an = a.name();
                if (an == "DependOnSlot") p.index_depend_on_slot = boolean(a, c);
                else if (an == "DependOnSlotGroup") p.index_depend_on_slot_group = boolean(a, c);
            }
        } else if (name == "Name") p.names.push_back(localized(c));
        else if (name == "Exclude") {
            PdoExclude e;
            e.pos = pos_of(c);
            e.index = u32(c).value_or(0);
            for (const auto a : c.attributes()) {
                const std::string_view an = a.name();
                if (an == "DependOnSlot") e.depend_on_slot = boolean(a, c);
                else if (an == "DependOnSlotGroup") e.depend_on_slot_group = boolean(a, c);
            }
            p.excludes.push_back(e);
        } else if (name == "Entry") p.entries.push_back(read_entry(c));
        else if (name == "ExcludedSm") {
            if (auto v = u32(c)) p.excluded_sms.push_back(*v);
        } else keep(p.extras, c, previous);
    });
    if (!has_index) missing(n.name(), "Index", p.pos);
    return p;
}

PdoEntry Reader::read_entry(const pugi::xml_node n) {
    PdoEntry e;
    e.pos = pos_of(n);
    for (const auto a : n.attributes()) {
        const std::string_view an = a.name();
        if (an == "Fixed") e.fixed = boolean(a, n);
        else keep(e.extras, a);
    }
    bool has_index = false;
    bool has_bit_len = false;
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (name == "Index") {
            has_index = true;
            const std::optional<std::uint32_t> index = u32(c);
            e.index = index.value_or(0);
            e.index_invalid = !index;
            e.index_pos = pos_of(c);
            for (const auto a : c.attributes()) {
                const std::string_view an = a.name();
                if (an == "DependOnSlot") e.index_depend_on_slot = boolean(a, c);
                else if (an == "DependOnSlotGroup") e.index_depend_on_slot_group = boolean(a, c);
            }
        } else if (name == "SubIndex") e.subindex = u32(c);
        else if (name == "BitLen") {
            has_bit_len = true;
            e.bit_len = u32(c).value_or(0);
            e.bit_len_pos = pos_of(c);
        } else if (name == "Name") e.names.push_back(localized(c));
        else if (name == "Comment") e.comment = text_of(c);
        else if (name == "DataType") {
            e.data_type = text_of(c);
            e.data_type_pos = pos_of(c);
            for (const auto a : c.attributes()) {
                const std::string_view an = a.name();
                if (an == "DScale") e.data_type_dscale = a.value();
                else if (an == "SwapData") e.data_type_swap_data = std::string(trim(a.value()));
            }
        } else keep(e.extras, c, previous);
    });
    if (!has_index) missing("Entry", "Index", e.pos);
    if (!has_bit_len) missing("Entry", "BitLen", e.pos);
    return e;
}

InitCmd Reader::read_init_cmd(const pugi::xml_node n) {
    InitCmd cmd;
    cmd.pos = pos_of(n);
    for (const auto a : n.attributes()) {
        const std::string_view an = a.name();
        if (an == "Fixed") cmd.fixed = boolean(a, n);
        else if (an == "CompleteAccess") cmd.complete_access = boolean(a, n);
        else if (an == "OverwrittenByModule") cmd.overwritten_by_module = boolean(a, n);
        else if (an == "Chn") cmd.channel = i32(a, n);
        else keep(cmd.extras, a);
    }
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (name == "Transition") cmd.transitions.push_back(Transition{text_of(c), pos_of(c)});
        else if (name == "Index") {
            cmd.index = u32(c);
            for (const auto a : c.attributes()) {
                const std::string_view an = a.name();
                if (an == "DependOnSlot") cmd.index_depend_on_slot = boolean(a, c);
                else if (an == "DependOnSlotGroup") cmd.index_depend_on_slot_group = boolean(a, c);
            }
        } else if (name == "SubIndex") cmd.subindex = u32(c);
        else if (name == "IDN") cmd.idn = i64(c);
        else if (name == "Type") cmd.type = i64(c);
        else if (name == "Data") {
            cmd.data = hex(c);
            cmd.has_data = true;
            for (const auto a : c.attributes())
                if (std::string_view(a.name()) == "AdaptAutomatically") cmd.data_adapt_automatically = boolean(a, c);
        } else if (name == "Comment") cmd.comment = text_of(c);
        else keep(cmd.extras, c, previous);
    });
    return cmd;
}

CoeProtocol Reader::read_coe(const pugi::xml_node n) {
    CoeProtocol coe;
    coe.pos = pos_of(n);
    for (const auto a : n.attributes()) {
        const std::string_view an = a.name();
        if (an == "SdoInfo") coe.sdo_info = boolean(a, n);
        else if (an == "PdoAssign") coe.pdo_assign = boolean(a, n);
        else if (an == "PdoConfig") coe.pdo_config = boolean(a, n);
        else if (an == "PdoUpload") coe.pdo_upload = boolean(a, n);
        else if (an == "CompleteAccess") coe.complete_access = boolean(a, n);
        else if (an == "SegmentedSdo") coe.segmented_sdo = boolean(a, n);
        else if (an == "DiagHistory") coe.diag_history = boolean(a, n);
        else if (an == "SdoUploadWithMaxLength") coe.sdo_upload_with_max_length = boolean(a, n);
        else if (an == "TimeDistribution") coe.time_distribution = boolean(a, n);
        else if (an == "ModuleOD") coe.module_od = boolean(a, n);
        else if (an == "EdsFile") coe.eds_file = a.value();
        else if (an == "DS402Channels") coe.ds402_channels = i32(a, n);
        else keep(coe.extras, a);
    }
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (name == "InitCmd") coe.init_cmds.push_back(read_init_cmd(c));
        else keep(coe.extras, c, previous);
    });
    return coe;
}

Mailbox Reader::read_mailbox(const pugi::xml_node n) {
    Mailbox m;
    m.pos = pos_of(n);
    for (const auto a : n.attributes()) {
        const std::string_view an = a.name();
        if (an == "DataLinkLayer") m.data_link_layer = boolean(a, n);
        else if (an == "RealTimeMode") m.real_time_mode = boolean(a, n);
        else keep(m.extras, a);
    }
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (name == "CoE") {
            m.coe = read_coe(c);
        } else if (name == "EoE") {
            EoeProtocol eoe;
            eoe.pos = pos_of(c);
            for (const auto a : c.attributes()) {
                const std::string_view an = a.name();
                if (an == "IP") eoe.ip = boolean(a, c);
                else if (an == "MAC") eoe.mac = boolean(a, c);
                else if (an == "TimeStamp") eoe.time_stamp = boolean(a, c);
                else keep(eoe.extras, a);
            }
            for_children(c, [&](const pugi::xml_node cc, std::string_view cn, std::string_view prev) {
                if (cn == "InitCmd") eoe.init_cmds.push_back(read_init_cmd(cc));
                else keep(eoe.extras, cc, prev);
            });
            m.eoe = std::move(eoe);
        } else if (name == "SoE") {
            SoeProtocol soe;
            soe.pos = pos_of(c);
            for (const auto a : c.attributes()) {
                const std::string_view an = a.name();
                if (an == "ChannelCount") soe.channel_count = i32(a, c);
                else if (an == "DriveFollowsBit3Support") soe.drive_follows_bit3_support = boolean(a, c);
                else keep(soe.extras, a);
            }
            for_children(c, [&](const pugi::xml_node cc, std::string_view cn, std::string_view prev) {
                if (cn == "InitCmd") soe.init_cmds.push_back(read_init_cmd(cc));
                else keep(soe.extras, cc, prev);
            });
            m.soe = std::move(soe);
        } else if (name == "AoE") {
            AoeProtocol aoe;
            aoe.pos = pos_of(c);
            for (const auto a : c.attributes()) {
                const std::string_view an = a.name();
                if (an == "AdsRouter") aoe.ads_router = boolean(a, c);
                else if (an == "GenerateOwnNetId") aoe.generate_own_net_id = boolean(a, c);
                else if (an == "InitializeOwnNetId") aoe.initialize_own_net_id = boolean(a, c);
                else keep(aoe.extras, a);
            }
            for_children(c, [&](const pugi::xml_node cc, std::string_view cn, std::string_view prev) {
                if (cn == "InitCmd") aoe.init_cmds.push_back(read_init_cmd(cc));
                else keep(aoe.extras, cc, prev);
            });
            m.aoe = std::move(aoe);
        } else if (name == "FoE" || name == "VoE") {
            PlainProtocol p;
            p.pos = pos_of(c);
            for (const auto a : c.attributes()) keep(p.extras, a);
            for_children(c, [&](const pugi::xml_node cc, std::string_view, std::string_view prev) { keep(p.extras, cc, prev); });
            (name == "FoE" ? m.foe : m.voe) = std::move(p);
        } else {
            keep(m.extras, c, previous);
        }
    });
    return m;
}

DcTime Reader::read_dc_time(const pugi::xml_node n) {
    DcTime t;
    t.pos = pos_of(n);
    t.value = i64(n).value_or(0);
    for (const auto a : n.attributes()) {
        const std::string_view an = a.name();
        if (an == "Factor") t.factor = i32(a, n);
        else if (an == "Input") t.input = boolean(a, n);
        else if (an == "OutputDelayTime") t.output_delay_time = i32(a, n);
        else if (an == "InputDelayTime") t.input_delay_time = i32(a, n);
    }
    return t;
}

DcOpMode Reader::read_op_mode(const pugi::xml_node n) {
    DcOpMode m;
    m.pos = pos_of(n);
    for (const auto a : n.attributes()) keep(m.extras, a);
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (name == "Name") m.name = text_of(c);
        else if (name == "Desc") m.desc = text_of(c);
        else if (name == "AssignActivate") {
            m.assign_activate_pos = pos_of(c);
            if (auto v = u32(c)) {
                m.assign_activate = *v;
                m.has_assign_activate = true;
            }
        } else if (name == "CycleTimeSync0") m.cycle_time_sync0 = read_dc_time(c);
        else if (name == "ShiftTimeSync0") m.shift_time_sync0 = read_dc_time(c);
        else if (name == "CycleTimeSync1") m.cycle_time_sync1 = read_dc_time(c);
        else if (name == "ShiftTimeSync1") m.shift_time_sync1 = read_dc_time(c);
        else keep(m.extras, c, previous);
    });
    return m;
}

Dc Reader::read_dc(const pugi::xml_node n) {
    Dc dc;
    dc.pos = pos_of(n);
    for (const auto a : n.attributes()) {
        const std::string_view an = a.name();
        if (an == "UnknownFRMW") dc.unknown_frmw = boolean(a, n);
        else if (an == "Unknown64Bit") dc.unknown_64bit = boolean(a, n);
        else if (an == "ExternalRefClock") dc.external_ref_clock = boolean(a, n);
        else if (an == "PotentialReferenceClock") dc.potential_reference_clock = boolean(a, n);
        else if (an == "TimeLoopControlOnly") dc.time_loop_control_only = boolean(a, n);
        else keep(dc.extras, a);
    }
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (name == "OpMode") dc.op_modes.push_back(read_op_mode(c));
        else keep(dc.extras, c, previous);
    });
    return dc;
}

Eeprom Reader::read_eeprom(const pugi::xml_node n) {
    Eeprom e;
    e.pos = pos_of(n);
    for (const auto a : n.attributes()) {
        if (std::string_view(a.name()) == "AssignToPdi") e.assign_to_pdi = boolean(a, n);
        else keep(e.extras, a);
    }
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (name == "Data") e.data = hex(c);
        else if (name == "ByteSize") {
            e.byte_size = u32(c);
            e.byte_size_pos = pos_of(c);
        } else if (name == "ConfigData") e.config_data = hex(c);
        else if (name == "BootStrap") e.boot_strap = hex(c);
        else if (name == "Category") {
            EepromCategory cat;
            cat.pos = pos_of(c);
            for (const auto a : c.attributes()) {
                if (std::string_view(a.name()) == "PreserveOnlineData") cat.preserve_online_data = boolean(a, c);
                else keep(cat.extras, a);
            }
            for_children(c, [&](const pugi::xml_node cc, std::string_view cn, std::string_view prev) {
                if (cn == "CatNo") {
                    cat.cat_no = u32(cc).value_or(0);
                    cat.cat_no_pos = pos_of(cc);
                } else if (cn == "Data") cat.data = hex(cc);
                else if (cn == "DataString") cat.data_string = cc.text().get();
                else if (cn == "DataUINT") cat.data_uint = u64(cc);
                else if (cn == "DataUDINT") cat.data_udint = u64(cc);
                else keep(cat.extras, cc, prev);
            });
            e.categories.push_back(std::move(cat));
        } else keep(e.extras, c, previous);
    });
    return e;
}

Profile Reader::read_profile(const pugi::xml_node n) {
    Profile p;
    p.pos = pos_of(n);
    for (const auto a : n.attributes()) {
        if (std::string_view(a.name()) == "Channel") p.channel = i32(a, n);
        else keep(p.extras, a);
    }
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (name == "ProfileNo") p.profile_no = i32(c);
        else if (name == "AddInfo") p.add_info = i32(c);
        else if (name == "DictionaryFile") p.dictionary_file = text_of(c);
        else if (name == "Dictionary") p.dictionary = read_dictionary(c);
        else keep(p.extras, c, previous);
    });
    return p;
}

Dictionary Reader::read_dictionary(const pugi::xml_node n) {
    Dictionary d;
    d.pos = pos_of(n);
    for (const auto a : n.attributes()) keep(d.extras, a);
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (name == "DataTypes") {
            for_children(c, [&](const pugi::xml_node t, std::string_view tn, std::string_view) {
                if (tn == "DataType") d.data_types.push_back(read_data_type(t));
            });
        } else if (name == "Objects") {
            for_children(c, [&](const pugi::xml_node o, std::string_view on, std::string_view) {
                if (on == "Object") d.objects.push_back(read_object(o));
            });
        } else {
            keep(d.extras, c, previous);
        }
    });
    return d;
}

DataType Reader::read_data_type(const pugi::xml_node n) {
    DataType t;
    t.pos = pos_of(n);
    for (const auto a : n.attributes()) keep(t.extras, a);
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (name == "Index") t.index = u32(c);
        else if (name == "Name") {
            t.name = text_of(c);
            t.name_pos = pos_of(c);
        } else if (name == "BaseType") t.base_type = text_of(c);
        else if (name == "Comment") t.comments.push_back(localized(c));
        else if (name == "BitSize") t.bit_size = u64(c).value_or(0);
        else if (name == "ArrayInfo") {
            ArrayInfo ai;
            ai.pos = pos_of(c);
            for_children(c, [&](const pugi::xml_node cc, std::string_view cn, std::string_view) {
                if (cn == "LBound") ai.lower_bound = i64(cc).value_or(0);
                else if (cn == "Elements") ai.elements = i64(cc).value_or(0);
            });
            t.array_info.push_back(ai);
        } else if (name == "SubItem") t.sub_items.push_back(read_type_sub_item(c));
        else if (name == "EnumInfo") {
            EnumValue ev;
            ev.pos = pos_of(c);
            for_children(c, [&](const pugi::xml_node cc, std::string_view cn, std::string_view) {
                if (cn == "Text") ev.texts.push_back(localized(cc));
                else if (cn == "Enum") ev.value = number(cc.text().get(), "Enum", pos_of(cc)).value_or(Number{});
                else if (cn == "Comment") ev.comments.push_back(localized(cc));
            });
            t.enums.push_back(std::move(ev));
        } else keep(t.extras, c, previous);
    });
    return t;
}

DataTypeSubItem Reader::read_type_sub_item(const pugi::xml_node n) {
    DataTypeSubItem s;
    s.pos = pos_of(n);
    for (const auto a : n.attributes()) keep(s.extras, a);
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (name == "SubIdx") s.subindex = u32(c);
        else if (name == "Name") s.name = text_of(c);
        else if (name == "DisplayName") s.display_names.push_back(localized(c));
        else if (name == "Type") s.type = text_of(c);
        else if (name == "Comment") s.comments.push_back(localized(c));
        else if (name == "BitSize") s.bit_size = u64(c).value_or(0);
        else if (name == "BitOffs") s.bit_offset = u64(c).value_or(0);
        else if (name == "DefaultString") s.default_string = c.text().get();
        else if (name == "DefaultData") s.default_data = hex(c);
        else if (name == "MinValue") s.min_value = number(c.text().get(), "MinValue", pos_of(c));
        else if (name == "MaxValue") s.max_value = number(c.text().get(), "MaxValue", pos_of(c));
        else if (name == "DefaultValue") s.default_value = number(c.text().get(), "DefaultValue", pos_of(c));
        else if (name == "Flags") s.flags = read_flags(c);
        else keep(s.extras, c, previous);
    });
    return s;
}

ObjectFlags Reader::read_flags(const pugi::xml_node n) {
    ObjectFlags f;
    f.pos = pos_of(n);
    for (const auto a : n.attributes()) keep(f.extras, a);
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (name == "Access") {
            f.access = text_of(c);
            for (const auto a : c.attributes()) {
                const std::string_view an = a.name();
                if (an == "ReadRestrictions") f.access_read_restrictions = a.value();
                else if (an == "WriteRestrictions") f.access_write_restrictions = a.value();
            }
        } else if (name == "Category") f.category = text_of(c);
        else if (name == "PdoMapping") f.pdo_mapping = text_of(c);
        else if (name == "SafetyMapping") f.safety_mapping = text_of(c);
        else if (name == "Attribute") f.attribute = u32(c);
        else if (name == "Transition") f.transition = text_of(c);
        else if (name == "SdoAccess") f.sdo_access = text_of(c);
        else if (name == "Backup") f.backup = i32(c);
        else if (name == "Setting") f.setting = i32(c);
        else keep(f.extras, c, previous);
    });
    return f;
}

ObjectInfo Reader::read_object_info(const pugi::xml_node n, std::size_t depth) {
    ObjectInfo info;
    info.pos = pos_of(n);
    for (const auto a : n.attributes()) keep(info.extras, a);
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (name == "DefaultString") info.default_string = c.text().get();
        else if (name == "MinData") info.min_data = hex(c);
        else if (name == "MaxData") info.max_data = hex(c);
        else if (name == "DefaultData") info.default_data = hex(c);
        else if (name == "MinValue") info.min_value = number(c.text().get(), "MinValue", pos_of(c));
        else if (name == "MaxValue") info.max_value = number(c.text().get(), "MaxValue", pos_of(c));
        else if (name == "DefaultValue") info.default_value = number(c.text().get(), "DefaultValue", pos_of(c));
        else if (name == "DisplayName") info.display_name = text_of(c);
        else if (name == "Unit") info.unit = u32(c);
        else if (name == "SubItem" && depth < 8) {
            ObjectSubItemInfo sub;
            sub.pos = pos_of(c);
            for_children(c, [&](const pugi::xml_node cc, std::string_view cn, std::string_view prev) {
                if (cn == "Name") sub.name = text_of(cc);
                else if (cn == "Info") sub.info = read_object_info(cc, depth + 1);
                else keep(sub.extras, cc, prev);
            });
            info.sub_items.push_back(std::move(sub));
        } else keep(info.extras, c, previous);
    });
    return info;
}

Object Reader::read_object(const pugi::xml_node n) {
    Object o;
    o.pos = pos_of(n);
    for (const auto a : n.attributes()) keep(o.extras, a);
    bool has_index = false;
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (name == "Index") {
            has_index = true;
            o.index = u32(c).value_or(0);
            o.index_pos = pos_of(c);
            for (const auto a : c.attributes()) {
                const std::string_view an = a.name();
                if (an == "DependOnSlot") o.index_depend_on_slot = boolean(a, c);
                else if (an == "DependOnSlotGroup") o.index_depend_on_slot_group = boolean(a, c);
                else if (an == "OverwrittenByModule") o.index_overwritten_by_module = boolean(a, c);
            }
        } else if (name == "Name") o.names.push_back(localized(c));
        else if (name == "Comment") o.comments.push_back(localized(c));
        else if (name == "Type") {
            o.type = text_of(c);
            o.type_pos = pos_of(c);
        } else if (name == "BitSize") {
            o.bit_size = u64(c).value_or(0);
            o.bit_size_pos = pos_of(c);
        } else if (name == "Info") o.info = read_object_info(c, 0);
        else if (name == "Flags") o.flags = read_flags(c);
        else keep(o.extras, c, previous);
    });
    if (!has_index) missing("Object", "Index", o.pos);
    return o;
}

Module Reader::read_module(const pugi::xml_node n) {
    Module m;
    m.pos = pos_of(n);
    for (const auto a : n.attributes()) keep(m.extras, a);
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (name == "Type") {
            m.type = text_of(c);
            m.type_pos = pos_of(c);
            for (const auto a : c.attributes()) {
                const std::string_view an = a.name();
                if (an == "ModuleIdent") m.module_ident = u32(a, c).value_or(0);
                else if (an == "ModuleClass") m.module_class = a.value();
                else if (an == "ModulePdoGroup") m.module_pdo_group = i32(a, c);
                else keep(m.type_extras, a);
            }
        } else if (name == "Name") m.names.push_back(localized(c));
        else if (name == "RxPdo") m.rx_pdos.push_back(read_pdo(c, PdoDirection::rx));
        else if (name == "TxPdo") m.tx_pdos.push_back(read_pdo(c, PdoDirection::tx));
        else if (name == "Mailbox") m.mailbox = read_mailbox(c);
        else if (name == "Profile") m.profile = read_profile(c);
        else if (name == "DcOpModeName") m.dc_op_mode_name = text_of(c);
        else if (!read_image(m.images, c, name)) keep(m.extras, c, previous);
    });
    return m;
}

Slot Reader::read_slot(const pugi::xml_node n) {
    Slot s;
    s.pos = pos_of(n);
    for (const auto a : n.attributes()) {
        const std::string_view an = a.name();
        if (an == "SlotGroup") s.slot_group = u32(a, n);
        else if (an == "MinInstances") s.min_instances = u32(a, n).value_or(0);
        else if (an == "MaxInstances") s.max_instances = u32(a, n).value_or(0);
        else if (an == "SlotPdoIncrement") s.slot_pdo_increment = u32(a, n);
        else if (an == "SlotGroupPdoIncrement") s.slot_group_pdo_increment = u32(a, n);
        else if (an == "SlotIndexIncrement") s.slot_index_increment = u32(a, n);
        else if (an == "SlotGroupIndexIncrement") s.slot_group_index_increment = u32(a, n);
        else if (an == "Default") s.default_ident = u32(a, n);
        else if (an == "Fallback") s.fallback = u32(a, n);
        else keep(s.extras, a);
    }
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (name == "Name") s.names.push_back(localized(c));
        else if (name == "ModuleIdent") {
            SlotModuleIdent id;
            id.pos = pos_of(c);
            id.value = u32(c).value_or(0);
            for (const auto a : c.attributes())
                if (std::string_view(a.name()) == "Default") id.default_ident = u32(a, c);
            s.module_idents.push_back(id);
        } else if (name == "ModuleClass") {
            SlotModuleClass mc;
            mc.pos = pos_of(c);
            for (const auto a : c.attributes()) keep(mc.extras, a);
            for_children(c, [&](const pugi::xml_node cc, std::string_view cn, std::string_view prev) {
                if (cn == "Class") mc.class_name = text_of(cc);
                else if (cn == "VendorId") mc.vendor_id = u32(cc);
                else if (cn == "Name") mc.names.push_back(localized(cc));
                else keep(mc.extras, cc, prev);
            });
            s.module_classes.push_back(std::move(mc));
        } else if (!read_image(s.images, c, name)) keep(s.extras, c, previous);
    });
    return s;
}

Slots Reader::read_slots(const pugi::xml_node n) {
    Slots s;
    s.pos = pos_of(n);
    for (const auto a : n.attributes()) {
        const std::string_view an = a.name();
        if (an == "MaxSlotCount") s.max_slot_count = u32(a, n);
        else if (an == "MaxSlotGroupCount") s.max_slot_group_count = u32(a, n);
        else if (an == "SlotPdoIncrement") s.slot_pdo_increment = u32(a, n);
        else if (an == "SlotGroupPdoIncrement") s.slot_group_pdo_increment = u32(a, n);
        else if (an == "SlotIndexIncrement") s.slot_index_increment = u32(a, n);
        else if (an == "SlotGroupIndexIncrement") s.slot_group_index_increment = u32(a, n);
        else keep(s.extras, a);
    }
    for_children(n, [&](const pugi::xml_node c, std::string_view name, std::string_view previous) {
        if (name == "Slot") s.slots.push_back(read_slot(c));
        else keep(s.extras, c, previous);
    });
    return s;
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

ReadResult read_esi_owned(std::string bytes_in, std::string path, const ReadOptions& options) {
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

    pugi::xml_document xml;
    const unsigned parse_options = pugi::parse_default | pugi::parse_embed_pcdata | pugi::parse_doctype;
    const pugi::xml_parse_result parsed =
        xml.load_buffer(source->text().data(), source->text().size(), parse_options, pugi::encoding_utf8);
    if (!parsed) {
        result.diagnostics.emplace(Severity::error, "xml-syntax", describe_parse_error(parsed), path,
                                   error_position(*source, parsed));
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
    Reader reader(*source, result.diagnostics, options);
    EsiDocument doc = reader.read_document(root);
    doc.path = path;
    doc.encoding = decoded.encoding;
    if (options.keep_source) doc.source = source;
    result.document = std::move(doc);
    return result;
}

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
    // Regular files announce their size; pipes and devices are bounded while reading.
    const auto size = std::filesystem::file_size(path, ec);
    if (!ec && size > max_bytes) return too_large();
    std::string bytes;
    if (!ec) bytes.reserve(static_cast<std::size_t>(size));
    char buffer[1 << 16];
    for (;;) {
        const std::size_t n = std::fread(buffer, 1, sizeof buffer, file);
        bytes.append(buffer, n);
        if (bytes.size() > max_bytes) return too_large();
        if (n < sizeof buffer) break;
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
