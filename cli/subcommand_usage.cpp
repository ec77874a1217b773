#include "subcommand_usage.hpp"

#include <filesystem>
#include <string_view>
#include <vector>

#include "esi/text_distance.hpp"

namespace esi::cli {

std::optional<std::string> subcommand_usage(const CLI::App& app, int argc, char** argv) {
    std::vector<std::string> names;
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) names.push_back(sub->get_name());
    if (names.empty() || app.get_require_subcommand_min() == 0) return std::nullopt;
    // The first word that is not an option is where the subcommand belongs.
    std::optional<std::string> word;
    for (int i = 1; i < argc && !word; ++i)
        if (argv[i][0] != '-') word = argv[i];
    for (const auto& name : names)
        if (word == name) return std::nullopt;

    const std::string tool = argc > 0 ? std::filesystem::path(argv[0]).filename().string() : app.get_name();
    std::string valid;
    for (std::size_t i = 0; i < names.size(); ++i)
        valid += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
    if (!word) return tool + ": a subcommand is required: " + valid + " (--help for usage)\n";
    const std::vector<std::string_view> candidates(names.begin(), names.end());
    const std::string nearest = closest_match(*word, candidates);
    return tool + ": unknown subcommand '" + *word + "'" + (nearest.empty() ? "" : "; did you mean '" + nearest + "'?") +
           " (subcommands: " + valid + "; --help for usage)\n";
}

}  // namespace esi::cli
