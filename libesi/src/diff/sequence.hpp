#pragma once
// Internal to the differ: aligning two ordered lists (PDO entries, InitCmds) whose order has a
// meaning. The longest common subsequence of their keys gives the elements that stayed in place;
// what is left over was moved, replaced, added or removed.

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace esi::diff_detail {

// Index pairs (i in a, j in b) of a longest common subsequence of keys, in order. Above a size
// where the quadratic table would be wasteful, matches greedily in order instead (still correct
// for lists that only differ at the end, which is what very long lists in real files do).
template <class Key>
std::vector<std::pair<std::size_t, std::size_t>> common_subsequence(const std::vector<Key>& a, const std::vector<Key>& b) {
    std::vector<std::pair<std::size_t, std::size_t>> out;
    const std::size_t n = a.size();
    const std::size_t m = b.size();
    // Common prefix and suffix need no table; real revisions mostly differ in a few places.
    std::size_t prefix = 0;
    while (prefix < n && prefix < m && a[prefix] == b[prefix]) ++prefix;
    std::size_t suffix = 0;
    while (suffix < n - prefix && suffix < m - prefix && a[n - 1 - suffix] == b[m - 1 - suffix]) ++suffix;
    for (std::size_t i = 0; i < prefix; ++i) out.emplace_back(i, i);

    const std::size_t rows = n - prefix - suffix;
    const std::size_t cols = m - prefix - suffix;
    constexpr std::size_t max_cells = std::size_t{4} << 20;
    if (rows > 0 && cols > 0) {
        if (rows * cols <= max_cells) {
            // table[i][j]: LCS length of a[prefix+i..] and b[prefix+j..]
            std::vector<std::uint32_t> table((rows + 1) * (cols + 1), 0);
            auto at = [&](std::size_t i, std::size_t j) -> std::uint32_t& { return table[i * (cols + 1) + j]; };
            for (std::size_t i = rows; i-- > 0;)
                for (std::size_t j = cols; j-- > 0;)
                    at(i, j) = a[prefix + i] == b[prefix + j] ? at(i + 1, j + 1) + 1 : std::max(at(i + 1, j), at(i, j + 1));
            std::size_t i = 0;
            std::size_t j = 0;
            while (i < rows && j < cols) {
                if (a[prefix + i] == b[prefix + j]) {
                    out.emplace_back(prefix + i, prefix + j);
                    ++i;
                    ++j;
                } else if (at(i + 1, j) >= at(i, j + 1)) {
                    ++i;
                } else {
                    ++j;
                }
            }
        } else {
            std::size_t j = 0;
            for (std::size_t i = 0; i < rows && j < cols; ++i) {
                std::size_t k = j;
                while (k < cols && !(a[prefix + i] == b[prefix + k])) ++k;
                if (k < cols) {
                    out.emplace_back(prefix + i, prefix + k);
                    j = k + 1;
                }
            }
        }
    }
    for (std::size_t s = suffix; s-- > 0;) out.emplace_back(n - 1 - s, m - 1 - s);
    return out;
}

// The result of aligning two ordered lists by key.
struct Alignment {
    // Pairs of elements that correspond: kept in place, moved, or replaced in place.
    struct Pair {
        std::size_t old_index;
        std::size_t new_index;
        enum class How { kept, moved, replaced } how;
    };
    std::vector<Pair> pairs;
    std::vector<std::size_t> removed;  // old indices without a counterpart
    std::vector<std::size_t> added;    // new indices without a counterpart
};

// Aligns two keyed lists: the LCS stays in place; an element whose key occurs among the leftovers
// on both sides moved (when `allow_move(key)`); leftovers between the same two anchors pair up in
// order as replacements (when `allow_replace`); the rest was added or removed.
template <class Key, class AllowMove>
Alignment align(const std::vector<Key>& a, const std::vector<Key>& b, AllowMove allow_move, bool allow_replace) {
    Alignment out;
    const auto kept = common_subsequence(a, b);
    std::vector<bool> old_used(a.size(), false);
    std::vector<bool> new_used(b.size(), false);
    for (const auto& [i, j] : kept) {
        out.pairs.push_back({i, j, Alignment::Pair::How::kept});
        old_used[i] = true;
        new_used[j] = true;
    }
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (old_used[i] || !allow_move(a[i])) continue;
        for (std::size_t j = 0; j < b.size(); ++j) {
            if (!new_used[j] && a[i] == b[j]) {
                out.pairs.push_back({i, j, Alignment::Pair::How::moved});
                old_used[i] = true;
                new_used[j] = true;
                break;
            }
        }
    }
    if (allow_replace) {
        // Walk the gaps between consecutive anchors (kept pairs) and pair leftovers in order.
        std::vector<std::pair<std::size_t, std::size_t>> anchors = kept;
        anchors.emplace_back(a.size(), b.size());
        std::size_t old_start = 0;
        std::size_t new_start = 0;
        for (const auto& [oi, nj] : anchors) {
            std::size_t j = new_start;
            for (std::size_t i = old_start; i < oi; ++i) {
                if (old_used[i]) continue;
                while (j < nj && new_used[j]) ++j;
                if (j >= nj) break;
                out.pairs.push_back({i, j, Alignment::Pair::How::replaced});
                old_used[i] = true;
                new_used[j] = true;
                ++j;
            }
            old_start = oi + 1;
            new_start = nj + 1;
        }
    }
    for (std::size_t i = 0; i < a.size(); ++i)
        if (!old_used[i]) out.removed.push_back(i);
    for (std::size_t j = 0; j < b.size(); ++j)
        if (!new_used[j]) out.added.push_back(j);
    return out;
}

}  // namespace esi::diff_detail
