#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

#include "lint/file_queue.hpp"

namespace {

constexpr std::uintmax_t MiB = 1 << 20;

std::vector<std::size_t> drain(esi::FileQueue& queue, unsigned worker) {
    std::vector<std::size_t> taken;
    while (const auto file = queue.take(worker)) {
        taken.push_back(*file);
        queue.done(*file);
    }
    return taken;
}

}  // namespace

TEST(FileQueue, OneWorkerTakesTheLargestFilesFirst) {
    esi::FileQueue queue({10, 500, 100, 300, 100}, 1000);
    EXPECT_EQ(drain(queue, 0), (std::vector<std::size_t>{1, 3, 2, 4, 0}));  // equal sizes keep input order
}

TEST(FileQueue, OtherWorkersTakeSmallFilesOnlySmallestFirst) {
    // Large: over a quarter of the largest (4 MiB) and over 1 MiB.
    esi::FileQueue queue({MiB / 2, 4 * MiB, MiB, 2 * MiB, MiB + 1}, 5 * MiB);
    EXPECT_EQ(drain(queue, 1), (std::vector<std::size_t>{0, 2}));
    EXPECT_EQ(drain(queue, 0), (std::vector<std::size_t>{1, 3, 4}));
}

TEST(FileQueue, FilesUpToOneMebibyteAreNeverLeftToOneWorker) {
    esi::FileQueue queue({MiB, 10, MiB / 2}, esi::FileQueue::default_budget({MiB, 10, MiB / 2}));
    EXPECT_EQ(drain(queue, 1), (std::vector<std::size_t>{1, 2, 0}));
}

TEST(FileQueue, AFileThatDoesNotFitTheBudgetWaitsForTheOthers) {
    esi::FileQueue queue({600, 500, 50}, 1000);
    ASSERT_EQ(queue.take(0), 0u);  // 600 in flight
    ASSERT_EQ(queue.take(1), 2u);  // 50 fits next to it; 500 would not
    queue.done(0);
    EXPECT_EQ(queue.take(0), 1u);  // 50 + 500 fit
}

TEST(FileQueue, AFileLargerThanTheBudgetStillRunsAlone) {
    esi::FileQueue queue({5000, 10}, 1000);
    ASSERT_EQ(queue.take(0), 0u);
    queue.done(0);
    EXPECT_EQ(queue.take(0), 1u);
    queue.done(1);
    EXPECT_EQ(queue.take(0), std::nullopt);
}

TEST(FileQueue, BudgetIsOneAndAQuarterOfTheLargestFileAtLeastOneMebibyte) {
    EXPECT_EQ(esi::FileQueue::default_budget({100, 4'000'000, 5}), 5'000'000u);
    EXPECT_EQ(esi::FileQueue::default_budget({100, 200}), MiB);
    EXPECT_EQ(esi::FileQueue::default_budget({}), MiB);
}

TEST(FileQueue, WorkersTakeEveryFileOnceAndStayWithinTheBudget) {
    std::vector<std::uintmax_t> sizes;
    for (unsigned i = 0; i < 300; ++i) sizes.push_back((i * 7919u) % 997u * 1000u + (i % 50 == 0 ? 4 * MiB : 0u));
    const std::uintmax_t budget = esi::FileQueue::default_budget(sizes);
    const std::uintmax_t largest = *std::max_element(sizes.begin(), sizes.end());
    esi::FileQueue queue(sizes, budget);
    std::vector<std::atomic<int>> taken(sizes.size());
    std::atomic<std::uintmax_t> in_flight{0};
    std::atomic<bool> over_budget{false};
    std::atomic<bool> large_elsewhere{false};
    auto worker = [&](unsigned number) {
        while (const auto file = queue.take(number)) {
            const std::uintmax_t now = in_flight += sizes[*file];
            if (now > budget && now != sizes[*file]) over_budget = true;
            if (number != 0 && sizes[*file] > std::max<std::uintmax_t>(largest / 4, MiB)) large_elsewhere = true;
            ++taken[*file];
            std::this_thread::yield();
            in_flight -= sizes[*file];
            queue.done(*file);
        }
    };
    std::vector<std::thread> threads;
    for (unsigned t = 0; t < 4; ++t) threads.emplace_back(worker, t);
    for (auto& t : threads) t.join();
    for (std::size_t i = 0; i < sizes.size(); ++i) EXPECT_EQ(taken[i], 1) << i;
    EXPECT_FALSE(over_budget);
    EXPECT_FALSE(large_elsewhere);
}
