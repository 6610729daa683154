#include "render_packets.h"

#include <algorithm>

#include "render.h"

namespace quaternia {

PacketTileRenderer::PacketTileRenderer(const LaneFractal& lanes, const Camera& camera,
                                       const Shader& shader, const MarchSettings& march,
                                       int samples)
    : lanes_(lanes),
      camera_(camera),
      shader_(shader),
      march_{march.epsilon, march.pixelAngle, march.maxSteps},
      samples_(samples),
      boundingRadius_(std::sqrt(lanes.bailoutSquared)) {}

void PacketTileRenderer::render(const Tile& tile, std::vector<PixelSamples>& pixels,
                                PacketTileStats& stats) {
    const int width = tile.x1 - tile.x0;
    pixels.assign(size_t(width) * size_t(tile.y1 - tile.y0), PixelSamples{});
    for (int k = 0; k < samples_; ++k) {
        rays_.clear();
        rayPixel_.clear();
        for (int py = tile.y0; py < tile.y1; ++py) {
            for (int px = tile.x0; px < tile.x1; ++px) {
                auto [sx, sy] = samplePosition(k, samples_, px, py);
                Ray ray = camera_.generateRay(px + sx, py + sy);
                if (k == 0) {
                    PixelSamples& pixel = pixels[size_t((py - tile.y0) * width + px - tile.x0)];
                    pixel.background = shader_.background(
                        samples_ == 1 ? ray : camera_.generateRay(px + 0.5, py + 0.5));
                }
                auto interval = intersectSphere(ray, boundingRadius_);
                if (!interval) continue;
                rays_.push(ray, interval->tNear, interval->tFar);
                rayPixel_.push_back((py - tile.y0) * width + (px - tile.x0));
            }
        }
        traceCameraRays(lanes_, march_, rays_, traced_, stats.camera);

        hits_.clear();
        hitPoints_.clear();
        for (size_t i = 0; i < traced_.size(); ++i) {
            const TraceResult& r = traced_[i];
            stats.marchSteps += r.steps;
            if (r.end == TraceEnd::Miss) continue;
            Ray ray{Point3d(rays_.ox[i], rays_.oy[i], rays_.oz[i]),
                    Vector3d(rays_.dx[i], rays_.dy[i], rays_.dz[i])};
            hits_.push_back({rayPixel_[i], r.t, ray.direction, ray.at(r.tOutside)});
            hitPoints_.push(hits_.back().outside);
        }
        if (hits_.empty()) continue;
        shadeHits(stats);
        for (size_t h = 0; h < hits_.size(); ++h) {
            PixelSamples& pixel = pixels[size_t(hits_[h].pixel)];
            pixel.sum += colors_[h];
            pixel.depthSum += hits_[h].t;
            ++pixel.hits;
        }
    }
}

void PacketTileRenderer::shadeHits(PacketTileStats& stats) {
    const size_t count = hits_.size();
    // The estimate at each hit's outside point: its orbit colours the surface, and its
    // iteration count is the M of the analytic normal (JuliaSet::gradientIterations).
    estimatePoints(lanes_, hitPoints_, hitEstimates_, stats.shading);
    gradientIterations_.resize(count);
    for (size_t h = 0; h < count; ++h) {
        const PointEstimate& e = hitEstimates_[h];
        gradientIterations_[h] = e.inside ? lanes_.maxIterations - 1 : e.iterations;
    }
    potentialNormals(lanes_, hitPoints_, gradientIterations_, normals_, stats.shading);

    shadowRays_.clear();
    shadowHit_.clear();
    for (size_t h = 0; h < count; ++h) {
        Vector3d& n = normals_[h];
        if (dot(n, hits_[h].direction) > 0) n = -n;  // seen from inside a thin sheet
        if (shader_.shadows() == Shadows::None || !(shader_.keyDiffuse(n) > 0)) continue;
        Point3d origin =
            shader_.shadowOrigin(hits_[h].outside, n, camera_.pixelFootprint(hits_[h].t));
        Ray ray{origin, shader_.lightDirection()};
        auto interval = intersectSphere(ray, boundingRadius_);
        if (!interval) continue;
        shadowRays_.push(ray, 0, interval->tFar);
        shadowHit_.push_back(int(h));
    }
    ShadowMarch shadowMarch;
    shadowMarch.minimumStep = shader_.shadowMinimumStep();
    shadowMarch.softness = shader_.shadowSoftness();
    shadowMarch.soft = shader_.shadows() == Shadows::Soft;
    traceShadowRays(lanes_, shadowMarch, shadowRays_, shadowVisibility_, stats.shading);

    if (shader_.occlusionEnabled()) {
        occlusionPoints_.clear();
        for (size_t h = 0; h < count; ++h) {
            for (int k = 1; k <= Shader::kOcclusionSamples; ++k)
                occlusionPoints_.push(hits_[h].outside + normals_[h] * shader_.occlusionHeight(k));
        }
        estimatePoints(lanes_, occlusionPoints_, occlusionEstimates_, stats.shading);
    }

    colors_.resize(count);
    size_t nextShadow = 0;
    for (size_t h = 0; h < count; ++h) {
        SurfaceSample sample;
        sample.normal = normals_[h];
        const PointEstimate& e = hitEstimates_[h];
        DistanceEstimate orbit;
        orbit.trap = e.trap;
        orbit.smoothIteration =
            e.inside ? lanes_.maxIterations
                     : smoothEscapeCount(e.iterations, e.radiusSquared, lanes_.degree);
        sample.albedo = shader_.albedo(orbit);
        if (!(shader_.keyDiffuse(sample.normal) > 0)) {
            sample.visibility = 0;
        } else if (nextShadow < shadowHit_.size() && shadowHit_[nextShadow] == int(h)) {
            sample.visibility = shader_.visibilityFromMarch(shadowVisibility_[nextShadow++]);
        } else {
            sample.visibility = 1;  // no shadows, or the shadow ray leaves the bounding sphere
        }
        if (shader_.occlusionEnabled()) {
            double distances[Shader::kOcclusionSamples];
            for (int k = 0; k < Shader::kOcclusionSamples; ++k)
                distances[k] =
                    occlusionEstimates_[h * Shader::kOcclusionSamples + size_t(k)].distance;
            sample.occlusion =
                shader_.ambientFromOpenness(shader_.occlusionFromEstimates(distances));
        }
        colors_[h] = shader_.light(sample, Ray{hits_[h].outside, hits_[h].direction});
    }
}

}  // namespace quaternia
