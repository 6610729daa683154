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

double hashUnit(uint32_t a, uint32_t b, uint32_t c) {
    uint32_t h =
        a * 0x9E3779B1u ^ (b + 0x7F4A7C15u) * 0x85EBCA77u ^ (c + 0x165667B1u) * 0xC2B2AE3Du;
    h ^= h >> 16;
    h *= 0x7FEB352Du;
    h ^= h >> 15;
    h *= 0x846CA68Bu;
    h ^= h >> 16;
    return double(h) / 4294967296.0;
}

}  // namespace quaternia
