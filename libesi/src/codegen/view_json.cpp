#include "codegen/view_json.hpp"

namespace esi::codegen {

nlohmann::ordered_json to_json(const ViewValue& value) {
    using Json = nlohmann::ordered_json;
    switch (value.kind) {
        case ViewValue::Kind::null: return Json(nullptr);
        case ViewValue::Kind::boolean: return Json(value.boolean);
        case ViewValue::Kind::integer: return Json(value.integer);
        case ViewValue::Kind::unsigned_integer: return Json(value.unsigned_integer);
        case ViewValue::Kind::real: return Json(value.real);
        case ViewValue::Kind::string: return Json(std::string(value.text()));
        case ViewValue::Kind::list: {
            Json out = Json::array();
            auto& items = out.get_ref<Json::array_t&>();
            items.reserve(value.size);
            for (const ViewValue* item = value.begin_items(); item != value.end_items(); ++item) items.push_back(to_json(*item));
            return out;
        }
        case ViewValue::Kind::object: {
            Json out = Json::object();
            // Keys are unique by construction: appending keeps the order without ordered_map's
            // linear search per insert.
            auto& members = out.get_ref<Json::object_t&>();
            members.reserve(value.size);
            for (const ViewMember* m = value.begin_members(); m != value.end_members(); ++m)
                members.emplace_back(std::string(m->key), to_json(m->value));
            return out;
        }
    }
    return Json(nullptr);
}

ViewValue from_json(ViewArena& arena, const nlohmann::ordered_json& json) {
    using Json = nlohmann::ordered_json;
    switch (json.type()) {
        case Json::value_t::boolean: return ViewValue::of_bool(json.get<bool>());
        case Json::value_t::number_integer: return ViewValue::of_int(json.get<std::int64_t>());
        case Json::value_t::number_unsigned: return ViewValue::of_uint(json.get<std::uint64_t>());
        case Json::value_t::number_float: return ViewValue::of_real(json.get<double>());
        case Json::value_t::string: return arena.string(json.get_ref<const std::string&>());
        case Json::value_t::array: {
            ListBuilder list(arena);
            for (const auto& item : json) list.add(from_json(arena, item));
            return list.finish();
        }
        case Json::value_t::object: {
            ObjectBuilder object(arena);
            for (const auto& [key, child] : json.items()) object.add(arena.key(key), from_json(arena, child));
            return object.finish();
        }
        default: return ViewValue::null();
    }
}

}  // namespace esi::codegen
