#include "lsp/lsp_client.hpp"

#include <csignal>
#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>

#include "support/test_support.hpp"

extern char** environ;

namespace esi::test {

using nlohmann::json;

LspClient::LspClient(std::vector<std::string> extra_args) {
    std::signal(SIGPIPE, SIG_IGN);  // writing to a server that has gone is a test failure, not a crash
    int in_pipe[2];
    int out_pipe[2];
    if (pipe(in_pipe) != 0 || pipe(out_pipe) != 0) throw std::runtime_error("pipe");
    std::vector<std::string> argv_strings{tool("esi-lsp").string()};
    argv_strings.insert(argv_strings.end(), extra_args.begin(), extra_args.end());
    std::vector<char*> argv;
    for (auto& s : argv_strings) argv.push_back(s.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, in_pipe[0], 0);
    posix_spawn_file_actions_adddup2(&actions, out_pipe[1], 1);
    for (int fd : {in_pipe[0], in_pipe[1], out_pipe[0], out_pipe[1]}) posix_spawn_file_actions_addclose(&actions, fd);
    pid_t pid = -1;
    const int rc = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    close(in_pipe[0]);
    close(out_pipe[1]);
    if (rc != 0) throw std::runtime_error("cannot start esi-lsp");
    pid_ = pid;
    to_server_ = in_pipe[1];
    from_server_ = out_pipe[0];
}

LspClient::~LspClient() {
    close_input();
    if (!exited_ && pid_ > 0) {
        if (!wait_exit(std::chrono::seconds(10))) kill(pid_, SIGKILL);
    }
    if (from_server_ >= 0) close(from_server_);
}

void LspClient::send_raw(const std::string& bytes) {
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t put = write(to_server_, bytes.data() + done, bytes.size() - done);
        if (put <= 0) throw std::runtime_error("the server's input is closed");
        done += static_cast<std::size_t>(put);
    }
}

void LspClient::send(const json& message) {
    const std::string body = message.dump();
    send_raw("Content-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body);
}

json LspClient::request(const std::string& method, json params, std::chrono::milliseconds timeout) {
    const int id = next_id_++;
    send({{"jsonrpc", "2.0"}, {"id", id}, {"method", method}, {"params", std::move(params)}});
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) throw std::runtime_error("no response to " + method);
        std::optional<json> message = receive(left);
        if (!message) throw std::runtime_error("no response to " + method);
        if (message->contains("id") && (*message)["id"] == id) return *message;
    }
}

void LspClient::notify(const std::string& method, json params) {
    send({{"jsonrpc", "2.0"}, {"method", method}, {"params", std::move(params)}});
}

std::optional<json> LspClient::receive(std::chrono::milliseconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    for (;;) {
        const std::size_t header_end = buffer_.find("\r\n\r\n");
        if (header_end != std::string::npos) {
            const std::size_t colon = buffer_.find(':');
            const std::size_t length = std::stoul(buffer_.substr(colon + 1, header_end - colon - 1));
            if (buffer_.size() >= header_end + 4 + length) {
                json message = json::parse(buffer_.substr(header_end + 4, length));
                buffer_.erase(0, header_end + 4 + length);
                return message;
            }
        }
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) return std::nullopt;
        pollfd fd{from_server_, POLLIN, 0};
        if (poll(&fd, 1, static_cast<int>(left.count())) <= 0) return std::nullopt;
        char chunk[65536];
        const ssize_t got = read(from_server_, chunk, sizeof chunk);
        if (got <= 0) return std::nullopt;
        buffer_.append(chunk, static_cast<std::size_t>(got));
    }
}

std::optional<json> LspClient::diagnostics_for(const std::string& uri, std::chrono::milliseconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) return std::nullopt;
        std::optional<json> message = receive(left);
        if (!message) return std::nullopt;
        if (message->value("method", "") == "textDocument/publishDiagnostics" && (*message)["params"]["uri"] == uri)
            return (*message)["params"];
    }
}

json LspClient::initialize() {
    json response = request("initialize", {{"processId", nullptr}, {"rootUri", nullptr}, {"capabilities", json::object()}});
    notify("initialized");
    return response.at("result");
}

void LspClient::open(const std::string& uri, const std::string& text, int version, const std::string& language) {
    notify("textDocument/didOpen",
           {{"textDocument", {{"uri", uri}, {"languageId", language}, {"version", version}, {"text", text}}}});
}

void LspClient::close_input() {
    if (to_server_ >= 0) close(to_server_);
    to_server_ = -1;
}

std::optional<int> LspClient::wait_exit(std::chrono::milliseconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    for (;;) {
        int status = 0;
        const pid_t done = waitpid(pid_, &status, WNOHANG);
        if (done == pid_) {
            exited_ = true;
            if (WIFEXITED(status)) return WEXITSTATUS(status);
            return -WTERMSIG(status);
        }
        if (std::chrono::steady_clock::now() > deadline) {
            kill(pid_, SIGKILL);
            waitpid(pid_, &status, 0);
            exited_ = true;
            return std::nullopt;
        }
        // Drain what the server writes meanwhile, so it never blocks on a full pipe.
        pollfd fd{from_server_, POLLIN, 0};
        if (poll(&fd, 1, 20) > 0) {
            char chunk[65536];
            const ssize_t got = read(from_server_, chunk, sizeof chunk);
            if (got > 0) buffer_.append(chunk, static_cast<std::size_t>(got));
        }
    }
}

std::string file_uri(const std::filesystem::path& path) {
    std::string uri = "file://";
    for (const char c : std::filesystem::absolute(path).lexically_normal().string()) {
        const auto u = static_cast<unsigned char>(c);
        if (std::isalnum(u) || c == '/' || c == '-' || c == '_' || c == '.' || c == '~') {
            uri += c;
        } else {
            static const char* hex = "0123456789ABCDEF";
            uri += '%';
            uri += hex[u >> 4];
            uri += hex[u & 15];
        }
    }
    return uri;
}

}  // namespace esi::test
