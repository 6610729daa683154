#include "quaternia/render/sample_pattern.h"

#include <cmath>
#include <cstdint>

namespace quaternia {
namespace {

// A small integer hash (Wang/Jenkins style) for reproducible jitter.
uint32_t hashPixel(uint32_t a) {
    a = (a ^ 61u) ^ (a >> 16);
    a *= 9u;
    a ^= a >> 4;
    a *= 0x27d4eb2du;
    a ^= a >> 15;
    return a;
}

double unitFromHash(uint32_t h) {
    return (h >> 8) * (1.0 / 16777216.0);
}

}  // namespace

std::array<double, 2> samplePosition(int k, int n, int px, int py) {
    if (n == 1) return {0.5, 0.5};
    int columns = int(std::ceil(std::sqrt(double(n))));
    int rows = (n + columns - 1) / columns;
    uint32_t h =
        hashPixel(uint32_t(px) * 73856093u ^ uint32_t(py) * 19349663u ^ uint32_t(k) * 83492791u);
    double jx = unitFromHash(h), jy = unitFromHash(hashPixel(h));
    return {(k % columns + jx) / columns, (k / columns + jy) / rows};
}

std::array<double, 2> lensSample(int k, int px, int py) {
    // R2: k / plastic and k / plastic^2, plastic^3 = plastic + 1 (Roberts 2018).
    constexpr double a1 = 0.7548776662466927, a2 = 0.5698402909980532;
    const uint32_t h = hashPixel(uint32_t(px) * 2654435761u ^ uint32_t(py) * 40503u ^ 0x9e3779b9u);
    const double ox = unitFromHash(h), oy = unitFromHash(hashPixel(h));
    auto wrap = [](double v) { return v - std::floor(v); };
    return {wrap(ox + a1 * k), wrap(oy + a2 * k)};
}

}  // namespace quaternia
