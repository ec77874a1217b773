#pragma once
// Lints documents on a thread of its own so that the server keeps answering while a 40 MB
// catalogue is linted. Debounced: a document is linted once its text has been still for the
// debounce time, so a burst of keystrokes costs one lint. Latest version wins: a submission
// replaces the document's waiting one, and a result whose document has changed (or closed) while
// it was linted is dropped, never published over a newer one.

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "esi/lsp/lint_document.hpp"

namespace esi::lsp {

struct LintRequest {
    std::string uri;
    std::string path;  // for the config lookup; empty for a buffer without a file
    std::int64_t version = 0;
    std::shared_ptr<const std::string> text;
};

struct LintResult {
    std::string uri;
    std::int64_t version = 0;
    std::shared_ptr<const std::string> text;  // the text linted (the findings' positions refer to it)
    DocumentLint lint;
};

class LintWorker {
public:
    // `publish` runs on the worker thread, for results still current when the lint finished.
    using Publish = std::function<void(LintResult)>;
    LintWorker(std::chrono::milliseconds debounce, Publish publish);
    ~LintWorker();  // stops the thread; a lint in progress finishes first, its result dropped
    LintWorker(const LintWorker&) = delete;
    LintWorker& operator=(const LintWorker&) = delete;

    void submit(LintRequest request);
    // The document closed: its waiting lint is dropped, a running one's result too.
    void forget(const std::string& uri);

private:
    struct Pending {
        LintRequest request;
        std::chrono::steady_clock::time_point due;
    };
    void run();
    // Whether `version` is still the newest the worker has seen for the document.
    bool current(const std::string& uri, std::int64_t version) const;

    std::chrono::milliseconds debounce_;
    Publish publish_;
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::map<std::string, Pending> pending_;
    std::map<std::string, std::int64_t> latest_;  // per open document: the newest version submitted
    bool stopping_ = false;
    std::thread thread_;
};

}  // namespace esi::lsp
