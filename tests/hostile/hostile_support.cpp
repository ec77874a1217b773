#include "hostile/hostile_support.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "core/sanitizers.hpp"
#include "support/test_support.hpp"

namespace esi::test {

namespace {

ChildResult run_child_here(const std::vector<std::string>& argv, const ChildOptions& options) {
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
        if (!options.stdin_file.empty()) {
            const int fd = open(options.stdin_file.c_str(), O_RDONLY);
            if (fd < 0) _exit(126);
            dup2(fd, 0);
        } else {
            dup2(in_pipe[0], 0);
        }
        dup2(out_pipe[1], 1);
        dup2(err_pipe[1], 2);
        if (options.file_size_limit) {
            const rlimit limit{*options.file_size_limit, *options.file_size_limit};
            setrlimit(RLIMIT_FSIZE, &limit);
        }
        if (options.address_space_limit) {
            const rlimit limit{*options.address_space_limit, *options.address_space_limit};
            setrlimit(RLIMIT_AS, &limit);
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

// ---- the spawner --------------------------------------------------------------------------
// A child's peak RSS (wait4's ru_maxrss) includes the memory of the process it was forked from:
// fork copies the parent's page tables and exec records the old address space's peak. Forked
// from this test process after a memory-heavy test, every child would "use" that test's memory.
// So children are started by a small spawner process forked when the test binary starts, while
// it is still small; it runs each request and sends the result back over a socket.

void write_all(int fd, const std::string& data) {
    std::size_t done = 0;
    while (done < data.size()) {
        const ssize_t n = send(fd, data.data() + done, data.size() - done, MSG_NOSIGNAL);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) throw std::runtime_error("spawner: send failed");
        done += static_cast<std::size_t>(n);
    }
}

bool read_exactly(int fd, char* out, std::size_t size) {
    std::size_t done = 0;
    while (done < size) {
        const ssize_t n = read(fd, out + done, size - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        done += static_cast<std::size_t>(n);
    }
    return true;
}

void put_number(std::string& out, std::int64_t value) { out.append(reinterpret_cast<const char*>(&value), sizeof value); }
void put_text(std::string& out, const std::string& text) {
    put_number(out, static_cast<std::int64_t>(text.size()));
    out += text;
}

bool get_number(int fd, std::int64_t& value) { return read_exactly(fd, reinterpret_cast<char*>(&value), sizeof value); }
bool get_text(int fd, std::string& text) {
    std::int64_t size = 0;
    if (!get_number(fd, size) || size < 0) return false;
    text.resize(static_cast<std::size_t>(size));
    return read_exactly(fd, text.data(), text.size());
}

std::string encode_request(const std::vector<std::string>& argv, const ChildOptions& options) {
    std::string out;
    put_number(out, static_cast<std::int64_t>(argv.size()));
    for (const auto& a : argv) put_text(out, a);
    put_number(out, options.file_size_limit ? static_cast<std::int64_t>(*options.file_size_limit) : -1);
    put_number(out, options.address_space_limit ? static_cast<std::int64_t>(*options.address_space_limit) : -1);
    put_number(out, options.ignore_sigxfsz ? 1 : 0);
    put_number(out, options.kill_after ? options.kill_after->count() : -1);
    put_text(out, options.stdin_data);
    put_text(out, options.stdin_file);
    return out;
}

bool decode_request(int fd, std::vector<std::string>& argv, ChildOptions& options) {
    std::int64_t count = 0, limit = 0, address_space = 0, ignore = 0, kill_after = 0;
    if (!get_number(fd, count)) return false;
    argv.assign(static_cast<std::size_t>(count), {});
    for (auto& a : argv)
        if (!get_text(fd, a)) return false;
    if (!get_number(fd, limit) || !get_number(fd, address_space) || !get_number(fd, ignore) || !get_number(fd, kill_after))
        return false;
    if (!get_text(fd, options.stdin_data) || !get_text(fd, options.stdin_file)) return false;
    if (limit >= 0) options.file_size_limit = static_cast<std::uint64_t>(limit);
    if (address_space >= 0) options.address_space_limit = static_cast<std::uint64_t>(address_space);
    options.ignore_sigxfsz = ignore != 0;
    if (kill_after >= 0) options.kill_after = std::chrono::microseconds(kill_after);
    return true;
}

[[noreturn]] void serve(int fd) {
    for (;;) {
        std::vector<std::string> argv;
        ChildOptions options;
        if (!decode_request(fd, argv, options)) _exit(0);  // the test process has gone
        const ChildResult r = run_child_here(argv, options);
        std::string reply;
        put_number(reply, r.exit_code);
        put_number(reply, r.signal);
        put_number(reply, r.max_rss_kb);
        put_text(reply, r.out);
        put_text(reply, r.err);
        try {
            write_all(fd, reply);
        } catch (...) {
            _exit(0);
        }
    }
}

class Spawner {
public:
    Spawner() {
        int sockets[2];
        if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sockets) != 0) return;
        const pid_t pid = fork();
        if (pid < 0) {
            close(sockets[0]);
            close(sockets[1]);
            return;
        }
        if (pid == 0) {
            close(sockets[0]);
            serve(sockets[1]);
        }
        close(sockets[1]);
        fd_ = sockets[0];
    }

    // nullopt when the spawner is not available (then the caller forks itself).
    std::optional<ChildResult> run(const std::vector<std::string>& argv, const ChildOptions& options) {
        if (fd_ < 0) return std::nullopt;
        std::lock_guard<std::mutex> lock(mutex_);
        write_all(fd_, encode_request(argv, options));
        ChildResult r;
        std::int64_t exit_code = 0, signal_number = 0, rss = 0;
        if (!get_number(fd_, exit_code) || !get_number(fd_, signal_number) || !get_number(fd_, rss) || !get_text(fd_, r.out) ||
            !get_text(fd_, r.err))
            throw std::runtime_error("spawner: no reply");
        r.exit_code = static_cast<int>(exit_code);
        r.signal = static_cast<int>(signal_number);
        r.max_rss_kb = static_cast<long>(rss);
        return r;
    }

private:
    int fd_ = -1;
    std::mutex mutex_;
};

// Created while static objects are initialised, before any test runs.
Spawner& spawner() {
    static Spawner instance;
    return instance;
}
[[maybe_unused]] Spawner& started_at_startup = spawner();

}  // namespace

ChildResult run_child(const std::vector<std::string>& argv, const ChildOptions& options) {
    if (auto r = spawner().run(argv, options)) return *r;
    return run_child_here(argv, options);
}

int memory_scale() { return ESI_ADDRESS_SANITIZER ? 4 : 1; }

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

Listener::Listener() {
    fd_ = socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t length = sizeof address;
    if (fd_ < 0 || bind(fd_, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 || listen(fd_, 8) != 0 ||
        getsockname(fd_, reinterpret_cast<sockaddr*>(&address), &length) != 0)
        ADD_FAILURE() << "cannot listen on 127.0.0.1";
    port_ = ntohs(address.sin_port);
}

Listener::~Listener() { close(fd_); }

bool Listener::anyone_connected() const {
    const int client = accept(fd_, nullptr, nullptr);
    if (client >= 0) close(client);
    return client >= 0;
}

}  // namespace esi::test
