// The SIMD path's adaptive sampling: LaneTileRenderer as the tracer of adaptive_driver.h.
#include <algorithm>
#include <limits>

#include "quaternia/render/lane_tile_renderer.h"
#include "quaternia/render/render.h"
#include "quaternia/render/sample_pattern.h"

namespace quaternia {

void LaneTileRenderer::renderAdaptive(const Tile& tile, std::vector<PixelSamples>& pixels,
                                      LaneTileStats& stats) {
    adaptiveStats_ = &stats;
    renderAdaptively(tile, camera_->width(), camera_->height(), samples_, *shader_, *this,
                     adaptiveScratch_, pixels);
    adaptiveStats_ = nullptr;
}

void LaneTileRenderer::traceFirstSamples(const Tile& tile, std::span<const SampleRequest> requests,
                                         std::vector<PixelSamples>& firstPass) {
    const int imageWidth = camera_->width(), imageHeight = camera_->height();
    // The cone blocks of the region: the tile's and the ring about it, on the image's grid of
    // kConeBlock pixels (the tile's corner is on it), so that each border pixel starts from
    // the cone of the block it has in its own tile.
    const Tile blocks{std::max(0, tile.x0 - kConeBlock), std::max(0, tile.y0 - kConeBlock),
                      std::min(imageWidth, (tile.x1 + kConeBlock) / kConeBlock * kConeBlock),
                      std::min(imageHeight, (tile.y1 + kConeBlock) / kConeBlock * kConeBlock)};
    const int blocksAcross = (blocks.x1 - blocks.x0 + kConeBlock - 1) / kConeBlock;
    tileBlocks_ = blocksAcross * ((blocks.y1 - blocks.y0 + kConeBlock - 1) / kConeBlock);
    adaptiveBlocks_ = blocks;
    LaneTileStats& stats = *adaptiveStats_;
    cameraRays_.marchCones(lanes_, blocks, stats.marchSteps, stats.camera);

    // In one batch, without shadow cylinders: a cylinder holds the rays of its block in the
    // batch, which for a border pixel are not those of its own tile, and a cylinder may change a
    // pixel by a rounding (ShadowCylindersChangeNoPixel); the decisions must not.
    stats.rays += int64_t(requests.size());
    const bool cylinders = shadowCylinders_;
    shadowCylinders_ = false;
    clearRays();
    for (const SampleRequest& r : requests)
        cameraRays_.queue(r.px, r.py, r.k, r.target);
    cameraRays_.pushQueued(blocks, cameraRayTargets());
    traceInto(firstPass, stats);
    shadowCylinders_ = cylinders;
    clearRays();
}

void LaneTileRenderer::traceRound(std::span<const SampleRequest> round,
                                  std::vector<PixelSamples>& pixels,
                                  const DeviationTracking* tracking, bool last) {
    LaneTileStats& stats = *adaptiveStats_;
    stats.rays += int64_t(round.size());
    for (const SampleRequest& r : round)
        cameraRays_.queue(r.px, r.py, r.k, r.target);
    cameraRays_.pushQueued(adaptiveBlocks_, cameraRayTargets());
    // Whole rounds per batch: each pixel's samples are summed in the order of the rounds.
    if (rays_.size() >= kRefinementBatch || last) {
        tracking_ = tracking;
        traceInto(pixels, stats);
        tracking_ = nullptr;
        clearRays();
    }
}

void LaneTileRenderer::clearRays() {
    rays_.clear();
    rayPixel_.clear();
    rayBlock_.clear();
    bypass_.clear();
}

void LaneTileRenderer::traceInto(std::vector<PixelSamples>& pixels, LaneTileStats& stats) {
    if (paths_.active()) {
        waveStats_ = &stats;
        paths_.trace(*this, currentTile_, sampleKey_, cameraRayTargets(), pixels, tracking_);
        waveStats_ = nullptr;
        return;
    }
    if (rays_.size() == 0) return;
    traceCameraRays(lanes_, march_, rays_, traced_, stats.camera);
    collectHits(stats);
    if (hits_.empty()) return;
    shadeHits(stats);
    for (size_t h = 0; h < hits_.size(); ++h) {
        PixelSamples& pixel = pixels[size_t(hits_[h].owner)];
        const Color sample = shader_->throughFog(
            Color(surfaces_.red[h], surfaces_.green[h], surfaces_.blue[h]), hits_[h].t);
        pixel.sum += sample;
        pixel.depthSum += hits_[h].t;
        ++pixel.hits;
        if (passes_) {
            pixel.normalSum += normals_[h];
            pixel.trapSum += hitEstimates_[h].trap;
        }
        if (tracking_) tracking_->add(hits_[h].owner, sample, *shader_);
    }
}

}  // namespace quaternia
