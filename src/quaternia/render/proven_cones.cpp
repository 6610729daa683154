#include "quaternia/render/proven_cones.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "quaternia/render/march.h"

namespace quaternia {
namespace {

// A block's cone gives up, and splits, where a run of this many steps fails.
constexpr int64_t kShortestRun = 16;
// Blocks of this side end the splitting: their pixels' rays go on one by one.
constexpr int kSmallestBlock = 2;

}  // namespace

double proveCone(const Fractal& fractal, const Ray& ray, double t, double tFar, double unit,
                 double slope, int64_t shortest, ProofRuns& runs, int64_t& tests) {
    while (t < tFar) {
        const double end = std::min(t + double(runs.span) * unit, tFar);
        ++tests;
        if (fractal.excludesTube(ray, t, end, slope * end)) {
            t = end;
            runs.proved();
        } else {
            runs.failed();
            if (runs.span < shortest) break;
        }
    }
    return t;
}

ProvenCones::ProvenCones(const Fractal& fractal, const Camera& camera, double step)
    : fractal_(fractal),
      camera_(camera),
      step_(step),
      boundingRadius_(fractal.boundingRadius()),
      active_(fractal.provesEmptySegments() && !camera.thinLens() && step > 0) {}

int64_t ProvenCones::clear(const Tile& tile, std::vector<double>& provenUntil) const {
    const int width = tile.x1 - tile.x0;
    provenUntil.assign(size_t(width) * size_t(tile.y1 - tile.y0), 0.0);
    int64_t tests = 0;
    if (!active_) return tests;
    // On the image's grid, whatever the tile.
    for (int y = tile.y0 / kBlock * kBlock; y < tile.y1; y += kBlock)
        for (int x = tile.x0 / kBlock * kBlock; x < tile.x1; x += kBlock)
            clearBlock(x, y, kBlock, 0, tile, provenUntil, tests);
    return tests;
}

void ProvenCones::markPixels(int x0, int y0, int size, double until, const Tile& tile,
                             std::vector<double>& provenUntil) {
    const int width = tile.x1 - tile.x0;
    for (int py = std::max(y0, tile.y0); py < std::min(y0 + size, tile.y1); ++py)
        for (int px = std::max(x0, tile.x0); px < std::min(x0 + size, tile.x1); ++px)
            provenUntil[size_t(py - tile.y0) * size_t(width) + size_t(px - tile.x0)] = until;
}

void ProvenCones::clearBlock(int x0, int y0, int size, double from, const Tile& tile,
                             std::vector<double>& provenUntil, int64_t& tests) const {
    const Ray centre = camera_.generateRay(x0 + 0.5 * size, y0 + 0.5 * size);
    // No cone near a field of view of 180 degrees (Camera::coneSlope): those pixels keep what
    // their parent proved.
    const double rho = camera_.coneSlope(centre, x0, y0, size);
    if (!(rho > 0)) {
        markPixels(x0, y0, size, from, tile, provenUntil);
        return;
    }
    // No ray of the block meets the set's ball before the central ray meets the ball widened by
    // the cone's radius at the farthest point of the set.
    const double farthest = length(centre.origin) + boundingRadius_;
    const auto interval = intersectSphere(centre, boundingRadius_ + rho * farthest);
    double t = interval ? std::max(from, interval->tNear) : 0;
    const double tFar = interval ? interval->tFar : 0;
    ProofRuns runs;  // in steps, as a ray's
    t = proveCone(fractal_, centre, t, tFar, step_, rho, kShortestRun, runs, tests);
    const bool missed = !(t < tFar);
    if (missed || size <= kSmallestBlock) {
        markPixels(x0, y0, size, missed ? std::numeric_limits<double>::infinity() : t, tile,
                   provenUntil);
        return;
    }
    const int half = size / 2;
    for (int y = y0; y < y0 + size; y += half)
        for (int x = x0; x < x0 + size; x += half)
            if (x < tile.x1 && x + half > tile.x0 && y < tile.y1 && y + half > tile.y0)
                clearBlock(x, y, half, t, tile, provenUntil, tests);
}

}  // namespace quaternia
