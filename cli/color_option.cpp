#include "color_option.hpp"

#include <unistd.h>

#include <cstdlib>

namespace esi::cli {

CLI::Option* add_color_option(CLI::App& app, std::string& when, const std::string& what) {
    when = "auto";
    return app
        .add_flag("--color{always}", when,
                  "colour " + what +
                      ": auto (default: only on a terminal, and not when the NO_COLOR environment variable is set), "
                      "always (--color alone; also under NO_COLOR) or never")
        ->type_name("WHEN")
        ->check(CLI::IsMember({"auto", "always", "never"}));
}

bool color_enabled(const std::string& when, int fd) {
    if (when == "always") return true;
    if (when == "never") return false;
    const char* no_color = std::getenv("NO_COLOR");
    if (no_color && *no_color) return false;
    return ::isatty(fd) != 0;
}

}  // namespace esi::cli
