// Adaptive anti-aliasing (render.adaptive): with n samples per pixel, every pixel first takes
// one of its n stratified samples (samplePosition), and more only where they would change it,
// in two steps:
//  1. Where the first samples of the pixel and of its eight neighbours disagree: one hits and
//     another misses (a silhouette) — such a pixel takes all n — or their colours differ
//     visibly (shadow edges, fine detail) — such a pixel takes 4 of the n, spread over it.
//  2. A pixel of 4 samples whose last three disagree with its first (some hit and some miss,
//     or one's colour differs visibly from the first's) takes all n.
// A pixel that takes them all has the uniform render's value up to the order of the sums; the
// others have the mean of the samples they took, each sample weighted alike (their strata
// spread over the pixel), and alpha the fraction of them that hit.
//
// The decisions for a pixel depend on its own and its neighbours' first samples alone, so both
// engines compute the first samples of a one-pixel border about each tile too: the picture is
// the same for any tile size and any RenderOptions::window.
#pragma once

#include <cstdint>
#include <vector>

#include "quaternia/image/image.h"
#include "quaternia/render/sample_pattern.h"
#include "quaternia/render/shade.h"
#include "quaternia/util/parallel.h"

namespace quaternia {

// The samples of one pixel, summed.
struct PixelSamples {
    Color sum = Color();
    double depthSum = 0;
    int hits = 0;
    int samples = 0;  // taken
    // Of the hit samples, for the passes (RenderOptions::passes): world normals and orbit traps.
    Vector3d normalSum = Vector3d();
    double trapSum = 0;
    // The scene around the set (path_waves.h): hits whose alpha is below 1 (a shadow
    // catcher's, a glow's over the background) leave 1 - alpha each here, and the hits of the
    // ground are counted apart (its object id).
    // Samples that hit nothing but carry a glow are hits of no object (layerHits).
    double uncovered = 0;
    int groundHits = 0;
    int layerHits = 0;
    // Whether the finished pixel shows some of the background: a sample missed, or a hit let
    // some through.
    bool showsBackground() const { return hits != samples || uncovered != 0; }
};

// The sample indices [first, end) that uniform sampling takes in each pixel: all n, or sample
// `only` alone where it is at least 0 (RenderOptions::onlySample).
struct UniformSamples {
    int first, end;
    UniformSamples(int n, int only) : first(only >= 0 ? only : 0), end(only >= 0 ? only + 1 : n) {}
    int count() const { return end - first; }
};

// The order in which a pixel takes its n samples and how many it takes at each step.
class AdaptiveSampling {
  public:
    explicit AdaptiveSampling(int samples);
    // The index k (for samplePosition(k, n, px, py)) of the j-th sample a pixel takes: first
    // the stratum at the centre (a first sample in a corner stratum would shift the pixels
    // that keep it alone), then three more in other rows and columns of the strata, then the
    // others in order. (The same for every pixel: first samples whose stratum alternated from
    // pixel to pixel made neighbours differ where the picture does not, and kept pixels off
    // centre.)
    int index(int j, int /*px*/, int /*py*/) const { return order_[size_t(j)]; }
    int samples() const { return int(order_.size()); }
    static constexpr int kFirst = 1;
    // Samples after step 1 for a pixel whose colours disagree with its neighbours'.
    int second() const { return second_; }

  private:
    std::vector<int> order_;
    int second_;
};

// What step 1 decides for each pixel of a tile.
enum Refinement : uint8_t { kKeepFirst = 0, kTakeSecond = 1, kTakeAll = 2 };

// Step 1: the tile's pixels' refinements, in refine ((y - y0) * width + (x - x0) for pixel
// (x, y) of the tile), from the first samples of `region` (refinementRegion(tile)),
// firstPass[(y - region.y0) * regionWidth + (x - region.x0)]. `display` is scratch.
void markPixelsToRefine(const Tile& region, const Tile& tile,
                        const std::vector<PixelSamples>& firstPass, const Shader& shader,
                        std::vector<Rgba>& display, std::vector<uint8_t>& refine);

// The display colour of a pixel's first samples' hits (black where none hit), for
// sampleDeviation.
Rgba firstDisplay(const PixelSamples& first, const Shader& shader);

// How far a later sample that hit (linear colour) lies from the first samples' display colour,
// in display values: the largest channel's difference.
float sampleDeviation(const Color& sample, const Rgba& firstDisplay, const Shader& shader);

// Step 2: whether a pixel of second() samples (sums `pixel`) takes all of them, its later
// samples' largest sampleDeviation being `deviation`.
bool secondSamplesDisagree(const PixelSamples& pixel, float deviation);

// The region of markPixelsToRefine: the tile grown by one pixel, within the image.
Tile refinementRegion(const Tile& tile, int imageWidth, int imageHeight);

}  // namespace quaternia
