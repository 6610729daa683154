#include "quaternia/render/adaptive_driver.h"

#include <algorithm>

namespace quaternia {
namespace {

// Samples j = from .. to - 1 (AdaptiveSampling::index) of the tile's pixels whose refinement is
// at least `least` and that have not taken them yet, one round per j, each pixel's in the
// order j (its sums then add in the order uniform sampling adds them).
void takeRounds(const Tile& tile, const AdaptiveSampling& order, int from, int to, uint8_t least,
                const DeviationTracking* tracking, SampleTracer& tracer, AdaptiveScratch& s,
                std::vector<PixelSamples>& pixels) {
    const int width = tile.x1 - tile.x0;
    // The pixels that take these samples, in the tile's order (a loop over all of its pixels
    // for each sample index cost 6% of an adaptive render).
    s.chosen.clear();
    for (size_t i = 0; i < s.refine.size(); ++i) {
        if (s.refine[i] >= least && pixels[i].samples < to) s.chosen.push_back(int(i));
    }
    for (int j = from; j < to; ++j) {
        s.requests.clear();
        for (const int i : s.chosen) {
            PixelSamples& pixel = pixels[size_t(i)];
            if (pixel.samples > j) continue;
            const int px = tile.x0 + i % width, py = tile.y0 + i / width;
            s.requests.push_back({px, py, order.index(j, px, py), i});
            ++pixel.samples;
        }
        tracer.traceRound(s.requests, pixels, tracking, j + 1 == to);
    }
}

}  // namespace

void renderAdaptively(const Tile& tile, int imageWidth, int imageHeight, int samples,
                      const Shader& shader, SampleTracer& tracer, AdaptiveScratch& s,
                      std::vector<PixelSamples>& pixels) {
    const AdaptiveSampling order(samples);
    constexpr int first = AdaptiveSampling::kFirst;

    // Step 1: the first samples of the tile and its border, then the decisions.
    const Tile region = refinementRegion(tile, imageWidth, imageHeight);
    const int regionWidth = region.x1 - region.x0;
    s.firstPass.assign(size_t(regionWidth) * size_t(region.y1 - region.y0),
                       PixelSamples{.samples = first});
    s.requests.clear();
    for (int py = region.y0; py < region.y1; ++py) {
        for (int px = region.x0; px < region.x1; ++px)
            s.requests.push_back({px, py, order.index(0, px, py),
                                  (py - region.y0) * regionWidth + (px - region.x0)});
    }
    tracer.traceFirstSamples(tile, s.requests, s.firstPass);
    markPixelsToRefine(region, tile, s.firstPass, shader, s.firstDisplay, s.refine);

    // The tile's pixels from their first samples.
    const int width = tile.x1 - tile.x0;
    pixels.resize(size_t(width) * size_t(tile.y1 - tile.y0));
    for (int py = tile.y0; py < tile.y1; ++py) {
        const PixelSamples* from = s.firstPass.data() +
                                   size_t(py - region.y0) * size_t(regionWidth) +
                                   (tile.x0 - region.x0);
        std::copy(from, from + width, pixels.begin() + ptrdiff_t(py - tile.y0) * width);
    }

    // Step 2: each later sample's colour against the first's (pixels of kTakeAll take these
    // samples too, their deviations unread), then the rest where they disagree.
    s.reference.resize(pixels.size());
    s.deviation.assign(pixels.size(), 0.0f);
    for (size_t i = 0; i < pixels.size(); ++i) {
        if (s.refine[i] != kKeepFirst) s.reference[i] = firstDisplay(pixels[i], shader);
    }
    const DeviationTracking tracking{s.reference, s.deviation};
    takeRounds(tile, order, first, order.second(), kTakeSecond, &tracking, tracer, s, pixels);
    for (size_t i = 0; i < pixels.size(); ++i) {
        if (s.refine[i] == kTakeSecond && secondSamplesDisagree(pixels[i], s.deviation[i]))
            s.refine[i] = kTakeAll;
    }
    takeRounds(tile, order, first, samples, kTakeAll, nullptr, tracer, s, pixels);
}

}  // namespace quaternia
