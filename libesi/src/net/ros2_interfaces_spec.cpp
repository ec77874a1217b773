// `ros2_interfaces:` of a slave: which ros2_control interface each mapped entry feeds, with the
// ethercat_driver_ros2 channel options (factor, offset, default) that only the user can know.

#include "ros2_interfaces_spec.hpp"

#include <cmath>
#include <limits>
#include <set>

#include "esi/net/network_keys.hpp"
#include "esi/number.hpp"

namespace esi::net {

namespace {

}  // namespace

bool parse_entry_key(std::string_view text, std::uint32_t& index, std::uint32_t& subindex) {
    const std::size_t colon = text.find(':');
    if (colon == std::string_view::npos) return false;
    const ParsedNumber i = parse_number(text.substr(0, colon));
    const ParsedNumber s = parse_number(text.substr(colon + 1));
    if (!i.ok() || !s.ok() || i.value.negative || s.value.negative) return false;
    const auto iv = i.value.as_uint64();
    const auto sv = s.value.as_uint64();
    if (!iv || !sv || *iv == 0 || *iv > 0xFFFF || *sv > 0xFF) return false;
    index = static_cast<std::uint32_t>(*iv);
    subindex = static_cast<std::uint32_t>(*sv);
    return true;
}

namespace {

// The driver reads `default` as a double; `.nan` means "send nothing unless commanded".
std::optional<double> default_value(yaml::Reader& reader, const yaml::Node& node) {
    if (node.IsScalar()) {
        const std::string& t = node.Scalar();
        if (t == ".nan" || t == ".NaN" || t == ".NAN") return std::numeric_limits<double>::quiet_NaN();
    }
    return reader.real(node, "default");
}

// ros2_control joins component and interface names with '/', and the driver looks an interface
// up as "state_interface/NAME": a name with '/' or blanks would never be found.
bool valid_interface_name(std::string_view name) {
    if (name.empty()) return false;
    for (char c : name) {
        const unsigned char u = static_cast<unsigned char>(c);
        if (u <= 0x20 || u == 0x7F || c == '/' || c == '"' || c == '\\') return false;
    }
    return true;
}

}  // namespace

std::vector<Ros2InterfaceSpec> read_ros2_interfaces(yaml::Reader& reader, const yaml::Node& node) {
    std::vector<Ros2InterfaceSpec> out;
    if (!node.IsMap()) {
        reader.error(node, "yaml-type", "'ros2_interfaces' must map entries (INDEX:SUBINDEX) to interface names");
        return out;
    }
    const yaml::Fields fields(node);
    std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
    for (const auto& item : fields.items()) {
        Ros2InterfaceSpec spec;
        spec.pos = item.key_node.pos();
        if (!parse_entry_key(item.key, spec.index, spec.subindex)) {
            reader.error(item.key_node, "yaml-type",
                         "a ros2_interfaces key is an entry INDEX:SUBINDEX (e.g. 0x6000:0x01), not '" + std::string(item.key) + "'");
            continue;
        }
        if (!seen.insert({spec.index, spec.subindex}).second) {
            reader.error(item.key_node, "yaml-duplicate-key", "entry " + std::string(item.key) + " is listed twice");
            continue;
        }
        auto take_name = [&](const yaml::Node& n) {
            if (n.IsNull()) {
                spec.no_interface = true;
                return;
            }
            const auto text = reader.text(n, "name");
            if (!text) return;
            if (!valid_interface_name(*text)) {
                reader.error(n, "net-ros2-interface",
                             "'" + *text + "' cannot be a ros2_control interface name (no blanks, '/', quotes or control characters)");
                return;
            }
            spec.name = *text;
        };
        if (item.value.IsMap()) {
            const auto f = reader.mapping(item.value, network_keys_of(NetworkContext::ros2_interface).keys, "a ros2 interface");
            if (!f) continue;
            if (const yaml::Node* n = f->find("name")) take_name(*n);
            if (const yaml::Node* n = f->find("factor")) spec.factor = reader.real(*n, "factor");
            if (const yaml::Node* n = f->find("offset")) spec.offset = reader.real(*n, "offset");
            if (const yaml::Node* n = f->find("default")) spec.default_value = default_value(reader, *n);
        } else {
            take_name(item.value);
        }
        out.push_back(std::move(spec));
    }
    return out;
}

}  // namespace esi::net
