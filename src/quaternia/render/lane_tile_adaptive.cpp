// The SIMD path's adaptive sampling (adaptive_sampling.h): LaneTileRenderer::renderAdaptive.
#include <algorithm>
#include <limits>

#include "quaternia/render/lane_tile_renderer.h"
#include "quaternia/render/render.h"
#include "quaternia/render/sample_pattern.h"

namespace quaternia {

namespace {

// Rays in one batch of the rest of the samples: about a tile's pixels (as a uniform sample of
// a 64-pixel tile holds), so that the batches stay in cache.
constexpr size_t kRefinementBatch = 4096;

}  // namespace

void LaneTileRenderer::renderAdaptive(const Tile& tile, std::vector<PixelSamples>& pixels,
                                      LaneTileStats& stats) {
    const int imageWidth = camera_->width(), imageHeight = camera_->height();
    const Tile region = refinementRegion(tile, imageWidth, imageHeight);
    // The cone blocks of the region: the tile's and the ring about it, on the image's grid of
    // kConeBlock pixels (the tile's corner is on it), so that each border pixel starts from
    // the cone of the block it has in its own tile.
    const Tile blocks{std::max(0, tile.x0 - kConeBlock), std::max(0, tile.y0 - kConeBlock),
                      std::min(imageWidth, (tile.x1 + kConeBlock) / kConeBlock * kConeBlock),
                      std::min(imageHeight, (tile.y1 + kConeBlock) / kConeBlock * kConeBlock)};
    const int blocksAcross = (blocks.x1 - blocks.x0 + kConeBlock - 1) / kConeBlock;
    tileBlocks_ = blocksAcross * ((blocks.y1 - blocks.y0 + kConeBlock - 1) / kConeBlock);
    marchCones(blocks, stats);

    // The first samples. Without shadow cylinders: a cylinder holds the rays of its block in
    // the batch, which for a border pixel are not those of its own tile, and a cylinder may
    // change a pixel by a rounding (ShadowCylindersChangeNoPixel); the decisions must not.
    const AdaptiveSampling order(samples_);
    const int regionWidth = region.x1 - region.x0;
    constexpr int first = AdaptiveSampling::kFirst;
    firstPass_.assign(size_t(regionWidth) * size_t(region.y1 - region.y0),
                      PixelSamples{.samples = first});
    stats.rays += int64_t(first) * int64_t(firstPass_.size());
    const bool cylinders = shadowCylinders_;
    shadowCylinders_ = false;
    clearRays();
    for (int py = region.y0; py < region.y1; ++py) {
        for (int px = region.x0; px < region.x1; ++px)
            queueSample(px, py, order.index(0, px, py),
                        (py - region.y0) * regionWidth + (px - region.x0));
    }
    pushSampleRays(blocks);
    traceInto(firstPass_, stats);
    shadowCylinders_ = cylinders;

    // The tile's pixels from their first samples, then the rest where they are wanted.
    markPixelsToRefine(region, tile, firstPass_, *shader_, firstDisplay_, refine_);
    const int width = tile.x1 - tile.x0;
    pixels.resize(size_t(width) * size_t(tile.y1 - tile.y0));
    for (int py = tile.y0; py < tile.y1; ++py) {
        const PixelSamples* from = firstPass_.data() +
                                   size_t(py - region.y0) * size_t(regionWidth) +
                                   (tile.x0 - region.x0);
        std::copy(from, from + width, pixels.begin() + ptrdiff_t(py - tile.y0) * width);
    }
    // Step 2: each later sample's colour against the first's.
    secondReference_.resize(pixels.size());
    deviation_.assign(pixels.size(), 0.0f);
    for (size_t i = 0; i < pixels.size(); ++i) {
        // (Pixels of kTakeAll take these samples too, their deviations unread.)
        if (refine_[i] != kKeepFirst) secondReference_[i] = firstDisplay(pixels[i], *shader_);
    }
    tracking_ = true;
    refineSamples(tile, blocks, order, first, order.second(), kTakeSecond, pixels, stats);
    tracking_ = false;
    for (size_t i = 0; i < pixels.size(); ++i) {
        if (refine_[i] == kTakeSecond && secondSamplesDisagree(pixels[i], deviation_[i]))
            refine_[i] = kTakeAll;
    }
    refineSamples(tile, blocks, order, first, samples_, kTakeAll, pixels, stats);
}

void LaneTileRenderer::clearRays() {
    rays_.clear();
    rayPixel_.clear();
    rayBlock_.clear();
    bypass_.clear();
}

void LaneTileRenderer::refineSamples(const Tile& tile, const Tile& blocks,
                                     const AdaptiveSampling& order, int from, int to, uint8_t least,
                                     std::vector<PixelSamples>& pixels, LaneTileStats& stats) {
    const int width = tile.x1 - tile.x0;
    // The pixels that take these samples, in the tile's order (a loop over all of its pixels
    // for each sample index cost 6% of an adaptive render).
    std::vector<int>& chosen = refinedPixels_;
    chosen.clear();
    for (size_t i = 0; i < refine_.size(); ++i) {
        if (refine_[i] >= least && pixels[i].samples < to) chosen.push_back(int(i));
    }
    clearRays();
    for (int j = from; j < to; ++j) {
        for (const int i : chosen) {
            PixelSamples& pixel = pixels[size_t(i)];
            if (pixel.samples > j) continue;
            queueSample(tile.x0 + i % width, tile.y0 + i / width,
                        order.index(j, tile.x0 + i % width, tile.y0 + i / width), i);
            ++pixel.samples;
            ++stats.rays;
        }
        pushSampleRays(blocks);
        // Whole samples per batch: each pixel's samples are summed in the order j.
        if (rays_.size() >= kRefinementBatch || j + 1 == to) {
            traceInto(pixels, stats);
            clearRays();
        }
    }
}

void LaneTileRenderer::pushSampleRays(const Tile& blocks) {
    // In three loops: the sample positions (a hash each), the rays and where they cross the
    // bounding sphere (a chain of a division and two square roots per ray, which in a loop
    // without calls or stores to growing vectors overlaps from ray to ray), then the batch.
    const size_t count = queued_.size();
    for (QueuedSample& q : queued_) {
        auto [sx, sy] = samplePosition(q.k, samples_, q.px, q.py);
        q.x = q.px + sx, q.y = q.py + sy;
    }
    queuedRays_.resize(count);
    queuedNear_.resize(count);
    queuedFar_.resize(count);
    for (size_t i = 0; i < count; ++i) {
        const QueuedSample& q = queued_[i];
        const Ray ray = camera_->thinLens()
                            ? camera_->generateRay(q.x, q.y, lensSample(q.k, q.px, q.py))
                            : camera_->generateRay(q.x, q.y);
        auto interval = intersectSphere(ray, boundingRadius_);
        queuedRays_[i] = ray;
        queuedNear_[i] = interval ? interval->tNear : 1;
        queuedFar_[i] = interval ? interval->tFar : -1;  // none: tNear > tFar
    }
    const int blocksAcross = (blocks.x1 - blocks.x0 + kConeBlock - 1) / kConeBlock;
    for (size_t i = 0; i < count; ++i) {
        const QueuedSample& q = queued_[i];
        const int block =
            (q.py - blocks.y0) / kConeBlock * blocksAcross + (q.px - blocks.x0) / kConeBlock;
        const double near = std::max(queuedNear_[i], blockStart_[size_t(block)]);
        // The cone or the bounding sphere missed: the ray skips the set.
        if (!(near <= queuedFar_[i])) {
            if (bypassing_) bypass_.push_back({queuedRays_[i], q.target});
            continue;
        }
        rays_.push(queuedRays_[i], near, queuedFar_[i]);
        rayPixel_.push_back(q.target);
        rayBlock_.push_back(block);
    }
    queued_.clear();
}

void LaneTileRenderer::traceInto(std::vector<PixelSamples>& pixels, LaneTileStats& stats) {
    if (scenery_) {
        tracePaths(pixels, stats);
        return;
    }
    if (rays_.size() == 0) return;
    traceCameraRays(lanes_, march_, rays_, traced_, stats.camera);
    collectHits(stats);
    if (hits_.empty()) return;
    shadeHits(stats);
    for (size_t h = 0; h < hits_.size(); ++h) {
        PixelSamples& pixel = pixels[size_t(hits_[h].pixel)];
        const Color sample = shader_->throughFog(
            Color(surfaces_.red[h], surfaces_.green[h], surfaces_.blue[h]), hits_[h].t);
        pixel.sum += sample;
        pixel.depthSum += hits_[h].t;
        ++pixel.hits;
        if (passes_) {
            pixel.normalSum += normals_[h];
            pixel.trapSum += hitEstimates_[h].trap;
        }
        if (tracking_) {
            float& deviation = deviation_[size_t(hits_[h].pixel)];
            deviation = std::max(
                deviation,
                sampleDeviation(sample, secondReference_[size_t(hits_[h].pixel)], *shader_));
        }
    }
}

}  // namespace quaternia
