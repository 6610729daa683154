// The brute-force silhouette of POV-Ray's hypercomplex (bicomplex) julia_fractal: every pixel's
// centre ray is sampled with a fixed step inside the bounding sphere, and each sample is tested
// by iterating z^power + c in the duplex form (a = (x - w) + (y + z) i, b = (x + w) + (y - z) i,
// on which the product acts component by component, |q|^2 = (|a|^2 + |b|^2) / 2). Only the
// camera comes from the library; nothing of Quaternia's set or marcher is used. Shared by
// quaternia_bicomplex_brute (bench/bicomplex_brute.cpp) and the tests of the renderers against
// it (render/bicomplex_brute_test.cpp).
#pragma once

#include <cstdint>
#include <vector>

#include "quaternia/render/camera.h"

namespace quaternia::bench {

struct BicomplexBrute {
    double c[4] = {0, 0, 0, 0};
    int power = 2;
    int iterations = 20;
    double bailout = 4;                 // POV-Ray's hypercomplex: Exit_Value 16
    double radius = 4;                  // its bounding sphere
    double slice[5] = {0, 0, 0, 1, 0};  // normal (x, y, z, w) and distance
    double step = 0.001;
};

// 255 where some sample of the pixel's centre ray is in the set, 0 elsewhere, row by row.
// Throws std::invalid_argument for a slice normal without w.
std::vector<uint8_t> bicomplexBruteMask(const BicomplexBrute& set, const Camera& camera, int width,
                                        int height, int threads = 0);

}  // namespace quaternia::bench
