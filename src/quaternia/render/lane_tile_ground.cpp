// The ground plane in the SIMD path (lane_tile_renderer.h): the points where rays meet it, lit
// by GroundLighting (ground_lighting.h), into their samples. The camera rays that see the
// ground and nothing else (they skip the set's bounding sphere, and the ground reflects
// nothing) take none of the paths of lane_tile_scenery.cpp: their samples go to their pixels.
#include <algorithm>
#include <cmath>
#include <vector>

#include "quaternia/render/lane_tile_renderer.h"

namespace quaternia {

int LaneTileRenderer::blockOfPixel(int pixel) const {
    const int width = currentTile_.x1 - currentTile_.x0;
    const int across = (width + kConeBlock - 1) / kConeBlock;
    return pixel / width / kConeBlock * across + pixel % width / kConeBlock;
}

void LaneTileRenderer::lightGround(LaneTileStats& stats) {
    // The cones of a directional light only in a uniform pass (one sample of every pixel of the
    // tile in the batch, sampleKey_): adaptive sampling's batches hold the tile's border (its
    // first samples, whose pixels are not on the tile's grid of blocks) or several samples of
    // some pixels, as many as the tile's size lets a batch hold; rays that start where a cone of
    // such a group was clear would change with the tile size by a rounding, and the decisions
    // with them.
    const GroundLighting::Frame frame{lanes_,
                                      *shader_,
                                      ground_,
                                      lightConstants_,
                                      march_,
                                      boundingRadius_,
                                      shadowCylinders_ && sampleKey_ >= 0};
    groundLighting_.light(groundPoints_, frame, shadows_, stats.shading);
}

void LaneTileRenderer::shadeGround(LaneTileStats& stats) {
    groundPoints_.clear();
    for (const GroundHit& hit : groundHits_) {
        const PathRay& path = outside_[hit.path];
        const int block =
            path.camera ? blockOfPixel(sampleResults_[size_t(path.sample)].pixel) : -1;
        groundPoints_.push_back({path.ray.at(hit.t), path.ray.direction, block});
    }
    lightGround(stats);
    const double offset = 1e-6 * boundingRadius_;
    for (size_t g = 0; g < groundHits_.size(); ++g) {
        const PathRay& path = outside_[groundHits_[g].path];
        SampleResult& sample = sampleResults_[size_t(path.sample)];
        const double t = groundHits_[g].t;
        const Vector3d n = groundPoints_[g].normal();
        if (path.camera) {
            sample.object = 2;
            sample.depth = t;
            sample.normal = n;
            if (ground_.shadowCatcher) {
                // Only the shadow: black, as opaque as the key light is hidden.
                sample.alpha = 1 - groundLighting_.keyVisibility()[g];
                continue;
            }
            sample.alpha = 1;
        }
        const double cosine = std::abs(path.ray.direction.y);
        const double reflected =
            ground_.reflectivity > 0 ? fresnelSchlick(cosine, ground_.reflectivity) : 0.0;
        const double kept = shader_->fogKept(t);
        sample.color += path.weight * (groundLighting_.colour()[g] * (kept * (1 - reflected)) +
                                       shader_->fogColor() * (1 - kept));
        if (reflected > 0) {
            const Ray ray{groundPoints_[g].x + n * offset, reflect(path.ray.direction, n)};
            spawn(path, ray, path.weight * (kept * reflected), path.travelled + t, false);
        }
    }
}

void LaneTileRenderer::shadeCameraGround(std::vector<PixelSamples>& pixels, LaneTileStats& stats) {
    groundPoints_.clear();
    for (const GroundHit& hit : cameraGround_) {
        const BypassRay& camera = bypass_[hit.path];
        groundPoints_.push_back(
            {camera.ray.at(hit.t), camera.ray.direction, blockOfPixel(camera.pixel)});
    }
    lightGround(stats);
    // As shadeGround's camera rays, with nothing reflected. (One sample result for all: a new
    // one per point cost more than the rest of the loop.)
    SampleResult sample;
    sample.object = 2;
    for (size_t g = 0; g < cameraGround_.size(); ++g) {
        sample.pixel = bypass_[cameraGround_[g].path].pixel;
        sample.depth = cameraGround_[g].t;
        sample.normal = groundPoints_[g].normal();
        if (ground_.shadowCatcher) {
            sample.alpha = 1 - groundLighting_.keyVisibility()[g];
        } else {
            sample.alpha = 1;
            const double kept = shader_->fogKept(sample.depth);
            sample.color = groundLighting_.colour()[g] * kept + shader_->fogColor() * (1 - kept);
        }
        addSample(pixels, sample);
    }
}

}  // namespace quaternia
