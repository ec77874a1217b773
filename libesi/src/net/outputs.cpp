#include "esi/net/outputs.hpp"

#include <algorithm>

namespace esi::net {

namespace {

constexpr OutputKind kinds[] = {OutputKind::eni, OutputKind::igh, OutputKind::lcec, OutputKind::map, OutputKind::html, OutputKind::ros2};

}  // namespace

std::span<const OutputKind> all_output_kinds() { return kinds; }

std::string_view to_string(OutputKind kind) {
    switch (kind) {
        case OutputKind::eni: return "eni";
        case OutputKind::igh: return "igh";
        case OutputKind::lcec: return "lcec";
        case OutputKind::map: return "map";
        case OutputKind::html: return "html";
        case OutputKind::ros2: return "ros2";
    }
    return "?";
}

std::optional<std::vector<OutputKind>> parse_output_kinds(std::string_view text, std::string& error) {
    std::vector<OutputKind> out;
    while (true) {
        const std::size_t comma = text.find(',');
        const std::string_view name = text.substr(0, comma);
        const auto it = std::find_if(std::begin(kinds), std::end(kinds), [&](OutputKind k) { return to_string(k) == name; });
        if (it == std::end(kinds)) {
            error = "'" + std::string(name) + "' is not an output kind (eni, igh, lcec, map, html, ros2)";
            return std::nullopt;
        }
        if (std::find(out.begin(), out.end(), *it) == out.end()) out.push_back(*it);
        if (comma == std::string_view::npos) break;
        text.remove_prefix(comma + 1);
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::vector<OutputFile> network_outputs(const Network& network, std::span<const OutputKind> chosen, const std::filesystem::path& directory) {
    std::vector<OutputFile> files;
    auto want = [&](OutputKind k) { return std::find(chosen.begin(), chosen.end(), k) != chosen.end(); };
    if (want(OutputKind::eni)) files.push_back({directory / "network.xml", write_eni(network)});
    if (want(OutputKind::igh)) {
        files.push_back({directory / "igh_config.h", write_igh_header(network)});
        files.push_back({directory / "igh_config.c", write_igh_source(network)});
    }
    if (want(OutputKind::lcec)) files.push_back({directory / "lcec.xml", write_lcec(network)});
    if (want(OutputKind::map)) {
        files.push_back({directory / "process_image.json", write_map_json(network)});
        files.push_back({directory / "process_image.csv", write_map_csv(network)});
        files.push_back({directory / "process_image.md", write_map_markdown(network)});
    }
    return files;
}

}  // namespace esi::net
