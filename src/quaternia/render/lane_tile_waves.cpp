// The SIMD path as the engine of the paths (path_waves.h): each wave's rays marched in lanes as
// camera rays are, their hits shaded by the same batches (shadeHits), the exits of refracted
// rays found by membership in lanes, the ground lit by GroundLighting.
#include <algorithm>

#include "quaternia/render/lane_tile_renderer.h"

namespace quaternia {

void LaneTileRenderer::marchWave(const RayBatch& rays, bool closest,
                                 std::vector<TraceResult>& traced) {
    CameraMarch march = march_;
    march.closest = closest;
    traceCameraRays(lanes_, march, rays, traced, waveStats_->camera);
    for (const TraceResult& r : traced)
        waveStats_->marchSteps += r.steps;
}

void LaneTileRenderer::shadeWave(const std::vector<WaveHit>& hits, const HitShading& how) {
    hits_.assign(hits.begin(), hits.end());
    hitPoints_.clear();
    for (const WaveHit& hit : hits_)
        hitPoints_.push(hit.outside);
    // Shadow cylinders group a block's camera rays: the first wave only.
    const bool cylinders = shadowCylinders_;
    shadowCylinders_ = cylinders && how.firstWave;
    secondaryWave_ = !how.firstWave;
    if (how.lit) {
        shadeHits(*waveStats_);
    } else {
        hitNormals(*waveStats_);
        surfaces_.resize(hits_.size());
        std::fill(surfaces_.red.begin(), surfaces_.red.end(), 0.0f);
        std::fill(surfaces_.green.begin(), surfaces_.green.end(), 0.0f);
        std::fill(surfaces_.blue.begin(), surfaces_.blue.end(), 0.0f);
    }
    shadowCylinders_ = cylinders;
    secondaryWave_ = false;
}

void LaneTileRenderer::outsideDistances(const PointBatch& points, std::vector<double>& distances) {
    // Membership alone (the distance is 0 exactly inside K_N): estimateDistances skips the
    // orbit's bookkeeping.
    estimateDistances(lanes_, points, distances, waveStats_->shading);
}

void LaneTileRenderer::outwardNormals(const PointBatch& points, std::vector<Vector3d>& normals) {
    // From the estimate at each point: its iterations are the M of the analytic normal.
    estimatePoints(lanes_, points, exitEstimates_, waveStats_->shading);
    gradientIterations_.resize(points.size());
    for (size_t p = 0; p < points.size(); ++p)
        gradientIterations_[p] = gradientIterationsOf(exitEstimates_[p], lanes_.maxIterations);
    potentialNormals(lanes_, points, gradientIterations_, normals, waveStats_->shading);
}

void LaneTileRenderer::lightGround(const std::vector<GroundPoint>& points, bool firstWave) {
    // The cones of a directional light only in a uniform pass (one sample of every pixel of the
    // tile in the batch, sampleKey_): adaptive sampling's batches hold the tile's border (its
    // first samples, whose pixels are not on the tile's grid of blocks) or several samples of
    // some pixels, as many as the tile's size lets a batch hold; rays that start where a cone of
    // such a group was clear would change with the tile size by a rounding, and the decisions
    // with them.
    const GroundLighting::Frame frame{lanes_,
                                      *shader_,
                                      paths_.ground(),
                                      lightConstants_,
                                      march_,
                                      boundingRadius_,
                                      shadowCylinders_ && firstWave && sampleKey_ >= 0};
    groundLighting_.light(points, frame, shadows_, waveStats_->shading);
}

void LaneTileRenderer::lightOthers(LaneTileStats& stats) {
    for (const LightSource& light : shader_->extraLights()) {
        shadows_.clear();
        otherLights_.resize(hits_.size());
        for (size_t h = 0; h < hits_.size(); ++h) {
            const KeyLight& at = otherLights_[h] = Shader::illumination(light, hits_[h].outside);
            if (light.shadows == Shadows::None || !(Shader::keyDiffuse(normals_[h], at) > 0))
                continue;
            const Ray ray{shader_->shadowOrigin(hits_[h].outside, normals_[h],
                                                camera_->pixelFootprint(hits_[h].t)),
                          at.toLight};
            auto interval = shader_->shadowIntervalOf(ray, at, light);
            if (!interval) continue;
            shadows_.push(ray, 0, interval->tFar, int(h));
        }
        shadows_.march(lanes_, shadowMarchOf(light, *shader_), stats.shading);
        const std::vector<int>& shadowHit = shadows_.owners();
        size_t next = 0;
        for (size_t h = 0; h < hits_.size(); ++h) {
            double visibility = 1;
            if (next < shadowHit.size() && shadowHit[next] == int(h))
                visibility = shader_->visibilityOf(light, shadows_.visibility()[next++]);
            else if (light.shadows != Shadows::None)
                visibility = Shader::keyDiffuse(normals_[h], otherLights_[h]) > 0 ? 1.0 : 0.0;
            const Color albedo(surfaces_.albedoR[h], surfaces_.albedoG[h], surfaces_.albedoB[h]);
            const Color added = shader_->lightOther(light, otherLights_[h], normals_[h], albedo,
                                                    hits_[h].direction, visibility);
            surfaces_.red[h] += float(added.x);
            surfaces_.green[h] += float(added.y);
            surfaces_.blue[h] += float(added.z);
        }
    }
}

}  // namespace quaternia
