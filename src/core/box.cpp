// SPDX-License-Identifier: Apache-2.0
#include "core/box.hpp"

namespace rays {

const char* box_problem(const Box& box) {
    // Written so that NaN fails every test.
    if (!(box.w > 0.0) || !(box.h > 0.0)) return "the box's width and height must be above 0";
    if (!(box.x >= 0.0) || !(box.y >= 0.0) || !(box.x + box.w <= kFrameSize) || !(box.y + box.h <= kFrameSize))
        return "the box must lie inside the 128x128 processing frame: x and y at least 0, x + w and y + h at most 128";
    return nullptr;
}

}  // namespace rays
