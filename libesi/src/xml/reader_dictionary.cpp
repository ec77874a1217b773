// ESI XML -> model: Profile and its object Dictionary (DataTypes, Objects with Info and Flags),
// as found in a Device, a Module or an EtherCATDict root.

#include "xml/reader_context.hpp"

namespace esi::xml_reader {

void Reader::read_profile(Profile& p, const Element n) {
    p.pos = pos_of(n);
    for (const Attr& a : n.attributes()) {
        if (is(a.name, "Channel")) p.channel = i32(a, n);
        else keep(p.extras, a);
    }
    for_children(n, [&](const Element c, std::string_view name, std::string_view previous) {
        if (is(name, "ProfileNo")) p.profile_no = i32(c);
        else if (is(name, "AddInfo")) p.add_info = i32(c);
        else if (is(name, "DictionaryFile")) text(p.dictionary_file, c);
        else if (is(name, "Dictionary")) read_dictionary(p.dictionary.emplace(), c);
        else keep(p.extras, c, previous);
    });
}

void Reader::read_dictionary(Dictionary& d, const Element n) {
    d.pos = pos_of(n);
    for (const Attr& a : n.attributes()) keep(d.extras, a);
    for_children(n, [&](const Element c, std::string_view name, std::string_view previous) {
        if (is(name, "DataTypes")) {
            reserve_for(d.data_types, c, "DataType");
            for_children(c, [&](const Element t, std::string_view tn, std::string_view) {
                if (!is(tn, "DataType")) return;
                read_data_type(d.data_types.emplace_back(), t);
            });
        } else if (is(name, "Objects")) {
            reserve_for(d.objects, c, "Object");
            for_children(c, [&](const Element o, std::string_view on, std::string_view) {
                if (!is(on, "Object")) return;
                read_object(d.objects.emplace_back(), o);
            });
        } else {
            keep(d.extras, c, previous);
        }
    });
}

void Reader::read_data_type(DataType& t, const Element n) {
    t.pos = pos_of(n);
    for (const Attr& a : n.attributes()) keep(t.extras, a);
    reserve_for(t.sub_items, n, "SubItem");
    for_children(n, [&](const Element c, std::string_view name, std::string_view previous) {
        if (is(name, "Index")) t.index = u32(c);
        else if (is(name, "Name")) {
            text(t.name, c);
            t.name_pos = pos_of(c);
        } else if (is(name, "BaseType")) text(t.base_type, c);
        else if (is(name, "Comment")) localized(t.comments, c);
        else if (is(name, "BitSize")) t.bit_size = u64(c).value_or(0);
        else if (is(name, "ArrayInfo")) {
            ArrayInfo ai;
            ai.pos = pos_of(c);
            for_children(c, [&](const Element cc, std::string_view cn, std::string_view) {
                if (is(cn, "LBound")) ai.lower_bound = i64(cc).value_or(0);
                else if (is(cn, "Elements")) ai.elements = i64(cc).value_or(0);
            });
            t.array_info.push_back(ai);
        } else if (is(name, "SubItem")) read_type_sub_item(t.sub_items.emplace_back(), c);
        else if (is(name, "EnumInfo")) {
            EnumValue ev;
            ev.pos = pos_of(c);
            for_children(c, [&](const Element cc, std::string_view cn, std::string_view) {
                if (is(cn, "Text")) localized(ev.texts, cc);
                else if (is(cn, "Enum")) ev.value = number(cc).value_or(Number{});
                else if (is(cn, "Comment")) localized(ev.comments, cc);
            });
            t.enums.push_back(std::move(ev));
        } else keep(t.extras, c, previous);
    });
}

void Reader::read_type_sub_item(DataTypeSubItem& s, const Element n) {
    s.pos = pos_of(n);
    for (const Attr& a : n.attributes()) keep(s.extras, a);
    for_children(n, [&](const Element c, std::string_view name, std::string_view previous) {
        if (is(name, "SubIdx")) s.subindex = u32(c);
        else if (is(name, "Name")) text(s.name, c);
        else if (is(name, "DisplayName")) localized(s.display_names, c);
        else if (is(name, "Type")) text(s.type, c);
        else if (is(name, "Comment")) localized(s.comments, c);
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

void Reader::read_flags(ObjectFlags& f, const Element n) {
    f.pos = pos_of(n);
    for (const Attr& a : n.attributes()) keep(f.extras, a);
    for_children(n, [&](const Element c, std::string_view name, std::string_view previous) {
        if (is(name, "Access")) {
            text(f.access, c);
            for (const Attr& a : c.attributes()) {
                const std::string_view an = a.name;
                if (is(an, "ReadRestrictions")) f.access_read_restrictions = a.value;
                else if (is(an, "WriteRestrictions")) f.access_write_restrictions = a.value;
            }
        } else if (is(name, "Category")) text(f.category, c);
        else if (is(name, "PdoMapping")) text(f.pdo_mapping, c);
        else if (is(name, "SafetyMapping")) text(f.safety_mapping, c);
        else if (is(name, "Attribute")) f.attribute = u32(c);
        else if (is(name, "Transition")) text(f.transition, c);
        else if (is(name, "SdoAccess")) text(f.sdo_access, c);
        else if (is(name, "Backup")) f.backup = i32(c);
        else if (is(name, "Setting")) f.setting = i32(c);
        else keep(f.extras, c, previous);
    });
}

void Reader::read_object_info(ObjectInfo& info, const Element n, std::size_t depth) {
    info.pos = pos_of(n);
    for (const Attr& a : n.attributes()) keep(info.extras, a);
    // Only an object's own Info lists SubItems in practice; the Infos of sub-items are leaves, and
    // counting their children costs a lookup each.
    if (depth == 0) reserve_for(info.sub_items, n, "SubItem");
    for_children(n, [&](const Element c, std::string_view name, std::string_view previous) {
        if (is(name, "DefaultString")) info.default_string = pcdata(c);
        else if (is(name, "MinData")) info.min_data = hex(c);
        else if (is(name, "MaxData")) info.max_data = hex(c);
        else if (is(name, "DefaultData")) info.default_data = hex(c);
        else if (is(name, "MinValue")) info.min_value = number(c);
        else if (is(name, "MaxValue")) info.max_value = number(c);
        else if (is(name, "DefaultValue")) info.default_value = number(c);
        else if (is(name, "DisplayName")) text(info.display_name, c);
        else if (is(name, "Unit")) info.unit = u32(c);
        else if (is(name, "SubItem") && depth < 8) {
            ObjectSubItemInfo& sub = info.sub_items.emplace_back();
            sub.pos = pos_of(c);
            bool has_info = false;
            for_children(c, [&](const Element cc, std::string_view cn, std::string_view prev) {
                if (is(cn, "Name")) text(sub.name, cc);
                else if (is(cn, "Info")) {
                    if (has_info) sub.info = {};  // a repeated Info replaces the first
                    read_object_info(sub.info, cc, depth + 1);
                    has_info = true;
                } else keep(sub.extras, cc, prev);
            });
        } else keep(info.extras, c, previous);
    });
}

void Reader::read_object(Object& o, const Element n) {
    o.pos = pos_of(n);
    for (const Attr& a : n.attributes()) keep(o.extras, a);
    bool has_index = false;
    for_children(n, [&](const Element c, std::string_view name, std::string_view previous) {
        if (is(name, "Index")) {
            has_index = true;
            o.index = u32(c).value_or(0);
            o.index_pos = pos_of(c);
            depend_on_slot(c, o.index_depend_on_slot, o.index_depend_on_slot_group, [&](const Attr& a) {
                if (is(a.name, "OverwrittenByModule")) o.index_overwritten_by_module = boolean(a, c);
            });
        } else if (is(name, "Name")) localized(o.names, c);
        else if (is(name, "Comment")) localized(o.comments, c);
        else if (is(name, "Type")) {
            text(o.type, c);
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

}  // namespace esi::xml_reader
