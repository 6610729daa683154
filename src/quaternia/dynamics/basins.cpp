// Basins of attraction (seed paper eqs. 2.4-2.5). Every attracting cycle of a polynomial
// attracts a critical point (Fatou), so the cycles are found from the critical orbits
// (connectedness.h); each pixel's orbit is then followed until it escapes (A(infinity)), comes
// within a small capture radius of a point of an attracting cycle, or runs out of iterations.
#include "quaternia/dynamics/basins.h"

#include <algorithm>
#include <cmath>

#include "quaternia/dynamics/connectedness.h"
#include "quaternia/util/parallel.h"

namespace quaternia {
namespace {

struct AttractingCycle {
    std::vector<Complex> points;
};

std::vector<AttractingCycle> attractingCycles(const ComplexPolynomial& p, int maxIterations) {
    std::vector<AttractingCycle> cycles;
    for (const CriticalOrbit& critical : connectedness(p, maxIterations).criticalOrbits) {
        const OrbitResult& orbit = critical.orbit;
        Stability stability = orbit.governingClass.stability;
        if (!orbit.cycle ||
            (stability != Stability::Attracting && stability != Stability::Superattracting)) {
            continue;
        }
        AttractingCycle cycle;
        for (const Quaternion& w : orbit.cycle->points)
            cycle.points.push_back({w.w, w.x});
        // Two critical points can share a cycle (e.g. an odd polynomial's): keep it once.
        bool known = std::any_of(cycles.begin(), cycles.end(), [&](const AttractingCycle& c) {
            return std::any_of(c.points.begin(), c.points.end(), [&](Complex w) {
                return std::abs(w - cycle.points[0]) <= 1e-6 * std::max(1.0, std::abs(w));
            });
        });
        if (!known) cycles.push_back(std::move(cycle));
    }
    return cycles;
}

// Within this distance of an attracting cycle point an orbit is taken as converging to it: a
// small fraction of the scale, and well below the gaps between distinct cycle points.
double captureRadius(const std::vector<AttractingCycle>& cycles, double escapeRadius) {
    double radius = 1e-3 * std::max(1.0, escapeRadius);
    std::vector<Complex> all;
    for (const AttractingCycle& cycle : cycles)
        all.insert(all.end(), cycle.points.begin(), cycle.points.end());
    for (std::size_t i = 0; i < all.size(); ++i) {
        for (std::size_t j = i + 1; j < all.size(); ++j)
            radius = std::min(radius, 0.25 * std::abs(all[i] - all[j]));
    }
    return radius;
}

Rgba hsv(double hue, double saturation, double value) {
    auto channel = [&](double n) {
        double k = std::fmod(n + hue * 6, 6.0);
        return float(value - value * saturation * std::clamp(std::min(k, 4 - k), 0.0, 1.0));
    };
    return {channel(5), channel(3), channel(1), 1};
}

struct BasinMap {
    const ComplexPolynomial& p;
    std::vector<AttractingCycle> cycles;
    double escapeRadius, capture;
    int maxIterations;

    // Each attracting cycle a hue (golden-ratio spaced), each immediate basin (the cycle point
    // approached at multiples of the period) a lighter or darker shade of it; infinity grey,
    // darkest where orbits escape fastest; undecided points mid grey.
    // The colour of z's fate, and its label (BasinImage::labels).
    std::pair<Rgba, int32_t> colourOf(Complex z) const {
        for (int k = 0; k <= maxIterations; ++k) {
            if (std::abs(z) > escapeRadius) {
                float grey = float(0.25 * (1 - std::exp(-k / 16.0)));
                return {{grey, grey, grey, 1}, BasinImage::kEscapes};
            }
            for (std::size_t c = 0; c < cycles.size(); ++c) {
                const std::vector<Complex>& points = cycles[c].points;
                const int n = int(points.size());
                for (int j = 0; j < n; ++j) {
                    if (std::abs(z - points[j]) >= capture) continue;
                    int phase = ((j - k) % n + n) % n;
                    double hue = std::fmod(0.6 + 0.618033988749895 * double(c), 1.0);
                    return {hsv(hue, 0.7, 0.95 - 0.45 * phase / n), int32_t(c)};
                }
            }
            z = p.evaluate(z);
        }
        return {{0.5f, 0.5f, 0.5f, 1}, BasinImage::kUndecided};
    }
};

}  // namespace

BasinImage renderBasins(const ComplexPolynomial& p, const PlaneView& view,
                        const BasinOptions& options) {
    BasinMap map{p, attractingCycles(p, options.maxIterations),
                 quaternionPolynomial(p).escapeRadius(), 0, options.maxIterations};
    map.capture = captureRadius(map.cycles, map.escapeRadius);
    BasinImage result;
    result.image = Image(view.pixelWidth, view.pixelHeight);
    result.labels.assign(size_t(view.pixelWidth) * size_t(view.pixelHeight), 0);
    result.attractingCycles = int(map.cycles.size());
    for (const AttractingCycle& cycle : map.cycles)
        result.periods.push_back(int(cycle.points.size()));
    const int samples = std::max(1, options.samples);
    ParallelOptions parallel;
    parallel.threads = options.threads;
    parallel.cancel = options.cancel;
    result.completed =
        parallelForTiles(view.pixelWidth, view.pixelHeight, parallel, [&](const Tile& tile, int) {
            for (int y = tile.y0; y < tile.y1; ++y) {
                for (int x = tile.x0; x < tile.x1; ++x) {
                    Rgba sum;
                    for (int s = 0; s < samples; ++s) {
                        // A rank-1 lattice: the pixel centre for one sample.
                        double u = (s + 0.5) / samples;
                        double v = std::fmod(0.5 + s * 0.618033988749895, 1.0);
                        const auto [c, label] = map.colourOf(view.pointAt(x + u, y + v));
                        if (s == 0)
                            result.labels[size_t(y) * size_t(view.pixelWidth) + size_t(x)] = label;
                        sum = {sum.r + c.r, sum.g + c.g, sum.b + c.b, sum.a + c.a};
                    }
                    float inverse = 1.0f / float(samples);
                    result.image.at(x, y) = {sum.r * inverse, sum.g * inverse, sum.b * inverse,
                                             sum.a * inverse};
                }
            }
        });
    return result;
}

}  // namespace quaternia
