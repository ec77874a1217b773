#include "esi/io/atomic_write.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <random>

namespace esi {

namespace {

std::string error_text() { return std::strerror(errno); }

// Writes content to a new temporary file in the target's directory, fsyncs it, returns its path.
bool write_temporary(const std::filesystem::path& target, const std::string& content, std::filesystem::path& temporary,
                     std::string& error) {
    static thread_local std::mt19937_64 random{std::random_device{}()};
    const std::filesystem::path dir = target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
    for (int attempt = 0; attempt < 16; ++attempt) {
        temporary = dir / ("." + target.filename().string() + ".tmp" + std::to_string(random() % 1000000000));
        const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
        if (fd < 0) {
            if (errno == EEXIST) continue;
            error = error_text();
            return false;
        }
        const char* data = content.data();
        std::size_t left = content.size();
        while (left > 0) {
            const ssize_t n = ::write(fd, data, left);
            if (n < 0) {
                if (errno == EINTR) continue;
                error = error_text();
                ::close(fd);
                ::unlink(temporary.c_str());
                return false;
            }
            data += n;
            left -= static_cast<std::size_t>(n);
        }
        if (::fsync(fd) != 0 || ::close(fd) != 0) {
            error = error_text();
            ::unlink(temporary.c_str());
            return false;
        }
        return true;
    }
    error = "cannot create a temporary file";
    return false;
}

}  // namespace

Diagnostics write_files_atomically(const std::vector<OutputFile>& files) {
    Diagnostics diagnostics;
    std::vector<std::filesystem::path> temporaries;
    for (const auto& file : files) {
        std::error_code ec;
        if (file.path.has_parent_path()) std::filesystem::create_directories(file.path.parent_path(), ec);
        if (ec) {
            diagnostics.emplace(Severity::error, "io-error", "cannot create directory: " + ec.message(), file.path.parent_path().string(), {});
            break;
        }
        std::filesystem::path temporary;
        std::string error;
        if (!write_temporary(file.path, file.content, temporary, error)) {
            diagnostics.emplace(Severity::error, "io-error", "cannot write: " + error, file.path.string(), {});
            break;
        }
        temporaries.push_back(temporary);
    }
    if (diagnostics.has_errors()) {
        for (const auto& t : temporaries) ::unlink(t.c_str());
        return diagnostics;
    }
    // Every file is complete on disk; now move them into place.
    for (std::size_t i = 0; i < files.size(); ++i) {
        if (std::rename(temporaries[i].c_str(), files[i].path.c_str()) != 0) {
            diagnostics.emplace(Severity::error, "io-error", "cannot replace file: " + error_text(), files[i].path.string(), {});
            for (std::size_t k = i; k < temporaries.size(); ++k) ::unlink(temporaries[k].c_str());
            break;
        }
    }
    return diagnostics;
}

Diagnostics write_file_atomically(const std::filesystem::path& path, const std::string& content) {
    return write_files_atomically({OutputFile{path, content}});
}

}  // namespace esi
