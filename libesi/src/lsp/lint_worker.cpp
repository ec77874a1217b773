#include "esi/lsp/lint_worker.hpp"

#include <algorithm>

namespace esi::lsp {

LintWorker::LintWorker(std::chrono::milliseconds debounce, Publish publish)
    : debounce_(debounce), publish_(std::move(publish)), thread_([this] { run(); }) {}

LintWorker::~LintWorker() {
    {
        const std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    thread_.join();
}

void LintWorker::submit(LintRequest request) {
    {
        const std::lock_guard lock(mutex_);
        latest_[request.uri] = request.version;
        const std::string uri = request.uri;
        pending_.insert_or_assign(uri, Pending{std::move(request), std::chrono::steady_clock::now() + debounce_});
    }
    wake_.notify_all();
}

void LintWorker::forget(const std::string& uri) {
    const std::lock_guard lock(mutex_);
    pending_.erase(uri);
    latest_.erase(uri);
}

bool LintWorker::current(const std::string& uri, std::int64_t version) const {
    const auto it = latest_.find(uri);
    return it != latest_.end() && it->second == version && !pending_.count(uri);
}

void LintWorker::run() {
    std::unique_lock lock(mutex_);
    for (;;) {
        if (stopping_) return;
        if (pending_.empty()) {
            wake_.wait(lock);
            continue;
        }
        // The document whose text has been still the longest.
        const auto next = std::min_element(pending_.begin(), pending_.end(),
                                           [](const auto& a, const auto& b) { return a.second.due < b.second.due; });
        if (next->second.due > std::chrono::steady_clock::now()) {
            // A copy: wait_until reads the deadline again after waking, and by then a submission
            // or a close may have replaced or erased the entry it would otherwise refer to.
            const auto due = next->second.due;
            wake_.wait_until(lock, due);
            continue;
        }
        LintRequest request = std::move(next->second.request);
        pending_.erase(next);
        lock.unlock();
        LintResult result{request.uri, request.version, request.text, lint_document(*request.text, request.path)};
        lock.lock();
        if (stopping_) return;
        if (!current(result.uri, result.version)) continue;  // changed or closed meanwhile
        // Published under the lock, so a close or change cannot slip between check and publish.
        publish_(std::move(result));
    }
}

}  // namespace esi::lsp
