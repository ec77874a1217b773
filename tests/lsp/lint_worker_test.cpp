// The lint worker on its own: the newest version wins, a closed document publishes nothing, and
// a burst of changes within the debounce time costs one lint. The instrumented tree also checks
// that a document closed while the worker waits out its debounce leaves nothing dangling.

#include <gtest/gtest.h>

#include <condition_variable>
#include <mutex>
#include <vector>

#include "esi/lsp/lint_worker.hpp"
#include "support/test_support.hpp"

namespace {

using namespace std::chrono_literals;

struct Published {
    std::mutex mutex;
    std::condition_variable changed;
    std::vector<std::pair<std::string, std::int64_t>> results;  // uri, version
    bool wait_for(std::size_t n, std::chrono::milliseconds timeout) {
        std::unique_lock lock(mutex);
        return changed.wait_for(lock, timeout, [&] { return results.size() >= n; });
    }
    // The worker's publish callback: records each result (it runs on the worker thread).
    esi::lsp::LintWorker::Publish recorder() {
        return [this](esi::lsp::LintResult result) {
            const std::lock_guard lock(mutex);
            results.emplace_back(result.uri, result.version);
            changed.notify_all();
        };
    }
};

esi::lsp::LintRequest request(const std::string& uri, std::int64_t version) {
    static const auto text =
        std::make_shared<const std::string>(esi::test::read_text(esi::test::source_dir() / "samples/esi/example-digital-io.xml"));
    return {uri, "", version, text};
}

TEST(LspLintWorker, OnlyTheNewestVersionIsPublished) {
    Published published;
    {
        esi::lsp::LintWorker worker(0ms, published.recorder());
        for (std::int64_t version = 1; version <= 20; ++version) worker.submit(request("file:///a.xml", version));
        ASSERT_TRUE(published.wait_for(1, 20s));
        std::this_thread::sleep_for(100ms);  // time for a wrongly published older version to show
    }
    // Whatever ran meanwhile, the last result published is version 20 and none came after it.
    ASSERT_FALSE(published.results.empty());
    EXPECT_EQ(published.results.back(), (std::pair<std::string, std::int64_t>{"file:///a.xml", 20}));
    for (std::size_t i = 1; i < published.results.size(); ++i) EXPECT_LT(published.results[i - 1].second, published.results[i].second);
}

TEST(LspLintWorker, ForgottenDocumentPublishesNothingAndBurstsAreDebounced) {
    Published published;
    {
        esi::lsp::LintWorker worker(200ms, published.recorder());
        worker.submit(request("file:///closed.xml", 1));
        worker.forget("file:///closed.xml");
        for (std::int64_t version = 1; version <= 5; ++version) worker.submit(request("file:///b.xml", version));
        ASSERT_TRUE(published.wait_for(1, 20s));
        std::this_thread::sleep_for(300ms);
    }
    ASSERT_EQ(published.results.size(), 1u);
    EXPECT_EQ(published.results[0], (std::pair<std::string, std::int64_t>{"file:///b.xml", 5}));
}

// The worker waits until the debounce deadline of the document due next. Closing that document
// erases its entry meanwhile; the next submission wakes the worker, which must not read the
// erased entry's deadline (it did once, seen by AddressSanitizer about once in 30 runs).
TEST(LspLintWorker, ClosingTheDocumentTheWorkerWaitsForLeavesItWaitingOnNothingFreed) {
    Published published;
    {
        esi::lsp::LintWorker worker(10s, published.recorder());
        for (int round = 0; round < 10; ++round) {
            worker.submit(request("file:///closed.xml", round));
            std::this_thread::sleep_for(20ms);  // the worker is now waiting for its deadline
            worker.forget("file:///closed.xml");
            worker.submit(request("file:///other.xml", round));  // wakes the worker
            std::this_thread::sleep_for(5ms);
        }
    }
    // Nothing came due within the test: nothing is published, and the closed document never is.
    EXPECT_TRUE(published.results.empty());
}

}  // namespace
