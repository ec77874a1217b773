#include "lint/file_queue.hpp"

#include <algorithm>
#include <numeric>

namespace esi {

FileQueue::FileQueue(std::vector<std::uintmax_t> sizes, std::uintmax_t budget) : sizes_(std::move(sizes)), budget_(budget) {
    const std::uintmax_t largest = sizes_.empty() ? 0 : *std::max_element(sizes_.begin(), sizes_.end());
    large_limit_ = std::max<std::uintmax_t>(largest / 4, std::uintmax_t{1} << 20);
    std::vector<std::size_t> order(sizes_.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    // Largest first; equal sizes keep their input order.
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return sizes_[a] > sizes_[b]; });
    order_.assign(order.begin(), order.end());
}

std::uintmax_t FileQueue::default_budget(const std::vector<std::uintmax_t>& sizes) {
    const std::uintmax_t largest = sizes.empty() ? 0 : *std::max_element(sizes.begin(), sizes.end());
    return std::max<std::uintmax_t>(largest + largest / 4, std::uintmax_t{1} << 20);
}

bool FileQueue::fits(std::size_t file) const { return in_flight_ == 0 || in_flight_ + sizes_[file] <= budget_; }

std::optional<std::size_t> FileQueue::take(unsigned worker) {
    std::unique_lock lock(mutex_);
    for (;;) {
        if (order_.empty()) return std::nullopt;
        std::optional<std::size_t> file;
        if (worker == 0 && fits(order_.front())) {
            file = order_.front();
            order_.pop_front();
        } else if (worker != 0 && large(order_.back())) {
            return std::nullopt;  // only large files are left: worker 0 lints them
        } else if (fits(order_.back())) {
            file = order_.back();
            order_.pop_back();
        }
        if (file) {
            in_flight_ += sizes_[*file];
            return file;
        }
        finished_.wait(lock);
    }
}

void FileQueue::done(std::size_t file) {
    {
        const std::lock_guard lock(mutex_);
        in_flight_ -= sizes_[file];
    }
    finished_.notify_all();
}

}  // namespace esi
