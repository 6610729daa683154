// How wide the undecided band of a classes image is (0 outside, 128 undecided, 255 inside):
// at each undecided pixel, the shortest run of undecided pixels through it along the four
// directions (rows, columns, both diagonals), in pixels. Where the band is a strip between the
// decided classes this is its width; where it swells (tiny components of K that no cell could
// decide, the neighbourhood of a parabolic point) the run grows with it.
#pragma once

#include <cstdint>
#include <vector>

namespace quaternia {

struct UndecidedBand {
    int64_t pixels = 0;  // undecided pixels
    int median = 0, p99 = 0, max = 0;
};

UndecidedBand measureUndecidedBand(const std::vector<uint8_t>& classes, int width, int height);

}  // namespace quaternia
