// Eeprom: the SII contents a tool programs from the file (ETG.2010). Hex data compares
// case-insensitively and without whitespace; categories pair up by CatNo.

#include <map>

#include <fmt/format.h>

#include "diff/compare.hpp"

namespace esi::diff_detail {

namespace {

std::optional<std::string> data(const std::optional<HexData>& d) {
    if (!d) return std::nullopt;
    return normalized_hex(*d);
}

SourcePos pos_of(const std::optional<HexData>& d, SourcePos fallback) { return d && d->pos.known() ? d->pos : fallback; }

std::string describe(const Eeprom& e) {
    if (e.data) return fmt::format("Data ({} bytes)", e.data->byte_length());
    return e.byte_size ? fmt::format("ByteSize {}", *e.byte_size) : std::string("Eeprom");
}

void compare_category(Recorder& r, const std::string& p, const EepromCategory& a, const EepromCategory& b) {
    const auto value = [&](std::string_view name, std::optional<std::string> x, std::optional<std::string> y) {
        r.value(
            ChangeKind::eeprom_category_changed, child(p, name), [&] { return fmt::format("{} of category {}", name, a.cat_no); },
            x, y, a.pos, b.pos);
    };
    value("Data", data(a.data), data(b.data));
    value("DataString", a.data_string, b.data_string);
    const auto u64 = [](const std::optional<std::uint64_t>& v) -> std::optional<std::string> {
        if (!v) return std::nullopt;
        return std::to_string(*v);
    };
    value("DataUINT", u64(a.data_uint), u64(b.data_uint));
    value("DataUDINT", u64(a.data_udint), u64(b.data_udint));
    r.value(ChangeKind::eeprom_attribute_changed, attr(p, "PreserveOnlineData"), "PreserveOnlineData",
            flag(a.preserve_online_data), flag(b.preserve_online_data), a.pos, b.pos);
    compare_extras(r, p, a.extras, b.extras, a.pos, b.pos);
}

}  // namespace

void compare_eeproms(Recorder& r, const std::string& path, const std::optional<Eeprom>& a, const std::optional<Eeprom>& b,
                     SourcePos old_parent, SourcePos new_parent) {
    if (!a && !b) return;
    if (!a || !b) {
        r.add(a ? ChangeKind::eeprom_removed : ChangeKind::eeprom_added, path,
              a ? std::optional<std::string>(describe(*a)) : std::nullopt,
              b ? std::optional<std::string>(describe(*b)) : std::nullopt, a ? a->pos : old_parent, b ? b->pos : new_parent,
              fmt::format("Eeprom description {}", a ? "removed" : "added"));
        return;
    }
    const Eeprom& x = *a;
    const Eeprom& y = *b;
    const auto hex_field = [&](ChangeKind kind, std::string_view name, const std::optional<HexData>& p,
                               const std::optional<HexData>& q) {
        r.value(kind, child(path, name), name, data(p), data(q), pos_of(p, x.pos), pos_of(q, y.pos));
    };
    hex_field(ChangeKind::eeprom_data_changed, "Data", x.data, y.data);
    hex_field(ChangeKind::eeprom_config_data_changed, "ConfigData", x.config_data, y.config_data);
    hex_field(ChangeKind::eeprom_boot_strap_changed, "BootStrap", x.boot_strap, y.boot_strap);
    if (x.byte_size != y.byte_size) {
        const bool decreased = !y.byte_size || (x.byte_size && *y.byte_size < *x.byte_size);
        r.value(decreased ? ChangeKind::eeprom_size_decreased : ChangeKind::eeprom_size_increased, child(path, "ByteSize"),
                "ByteSize", dec(x.byte_size), dec(y.byte_size), x.byte_size_pos.known() ? x.byte_size_pos : x.pos,
                y.byte_size_pos.known() ? y.byte_size_pos : y.pos);
    }
    r.value(ChangeKind::eeprom_attribute_changed, attr(path, "AssignToPdi"), "AssignToPdi", flag(x.assign_to_pdi),
            flag(y.assign_to_pdi), x.pos, y.pos);

    std::map<std::uint32_t, std::vector<const EepromCategory*>> ca;
    std::map<std::uint32_t, std::vector<const EepromCategory*>> cb;
    for (const auto& c : x.categories) ca[c.cat_no].push_back(&c);
    for (const auto& c : y.categories) cb[c.cat_no].push_back(&c);
    std::map<std::uint32_t, bool> numbers;
    for (const auto& [k, v] : ca) numbers[k] = true;
    for (const auto& [k, v] : cb) numbers[k] = true;
    for (const auto& [cat, unused] : numbers) {
        const auto& la = ca[cat];
        const auto& lb = cb[cat];
        const std::size_t n = std::max(la.size(), lb.size());
        for (std::size_t i = 0; i < n; ++i) {
            const EepromCategory* p = i < la.size() ? la[i] : nullptr;
            const EepromCategory* q = i < lb.size() ? lb[i] : nullptr;
            const std::string cp =
                child(path, indexed("Category", n > 1 ? fmt::format("{}#{}", cat, i + 1) : std::to_string(cat)));
            if (p && q) {
                compare_category(r, cp, *p, *q);
                continue;
            }
            r.add(p ? ChangeKind::eeprom_category_removed : ChangeKind::eeprom_category_added, cp,
                  p ? std::optional<std::string>(std::to_string(cat)) : std::nullopt,
                  q ? std::optional<std::string>(std::to_string(cat)) : std::nullopt, p ? p->pos : x.pos, q ? q->pos : y.pos,
                  fmt::format("SII category {} {}", cat, p ? "removed" : "added"));
        }
    }
    compare_extras(r, path, x.extras, y.extras, x.pos, y.pos);
}

}  // namespace esi::diff_detail
