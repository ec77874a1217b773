#pragma once
// A part of a text: [begin, end) in bytes.

#include <cstddef>

namespace esi {

struct TextSpan {
    std::size_t begin = 0;
    std::size_t end = 0;
};

}  // namespace esi
