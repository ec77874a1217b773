#include "cli_reference.hpp"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string_view>
#include <vector>

namespace esi::cli {

namespace {

// Options CLI11 shows in --help: a non-empty group (an empty group hides an option).
std::vector<const CLI::Option*> visible_options(const CLI::App& app, bool positional) {
    return app.get_options([positional](const CLI::Option* option) {
        return !option->get_group().empty() && option->nonpositional() != positional;
    });
}

std::vector<const CLI::App*> commands(const CLI::App& app) {
    return app.get_subcommands([](const CLI::App* sub) { return !sub->get_group().empty(); });
}

// Text as roff: backslashes and hyphens escaped, a leading period or quote neutralised, and every
// non-ASCII character as \[uXXXX] so that groff needs no input encoding.
std::string roff(std::string_view text) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const auto byte = static_cast<unsigned char>(text[i]);
        if (byte < 0x80) {
            if ((byte == '.' || byte == '\'') && (out.empty() || out.back() == '\n')) out += "\\&";
            if (byte == '\\') out += "\\e";
            else if (byte == '-') out += "\\-";
            else out += static_cast<char>(byte);
            continue;
        }
        // A UTF-8 sequence: its length from the lead byte; a malformed one is dropped.
        const std::size_t length = byte >= 0xF0 ? 4 : byte >= 0xE0 ? 3 : byte >= 0xC0 ? 2 : 0;
        if (length == 0 || i + length > text.size()) continue;
        std::uint32_t code = byte & (0x7F >> length);
        for (std::size_t k = 1; k < length; ++k) code = (code << 6) | (static_cast<unsigned char>(text[i + k]) & 0x3F);
        char hex[16];
        std::snprintf(hex, sizeof hex, "\\[u%04X]", static_cast<unsigned>(code));
        out += hex;
        i += length - 1;
    }
    return out;
}

// Flags expect no value (CLI11 sets expected(0) for them).
bool takes_value(const CLI::Option& option) { return option.get_expected_max() > 0; }

// The names CLI11 prints for an option: -j,--jobs.
std::vector<std::string> option_names(const CLI::Option& option) {
    std::vector<std::string> names;
    for (const auto& s : option.get_snames()) names.push_back("-" + s);
    for (const auto& l : option.get_lnames()) names.push_back("--" + l);
    return names;
}

// The values of an IsMember check, from its description "{a,b,c}" in the type name.
std::vector<std::string> choices(const CLI::Option& option) {
    const std::string type = option.get_type_name();
    const auto open = type.find('{');
    const auto close = type.find('}', open);
    std::vector<std::string> out;
    if (open == std::string::npos || close == std::string::npos) return out;
    std::string item;
    for (char c : type.substr(open + 1, close - open - 1)) {
        if (c == ',') {
            out.push_back(item);
            item.clear();
        } else {
            item += c;
        }
    }
    out.push_back(item);
    return out;
}

std::string synopsis_line(const CLI::App& app, const std::string& command) {
    std::string line = ".B " + roff(command) + "\n";
    if (!visible_options(app, false).empty()) line += "[\\fIOPTIONS\\fR]\n";
    for (const CLI::Option* positional : visible_options(app, true)) {
        std::string name = "\\fI" + roff(positional->get_name(true)) + "\\fR";
        if (positional->get_items_expected_max() > 1) name += "\\ .\\|.\\|.";
        line += positional->get_required() ? name + "\n" : "[" + name + "]\n";
    }
    if (!commands(app).empty()) line += "\\fICOMMAND\\fR [\\fICOMMAND-OPTIONS\\fR]\n";
    return line;
}

std::string option_list(const CLI::App& app) {
    std::string out;
    for (const CLI::Option* positional : visible_options(app, true)) {
        out += ".TP\n\\fI" + roff(positional->get_name(true)) + "\\fR\n" + roff(positional->get_description()) + "\n";
    }
    for (const CLI::Option* option : visible_options(app, false)) {
        out += ".TP\n";
        bool first = true;
        for (const auto& name : option_names(*option)) {
            out += (first ? "\\fB" : ", \\fB") + roff(name) + "\\fR";
            first = false;
        }
        if (takes_value(*option)) out += " \\fI" + roff(option->get_type_name()) + "\\fR";
        out += "\n" + roff(option->get_description()) + "\n";
    }
    return out;
}

std::string description_of(const CLI::App& app, const std::string& tool) {
    // The tools' descriptions read "tool: what it does"; NAME wants "what it does".
    std::string description = app.get_description();
    const std::string lead = tool + ": ";
    if (description.rfind(lead, 0) == 0) description.erase(0, lead.size());
    return description;
}

}  // namespace

std::string render_man_sections(const CLI::App& app, const std::string& tool) {
    std::string out = ".SH NAME\n" + roff(tool) + " \\- " + roff(description_of(app, tool)) + "\n.SH SYNOPSIS\n";
    const auto subcommands = commands(app);
    if (subcommands.empty()) {
        out += synopsis_line(app, tool);
    } else {
        bool first = true;
        for (const CLI::App* sub : subcommands) {
            if (!first) out += ".br\n";
            out += synopsis_line(*sub, tool + " " + sub->get_name());
            first = false;
        }
    }
    out += ".\\\" esi-man-split\n.SH OPTIONS\n" + option_list(app);
    if (!subcommands.empty()) {
        out += ".SH COMMANDS\n";
        for (const CLI::App* sub : subcommands) {
            out += ".SS " + roff(tool + " " + sub->get_name()) + "\n" + roff(sub->get_description()) + "\n" + option_list(*sub);
        }
    }
    return out;
}

std::string render_completion_table(const CLI::App& app) {
    std::string out;
    auto add = [&out](const CLI::App& command, const std::string& name) {
        for (const CLI::Option* positional : visible_options(command, true)) out += "positional\t" + name + "\t" + positional->get_name(true) + "\n";
        for (const CLI::Option* option : visible_options(command, false)) {
            std::string names, values;
            for (const auto& n : option_names(*option)) names += (names.empty() ? "" : " ") + n;
            for (const auto& v : choices(*option)) values += (values.empty() ? "" : " ") + v;
            out += "option\t" + name + "\t" + names + "\t" + (takes_value(*option) ? "1" : "0") + "\t" + (values.empty() ? "-" : values) + "\n";
        }
    };
    add(app, ".");
    for (const CLI::App* sub : commands(app)) {
        out += "command\t" + sub->get_name() + "\t" + sub->get_description() + "\n";
        add(*sub, sub->get_name());
    }
    return out;
}

std::optional<int> print_reference_if_asked(const CLI::App& app, int argc, char** argv) {
    if (argc != 2) return std::nullopt;
    const std::string_view flag = argv[1];
    // CLI11 names the App after argv[0] only while parsing, which these flags skip.
    const std::string tool = app.get_name().empty() ? std::filesystem::path(argv[0]).filename().string() : app.get_name();
    std::string text;
    if (flag == "--help-man") text = render_man_sections(app, tool);
    else if (flag == "--help-completion") text = render_completion_table(app);
    else return std::nullopt;
    std::fwrite(text.data(), 1, text.size(), stdout);
    return std::fflush(stdout) == 0 ? 0 : 2;
}

}  // namespace esi::cli
