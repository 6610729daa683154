// Comparing two silhouettes with the measures of the reference set
// (tests/data/reference and its README): intersection over union, and the pixels of
// each mask that lie more than one pixel from the other. A renderer that is right up to a
// sub-pixel offset of the surface has a high IoU and almost no far pixels; an error in camera,
// slice or iteration shows up as hundreds of far pixels.
#pragma once

#include <cstdint>
#include <string>

#include "quaternia/image/image.h"

namespace quaternia {

struct MaskComparison {
    double iou = 1;  // intersection / union; 1 when both masks are empty
    int64_t countA = 0, countB = 0, intersection = 0, unionCount = 0;
    // Pixels of A outside B dilated by one pixel in all 8 directions, and the other way round.
    int64_t farFromB = 0;
    int64_t farFromA = 0;
};

// Throws std::invalid_argument when the masks differ in size (or a mask's `inside` does not
// hold width * height values).
MaskComparison compareMasks(const Mask& a, const Mask& b);

// "iou 0.9912 (A 1234, B 1240, both 1230, far from B 2, far from A 7)", for test messages.
std::string describe(const MaskComparison& comparison);

// To look at a failure: white where both masks are inside, red where only A is, blue where
// only B is, black where neither; opaque. Throws as compareMasks.
Image differenceImage(const Mask& a, const Mask& b);

}  // namespace quaternia
