#pragma once
// The registry behind esi/io/leftovers.hpp. A fixed table of slots holding paths in place, so
// that the signal handler reads them without allocating and a slot is never freed under it.

#include <signal.h>

#include <filesystem>

namespace esi::io_detail {

enum class LeftoverKind { file, directory };

// Registers `path` for as long as the object lives (or until release()). When every slot is taken
// the path is simply not registered: the normal error paths still remove it.
class LeftoverRegistration {
public:
    LeftoverRegistration() = default;
    LeftoverRegistration(const std::filesystem::path& path, LeftoverKind kind);
    ~LeftoverRegistration() { release(); }
    LeftoverRegistration(LeftoverRegistration&& other) noexcept : slot_(other.slot_) { other.slot_ = -1; }
    LeftoverRegistration& operator=(LeftoverRegistration&& other) noexcept;
    LeftoverRegistration(const LeftoverRegistration&) = delete;
    LeftoverRegistration& operator=(const LeftoverRegistration&) = delete;

    // The path no longer needs removing (renamed into place, removed, or kept on success).
    void release() noexcept;

private:
    int slot_ = -1;
};

// Holds back SIGINT, SIGTERM and SIGHUP for its lifetime (on this thread), so that creating a
// file or directory and registering it happen as one step: a signal in between would leave
// something the handler does not know of. Only around calls that return at once.
class DeferredSignals {
public:
    DeferredSignals();
    ~DeferredSignals();
    DeferredSignals(const DeferredSignals&) = delete;
    DeferredSignals& operator=(const DeferredSignals&) = delete;

private:
    sigset_t previous_;
};

}  // namespace esi::io_detail
