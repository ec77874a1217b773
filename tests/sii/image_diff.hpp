#pragma once
// Field-by-field differences between two decoded SII images, with string indices resolved to
// their text (indices legitimately differ between tools). Used to compare the images vendor
// tools wrote with the ones built from the same ESI.

#include <string>
#include <vector>

#include "esi/sii/image.hpp"

namespace esi::test {

struct ImageDifference {
    std::string field;  // "header word 0x07", "General.coe_details", "RxPDO 0x1600.flags", "category 42"
    std::string built;  // value in the first image ("-" when absent)
    std::string real;   // value in the second image
};

std::vector<ImageDifference> diff_images(const sii::Image& built, const sii::Image& real);

}  // namespace esi::test
