// The widest SIMD vector of any instruction-set target Quaternia is built for (AVX-512: 64
// bytes). Every lane function (the ray marcher's and the PNG encoder's) sizes and aligns its
// per-lane arrays by it, and checks with a static_assert that Highway's widest target fits.
#pragma once

#include <cstddef>

namespace quaternia {

inline constexpr size_t kMaxLaneBytes = 64;

}  // namespace quaternia
