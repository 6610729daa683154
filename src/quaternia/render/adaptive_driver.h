// One driver of adaptive sampling (adaptive_sampling.h) for both engines: it decides which
// samples each pixel of a tile takes, in which rounds, and counts them; a SampleTracer (the
// scalar reference in render.cpp, the lanes in lane_tile_renderer.h) traces them and adds their
// hits to the pixels' sums. So the two engines take the same samples of the same pixels by
// construction, and differ only in how a ray is traced.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "quaternia/render/adaptive_sampling.h"

namespace quaternia {

// Sample k (samplePosition(k, n, px, py)) of pixel (px, py), whose sums are sums[target].
struct SampleRequest {
    int px, py, k, target;
};

// Step 2 of adaptive sampling while a round is traced: each pixel's first samples' display
// colour (reference[target]) and the largest sampleDeviation of its later samples that hit
// (deviation[target]).
struct DeviationTracking {
    const std::vector<Rgba>& reference;
    std::vector<float>& deviation;
    void add(int target, const Color& sample, const Shader& shader) const {
        float& largest = deviation[size_t(target)];
        largest = std::max(largest, sampleDeviation(sample, reference[size_t(target)], shader));
    }
};

// Rays a tracer gathers from rounds into one batch: about a tile's pixels (as a uniform sample of
// a 64-pixel tile holds), so that the batches stay in cache.
inline constexpr size_t kRefinementBatch = 4096;

class SampleTracer {
  public:
    virtual ~SampleTracer() = default;
    // The first sample of every pixel of the tile's refinementRegion, in one batch, before any
    // round of the tile: each request's hits added to firstPass[target].
    virtual void traceFirstSamples(const Tile& tile, std::span<const SampleRequest> requests,
                                   std::vector<PixelSamples>& firstPass) = 0;
    // One round of later samples (the j-th sample of each pixel that takes it): each request's
    // hits added to pixels[target], in the order of the rounds for each pixel. A tracer may keep
    // rounds back to trace them with later ones, but has traced them all when `last` is set
    // (the last round of the step). `tracking`, where given, receives each hit's deviation.
    virtual void traceRound(std::span<const SampleRequest> round, std::vector<PixelSamples>& pixels,
                            const DeviationTracking* tracking, bool last) = 0;
};

// What the driver keeps from tile to tile (one per thread), so that it allocates nothing after
// the first tiles.
struct AdaptiveScratch {
    std::vector<PixelSamples> firstPass;
    std::vector<uint8_t> refine;
    std::vector<Rgba> firstDisplay, reference;
    std::vector<float> deviation;
    std::vector<int> chosen;
    std::vector<SampleRequest> requests;
};

// Adaptive sampling of one tile of an image of imageWidth x imageHeight pixels with `samples`
// samples per pixel: pixels[(y - y0) * width + (x - x0)] receives the sums of pixel (x, y),
// `samples` counted here, hits and colours by the tracer.
void renderAdaptively(const Tile& tile, int imageWidth, int imageHeight, int samples,
                      const Shader& shader, SampleTracer& tracer, AdaptiveScratch& scratch,
                      std::vector<PixelSamples>& pixels);

}  // namespace quaternia
