// What the tests of the SIMD lanes share: batches of random points.
#pragma once

#include <random>

#include "quaternia/render/lanes/march_lanes.h"

namespace quaternia::testing {

// `count` points uniform in the cube [-radius, radius]^3, the same for the same seed.
inline PointBatch randomPoints(int count, double radius, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> coordinate(-radius, radius);
    PointBatch points;
    for (int i = 0; i < count; ++i)
        points.push(Point3d(coordinate(random), coordinate(random), coordinate(random)));
    return points;
}

}  // namespace quaternia::testing
