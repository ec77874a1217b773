#include "esi/io/same_file.hpp"

#include <sys/stat.h>

namespace esi {

namespace fs = std::filesystem;

bool same_file(const fs::path& a, const fs::path& b) {
    struct stat sa {};
    struct stat sb {};
    if (::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0) return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
    // One of them does not exist (yet): the same only if both paths lead to one place.
    std::error_code ea;
    std::error_code eb;
    const fs::path ca = fs::weakly_canonical(a, ea);
    const fs::path cb = fs::weakly_canonical(b, eb);
    return !ea && !eb && ca == cb;
}

Diagnostics refuse_output_over_input(const fs::path& output, const std::vector<fs::path>& inputs) {
    Diagnostics diagnostics;
    for (const auto& input : inputs) {
        if (!same_file(output, input)) continue;
        const bool spelled_alike = fs::path(output).lexically_normal() == fs::path(input).lexically_normal();
        diagnostics.emplace(Severity::error, "output-is-input",
                            "the output " + output.string() + " is the input " + input.string() +
                                (spelled_alike ? "" : " (the same file through a link)") +
                                "; writing it would destroy the input: choose another output",
                            output.string(), SourcePos{});
        break;
    }
    return diagnostics;
}

}  // namespace esi
