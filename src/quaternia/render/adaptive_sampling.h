// Adaptive anti-aliasing (render.adaptive): with n samples per pixel, every pixel first takes
// one of its n stratified samples (samplePosition), and the other n - 1 only where they would
// change it: where the first samples of the pixel and of its eight neighbours disagree (one
// hits, another misses, or their colours differ visibly). A pixel that takes them all has the
// uniform render's value; one that does not has its first sample's, which its neighbours show
// to lie in a smooth part of the picture.
//
// The decision for a pixel depends on its own and its neighbours' first samples alone, so both
// engines compute the first samples of a one-pixel border about each tile too: the picture is
// the same for any tile size and any RenderOptions::window.
#pragma once

#include <cstdint>
#include <vector>

#include "quaternia/image/image.h"
#include "quaternia/render/shade.h"
#include "quaternia/util/parallel.h"

namespace quaternia {

// The samples of one pixel, summed.
struct PixelSamples {
    Color sum;
    double depthSum = 0;
    int hits = 0;
    int samples = 0;  // taken
};

// How many samples every pixel takes before the decision (1: the neighbours decide).
int adaptiveFirstSamples(int samples);

// The index k (for samplePosition(k, samples, ...)) of the j-th sample a pixel takes: the first
// is the stratum at the pixel's centre (a first sample in a corner stratum would shift the
// pixels that keep it alone), then the others in order.
int adaptiveSampleIndex(int j, int samples);

// The tile's pixels that take the rest of their samples, in refine ((y - y0) * width + (x -
// x0) for pixel (x, y) of the tile), from the first samples of `region`: the tile and the
// pixels about it within one pixel that lie in the image, firstPass[(y - region.y0) *
// regionWidth + (x - region.x0)]. `display` is scratch.
void markPixelsToRefine(const Tile& region, const Tile& tile,
                        const std::vector<PixelSamples>& firstPass, const Shader& shader,
                        std::vector<Rgba>& display, std::vector<uint8_t>& refine);

// The region of markPixelsToRefine: the tile grown by one pixel, within the image.
Tile refinementRegion(const Tile& tile, int imageWidth, int imageHeight);

}  // namespace quaternia
