// Where in a pixel each sample looks, and where on the lens: reproducible from the pixel and the
// sample's index alone, so that every engine, tile size, thread count and frame range takes the
// same rays.
#pragma once

#include <array>
#include <cstdint>

namespace quaternia {

// Sample k of n within a pixel, in [0, 1)^2: a stratified grid jittered by a hash of the pixel,
// so images are reproducible; the single sample is the pixel centre.
std::array<double, 2> samplePosition(int k, int n, int px, int py);
// The lens point (of the unit square, Camera::generateRay) of sample k of n of pixel (px, py)
// for depth of field: a rank-1 lattice in k (the plastic number's R2 sequence, even over any
// prefix of the samples) turned by an offset hashed from the pixel, so that neighbouring pixels
// do not repeat the same lens points (which would show as a ghost image instead of blur).
std::array<double, 2> lensSample(int k, int px, int py);
// A hash of three integers to [0, 1) (Wang-style integer mixing), for directions drawn per
// sample (glossy lobes, the environment's shadow rays): the same for the same key in every run.
double hashUnit(uint32_t a, uint32_t b, uint32_t c);

}  // namespace quaternia
