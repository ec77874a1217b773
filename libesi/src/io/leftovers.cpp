#include "esi/io/leftovers.hpp"

#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <climits>
#include <cstring>

#include "io/leftover_registry.hpp"

namespace esi {

namespace io_detail {

namespace {

// 64 slots: a set written through O_TMPFILE has one named temporary at a time, plus the
// directories it created and its lock file; the named-file fallback (file systems without
// O_TMPFILE) registers up to 64 of its temporaries.
constexpr int slot_count = 64;

enum SlotState : int { free_slot = 0, filling = 1, armed = 2 };

struct Slot {
    std::atomic<int> state{free_slot};
    LeftoverKind kind = LeftoverKind::file;
    char path[PATH_MAX] = {};
};

Slot slots[slot_count];

static_assert(std::atomic<int>::is_always_lock_free, "the signal handler reads the slots' states");

}  // namespace

LeftoverRegistration::LeftoverRegistration(const std::filesystem::path& path, LeftoverKind kind) {
    const std::string& text = path.native();
    if (text.empty() || text.size() >= PATH_MAX) return;
    for (int i = 0; i < slot_count; ++i) {
        int expected = free_slot;
        if (!slots[i].state.compare_exchange_strong(expected, filling, std::memory_order_acquire)) continue;
        slots[i].kind = kind;
        std::memcpy(slots[i].path, text.c_str(), text.size() + 1);
        slots[i].state.store(armed, std::memory_order_release);
        slot_ = i;
        return;
    }
}

LeftoverRegistration& LeftoverRegistration::operator=(LeftoverRegistration&& other) noexcept {
    if (this != &other) {
        release();
        slot_ = other.slot_;
        other.slot_ = -1;
    }
    return *this;
}

void LeftoverRegistration::release() noexcept {
    if (slot_ < 0) return;
    slots[slot_].state.store(free_slot, std::memory_order_release);
    slot_ = -1;
}

DeferredSignals::DeferredSignals() {
    sigset_t deferred;
    sigemptyset(&deferred);
    for (const int signal_number : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&deferred, signal_number);
    pthread_sigmask(SIG_BLOCK, &deferred, &previous_);
}

DeferredSignals::~DeferredSignals() { pthread_sigmask(SIG_SETMASK, &previous_, nullptr); }

}  // namespace io_detail

void remove_registered_leftovers() noexcept {
    using io_detail::LeftoverKind;
    using io_detail::slots;
    for (auto& slot : slots)
        if (slot.state.load(std::memory_order_acquire) == io_detail::armed && slot.kind == LeftoverKind::file) ::unlink(slot.path);
    // Directories nest: remove what is empty, again while that makes progress (deepest first).
    for (bool progress = true; progress;) {
        progress = false;
        for (auto& slot : slots) {
            if (slot.state.load(std::memory_order_acquire) != io_detail::armed || slot.kind != LeftoverKind::directory) continue;
            if (::rmdir(slot.path) == 0) {
                slot.state.store(io_detail::free_slot, std::memory_order_release);
                progress = true;
            }
        }
    }
}

namespace {

extern "C" void remove_leftovers_and_die(int signal_number) {
    const int saved_errno = errno;
    remove_registered_leftovers();
    errno = saved_errno;
    // SA_RESETHAND restored the default action; the signal is blocked until this returns, then
    // ends the process with its usual status.
    ::raise(signal_number);
}

}  // namespace

void install_leftover_cleanup() {
    struct sigaction action {};
    action.sa_handler = remove_leftovers_and_die;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND;
    for (const int signal_number : {SIGINT, SIGTERM, SIGHUP}) {
        struct sigaction previous {};
        // A signal the program (or its parent, e.g. nohup) ignores stays ignored.
        if (::sigaction(signal_number, nullptr, &previous) == 0 && previous.sa_handler == SIG_IGN) continue;
        ::sigaction(signal_number, &action, nullptr);
    }
}

}  // namespace esi
