// Every type an Object, a SubItem or a BaseType names must be declared as a DataType: the ETG
// schema's DataTypesKey/ObjectTypesRef keyrefs (EtherCATBase.xsd ProfileType) reject a dictionary
// that uses UINT without a <DataType><Name>UINT</Name>…</DataType>. Basic types, STRING(n) and
// "ARRAY [a..b] OF T" are declared here from the one data-type table; a name that is none of
// these and not declared by the source is an error at the place that uses it.

#include <algorithm>
#include <map>
#include <set>

#include "derive/steps.hpp"
#include "esi/derive/object_builder.hpp"

namespace esi::derive {

void derive_data_types(Dictionary& dictionary, Context& context) {
    std::set<std::string, std::less<>> declared;
    for (const auto& t : dictionary.data_types) declared.insert(t.name);

    // Referenced names in order of first use, with where they were used.
    std::map<std::string, SourcePos, std::less<>> wanted;
    std::vector<std::string> queue;
    auto want = [&](const std::string& name, SourcePos pos) {
        if (name.empty() || declared.count(name) || wanted.count(name)) return;
        wanted.emplace(name, pos);
        queue.push_back(name);
    };
    for (const auto& o : dictionary.objects) want(o.type, o.type_pos.known() ? o.type_pos : o.pos);
    for (const auto& t : dictionary.data_types) {
        if (t.base_type) want(*t.base_type, t.pos);
        for (const auto& s : t.sub_items) want(s.type, s.pos);
    }

    std::vector<DataType> added;
    for (std::size_t i = 0; i < queue.size(); ++i) {
        const std::string name = queue[i];
        const SourcePos pos = wanted[name];
        const TypeName parsed = parse_type_name(name);
        DataType t;
        t.name = name;
        t.pos = t.name_pos = pos;
        switch (parsed.kind) {
            case TypeName::Kind::basic:
            case TypeName::Kind::string:
                t.bit_size = implied_bit_size(name).value_or(0);
                break;
            case TypeName::Kind::array: {
                t.base_type = parsed.element;
                t.bit_size = implied_bit_size(name).value_or(0);
                t.array_info.push_back(ArrayInfo{parsed.lower_bound, static_cast<std::int64_t>(parsed.element_count()), pos});
                want(parsed.element, pos);
                break;
            }
            case TypeName::Kind::named:
                context.error(pos, "derive-data-type",
                              "the type '" + name + "' is neither a basic type (UINT, DINT, STRING(8) …) nor declared in data_types");
                continue;
        }
        added.push_back(std::move(t));
    }
    std::sort(added.begin(), added.end(), [](const DataType& a, const DataType& b) { return a.name < b.name; });
    for (auto& t : added) dictionary.data_types.push_back(std::move(t));

    for (auto& o : dictionary.objects)
        if (o.bit_size == 0) o.bit_size = type_bit_size(dictionary, o.type);
}

}  // namespace esi::derive
