// Basins of attraction A_c(z) of a complex polynomial (seed paper eq. 2.4-2.5): which attracting
// cycle, or infinity, each point's orbit converges to, and into which immediate basin (the
// cycle point it approaches at multiples of the period).
#pragma once

#include <atomic>
#include <vector>

#include "quaternia/algebra/complex_polynomial.h"
#include "quaternia/image/image.h"
#include "quaternia/image/plane_view.h"

namespace quaternia {

struct BasinOptions {
    int maxIterations = 500;
    int samples = 1;  // per pixel, for anti-aliasing
    int threads = 0;
    const std::atomic<bool>* cancel = nullptr;
};

struct BasinImage {
    Image image;  // each attracting cycle a hue, its immediate basins shades of it; infinity dark
    // Per pixel, row-major, of the pixel's first sample: the index of the attracting cycle whose
    // basin holds it (into periods), kEscapes, or kUndecided.
    static constexpr int32_t kEscapes = -1, kUndecided = -2;
    std::vector<int32_t> labels;
    int attractingCycles = 0;  // finite attracting cycles found
    std::vector<int> periods;  // of each attracting cycle
    bool completed = true;
};

// Colours every pixel of the view by the basin its centre (and sub-samples) falls into.
BasinImage renderBasins(const ComplexPolynomial& p, const PlaneView& view,
                        const BasinOptions& options);

}  // namespace quaternia
