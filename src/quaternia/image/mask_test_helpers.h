// compareMasks for tests. Two empty masks compare as equal (IoU 1, nothing far), so a renderer
// that draws nothing, or a mask file that reads as empty, would pass any bound: every test
// comparison goes through here and fails first when a mask is empty.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "quaternia/image/mask_compare.h"

namespace quaternia::testing {

// compareMasks(a, b), with a test failure (naming `what`) where a or b has no inside pixel.
inline MaskComparison compareNonEmptyMasks(const Mask& a, const Mask& b,
                                           const std::string& what = "") {
    MaskComparison comparison = compareMasks(a, b);
    EXPECT_GT(comparison.countA, 0) << what << ": the first mask is empty";
    EXPECT_GT(comparison.countB, 0) << what << ": the second mask is empty";
    return comparison;
}

}  // namespace quaternia::testing
