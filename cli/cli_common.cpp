#include "cli_common.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>

#include "cli_reference.hpp"
#include "esi/version.hpp"
#include "subcommand_usage.hpp"

namespace esi::cli {

std::optional<int> parse_or_exit(CLI::App& app, int argc, char** argv) {
    // The man page and the shell completions are rendered from this App (cli_reference.hpp).
    if (const std::optional<int> printed = print_reference_if_asked(app, argc, argv)) return printed;
    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        if (const std::optional<std::string> usage = subcommand_usage(app, argc, argv)) std::cerr << *usage;
        else app.exit(e);
        return exit_usage;
    }
    return std::nullopt;
}

CLI::Option* add_device_option(CLI::App& app, std::string& text, const std::string& description) {
    return app.add_option("--device", text, description + ": PRODUCTCODE[:REVISION] (decimal, #x… or 0x…)");
}

bool parse_device_option(std::string_view tool, const std::string& text, std::optional<DeviceSelector>& out) {
    out.reset();
    if (text.empty()) return true;
    std::string error;
    out = parse_device_selector(text, error);
    if (out) return true;
    std::cerr << tool << ": --device: " << error << "\n";
    return false;
}

void add_version_flag(CLI::App& app, std::string_view tool) {
    app.set_version_flag("--version", std::string(tool) + " (libesi) " + std::string(version()));
}

bool parse_template_dirs(std::string_view tool, const std::vector<std::string>& given, std::vector<std::filesystem::path>& out) {
    out.clear();
    for (const auto& dir : given) {
        std::error_code ec;
        if (!std::filesystem::is_directory(dir, ec)) {
            std::cerr << tool << ": --templates: " << dir << " is not a directory\n";
            return false;
        }
        out.emplace_back(dir);
    }
    return true;
}

std::optional<std::filesystem::path> executable_path(const char* argv0) {
    std::error_code ec;
    std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) return self;
    if (argv0 && std::string_view(argv0).find('/') != std::string_view::npos) return std::filesystem::absolute(argv0, ec);
    return std::nullopt;
}

void write_stdout(std::string_view text) {
    std::fwrite(text.data(), 1, text.size(), stdout);
    std::fflush(stdout);
}

}  // namespace esi::cli

namespace esi::cli {

int exit_with_stdout_checked(std::string_view tool, int exit_code) {
    std::cout.flush();
    errno = 0;
    const bool flushed = std::fflush(stdout) == 0;
    const int error = errno;
    if (flushed && !std::ferror(stdout) && std::cout.good()) return exit_code;
    std::cerr << tool << ": cannot write standard output" << (error != 0 ? std::string(": ") + std::strerror(error) : std::string()) << "\n";
    return exit_usage;
}

}  // namespace esi::cli
