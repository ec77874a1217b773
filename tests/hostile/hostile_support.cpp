#include "hostile/hostile_support.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <stdexcept>
#include <thread>

#include "support/test_support.hpp"

namespace esi::test {

ChildResult run_child(const std::vector<std::string>& argv, const ChildOptions& options) {
    int in_pipe[2], out_pipe[2], err_pipe[2];
    if (pipe2(in_pipe, O_CLOEXEC) != 0 || pipe2(out_pipe, O_CLOEXEC) != 0 || pipe2(err_pipe, O_CLOEXEC) != 0)
        throw std::runtime_error("pipe failed");
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error("fork failed");
    if (pid == 0) {
        // Child: only async-signal-safe calls until exec.
        dup2(in_pipe[0], 0);
        dup2(out_pipe[1], 1);
        dup2(err_pipe[1], 2);
        if (options.file_size_limit) {
            const rlimit limit{*options.file_size_limit, *options.file_size_limit};
            setrlimit(RLIMIT_FSIZE, &limit);
        }
        signal(SIGXFSZ, options.ignore_sigxfsz ? SIG_IGN : SIG_DFL);
        execv(args[0], args.data());
        _exit(127);
    }
    close(in_pipe[0]);
    close(out_pipe[1]);
    close(err_pipe[1]);
    const auto started = std::chrono::steady_clock::now();
    ChildResult result;
    std::size_t written = 0;
    int in_fd = in_pipe[1];
    if (options.stdin_data.empty()) {
        close(in_fd);
        in_fd = -1;
    } else {
        fcntl(in_fd, F_SETFL, O_NONBLOCK);
    }
    bool out_open = true, err_open = true, killed = false;
    char buffer[65536];
    while (out_open || err_open || in_fd >= 0) {
        int timeout_ms = -1;
        if (options.kill_after && !killed) {
            const auto elapsed = std::chrono::steady_clock::now() - started;
            if (elapsed >= *options.kill_after) {
                kill(pid, SIGKILL);
                killed = true;
            } else {
                // poll has millisecond resolution; sub-millisecond delays are slept exactly.
                const auto left = std::chrono::duration_cast<std::chrono::microseconds>(*options.kill_after - elapsed);
                if (left < std::chrono::milliseconds(1)) {
                    std::this_thread::sleep_for(left);
                    kill(pid, SIGKILL);
                    killed = true;
                } else {
                    timeout_ms = static_cast<int>(left.count() / 1000);
                }
            }
        }
        std::vector<pollfd> fds;
        if (out_open) fds.push_back({out_pipe[0], POLLIN, 0});
        if (err_open) fds.push_back({err_pipe[0], POLLIN, 0});
        if (in_fd >= 0) fds.push_back({in_fd, POLLOUT, 0});
        const int ready = poll(fds.data(), fds.size(), timeout_ms);
        if (ready < 0 && errno != EINTR) break;
        for (const auto& p : fds) {
            if (p.fd == in_fd && (p.revents & (POLLOUT | POLLERR | POLLHUP))) {
                const ssize_t n = write(in_fd, options.stdin_data.data() + written, options.stdin_data.size() - written);
                if (n > 0) written += static_cast<std::size_t>(n);
                if (n < 0 || written == options.stdin_data.size()) {
                    close(in_fd);
                    in_fd = -1;
                }
            } else if (p.revents & (POLLIN | POLLHUP | POLLERR)) {
                const ssize_t n = read(p.fd, buffer, sizeof buffer);
                if (n <= 0) {
                    close(p.fd);
                    (p.fd == out_pipe[0] ? out_open : err_open) = false;
                } else {
                    (p.fd == out_pipe[0] ? result.out : result.err).append(buffer, static_cast<std::size_t>(n));
                }
            }
        }
    }
    int status = 0;
    rusage usage{};
    while (wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {
    }
    result.max_rss_kb = usage.ru_maxrss;
    if (WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) result.signal = WTERMSIG(status);
    return result;
}

int memory_scale() {
#if defined(__SANITIZE_ADDRESS__)
    return 4;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
    return 4;
#else
    return 1;
#endif
#else
    return 1;
#endif
}

bool permissions_apply() { return geteuid() != 0; }

std::map<std::string, std::string> snapshot(const std::filesystem::path& dir) {
    std::map<std::string, std::string> out;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(dir))
        if (entry.is_regular_file()) out[std::filesystem::relative(entry.path(), dir).string()] = read_text(entry.path());
    return out;
}

std::string sample_esi() { return read_text(source_dir() / "samples" / "esi" / "example-digital-io.xml"); }

std::string replace_once(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << "'" << from << "' is not in the text";
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

std::uint32_t line_of(const std::string& text, const std::string& needle) {
    const auto at = text.find(needle);
    if (at == std::string::npos) return 0;
    std::uint32_t line = 1;
    for (std::size_t i = 0; i < at; ++i)
        if (text[i] == '\n') ++line;
    return line;
}

}  // namespace esi::test
