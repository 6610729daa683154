#include "quaternia/render/lane_tile_renderer.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "quaternia/render/render.h"
#include "quaternia/render/sample_pattern.h"

namespace quaternia {

namespace {

// A hit's albedo, from its orbit (the estimate at its outside point) where the colouring wants
// it (else null).
Color albedoOf(const Shader& shader, const LaneFractal& lanes, const PointEstimate* orbit) {
    DistanceEstimate orbitOfHit;
    if (orbit) {
        orbitOfHit.trap = orbit->trap;
        if (shader.albedoUsesSmoothIteration()) {
            orbitOfHit.smoothIteration =
                orbit->inside
                    ? lanes.maxIterations
                    : smoothEscapeCount(orbit->iterations, orbit->radiusSquared, lanes.degree);
        }
    }
    return shader.albedo(orbitOfHit);
}

}  // namespace

LaneTileRenderer::LaneTileRenderer(const LaneFractal& lanes, const Camera& camera,
                                   const Shader& shader, const MarchSettings& march, int samples,
                                   bool shadowCylinders, bool adaptive)
    : lanes_(lanes),
      camera_(&camera),
      shader_(&shader),
      march_{march.epsilon, march.pixelAngle, march.maxSteps, march.relaxation},
      samples_(samples),
      shadowCylinders_(shadowCylinders),
      adaptive_(adaptive),
      boundingRadius_(lanes.boundingRadius),
      lightConstants_(shader.lightConstants()) {
    cameraRays_.bind(camera, boundingRadius_, march_, samples_, shader.glowIntensity() > 0);
}

void LaneTileRenderer::rebind(const LaneFractal& lanes, const Camera& camera, const Shader& shader,
                              const MarchSettings& march, int samples, bool adaptive) {
    // Everything the constructor takes from the frame; the batches are sized tile by tile.
    lanes_ = lanes;
    camera_ = &camera;
    shader_ = &shader;
    march_ = {march.epsilon, march.pixelAngle, march.maxSteps, march.relaxation};
    samples_ = samples;
    adaptive_ = adaptive;
    boundingRadius_ = lanes.boundingRadius;
    lightConstants_ = shader.lightConstants();
    cameraRays_.bind(camera, boundingRadius_, march_, samples_, shader.glowIntensity() > 0);
}

void LaneTileRenderer::render(const Tile& tile, std::vector<PixelSamples>& pixels,
                              LaneTileStats& stats) {
    currentTile_ = tile;
    if (adaptive_ && samples_ > 1 && onlySample_ < 0) {
        sampleKey_ = -1;  // each pixel's own count of samples
        renderAdaptive(tile, pixels, stats);
    } else {
        renderUniform(tile, pixels, stats);
    }
}

void LaneTileRenderer::renderUniform(const Tile& tile, std::vector<PixelSamples>& pixels,
                                     LaneTileStats& stats) {
    const int width = tile.x1 - tile.x0;
    tileBlocks_ =
        (width + kConeBlock - 1) / kConeBlock * ((tile.y1 - tile.y0 + kConeBlock - 1) / kConeBlock);
    const UniformSamples taken(samples_, onlySample_);
    pixels.assign(size_t(width) * size_t(tile.y1 - tile.y0),
                  PixelSamples{.samples = taken.count()});
    stats.rays += int64_t(taken.count()) * int64_t(pixels.size());
    cameraRays_.marchCones(lanes_, tile, stats.marchSteps, stats.camera);
    for (int k = taken.first; k < taken.end; ++k) {
        sampleKey_ = k;
        clearRays();
        cameraRays_.sampleRays(tile, k, cameraRayTargets());
        traceInto(pixels, stats);
    }
}

void LaneTileRenderer::collectHits(LaneTileStats& stats) {
    hits_.clear();
    hitPoints_.clear();
    for (size_t i = 0; i < traced_.size(); ++i) {
        const TraceResult& r = traced_[i];
        stats.marchSteps += r.steps;
        if (r.end == TraceEnd::Miss) continue;
        Ray ray{Point3d(rays_.ox[i], rays_.oy[i], rays_.oz[i]),
                Vector3d(rays_.dx[i], rays_.dy[i], rays_.dz[i])};
        hits_.push_back({rayPixel_[i], rayBlock_[i], r.t, ray.direction, ray.at(r.tOutside)});
        hitPoints_.push(hits_.back().outside);
    }
}

void LaneTileRenderer::shadeHits(LaneTileStats& stats) {
    hitNormals(stats);
    aimShadowRays();
    marchShadowRays(stats);
    if (occlusion()) {
        occlusionPoints_.clear();
        for (size_t h = 0; h < hits_.size(); ++h) {
            for (int k = 1; k <= Shader::kOcclusionSamples; ++k)
                occlusionPoints_.push(hits_[h].outside + normals_[h] * shader_->occlusionHeight(k));
        }
        estimateDistances(lanes_, occlusionPoints_, occlusionDistances_, stats.shading);
    }
    sampleSurfaces();
    lightSurfaces(lightConstants_, surfaces_);  // the colours: surfaces_.red, green, blue
    if (!shader_->extraLights().empty()) lightOthers(stats);
    if (shader_->environmentLighting()) lightByEnvironment(stats);
}

void LaneTileRenderer::lightByEnvironment(LaneTileStats& stats) {
    if (shader_->environment()->samples() == 0) {
        // Unshadowed: the irradiance at each normal, read together.
        environmentLight_.resize(hits_.size());
        shader_->environment()->diffuseBatch(normals_, environmentLight_);
        for (size_t h = 0; h < hits_.size(); ++h) {
            surfaces_.red[h] += float(surfaces_.albedoR[h] * environmentLight_[h].x);
            surfaces_.green[h] += float(surfaces_.albedoG[h] * environmentLight_[h].y);
            surfaces_.blue[h] += float(surfaces_.albedoB[h] * environmentLight_[h].z);
        }
        return;
    }
    environmentPoints_.resize(hits_.size());
    for (size_t h = 0; h < hits_.size(); ++h) {
        const Point3d& x = hits_[h].outside;
        environmentPoints_[h] = {
            x, shader_->shadowOrigin(x, normals_[h], camera_->pixelFootprint(hits_[h].t)),
            normals_[h], Color(surfaces_.albedoR[h], surfaces_.albedoG[h], surfaces_.albedoB[h])};
    }
    environmentShadows_.light(lanes_, *shader_, environmentPoints_, shadows_, stats.shading);
    const std::vector<Color>& added = environmentShadows_.colour();
    for (size_t h = 0; h < hits_.size(); ++h) {
        surfaces_.red[h] += float(added[h].x);
        surfaces_.green[h] += float(added[h].y);
        surfaces_.blue[h] += float(added[h].z);
    }
}

void LaneTileRenderer::hitNormals(LaneTileStats& stats) {
    const size_t count = hits_.size();
    // The estimate at each hit's outside point, where the orbit colours the surface: its
    // iteration count is then the M of the analytic normal
    // (QuaternionJuliaSet::gradientIterations). Without orbit colouring, the normals find their M
    // themselves.
    if (shader_->albedoUsesOrbit()) {
        estimatePoints(lanes_, hitPoints_, hitEstimates_, stats.shading);
        gradientIterations_.resize(count);
        for (size_t h = 0; h < count; ++h)
            gradientIterations_[h] = gradientIterationsOf(hitEstimates_[h], lanes_.maxIterations);
        potentialNormals(lanes_, hitPoints_, gradientIterations_, normals_, stats.shading);
    } else {
        potentialNormalsAlone(lanes_, hitPoints_, normals_, stats.shading);
        // The trap pass wants the orbits the colouring did not (the normals stay as above).
        if (passes_) estimatePoints(lanes_, hitPoints_, hitEstimates_, stats.shading);
    }
    for (size_t h = 0; h < count; ++h) {
        Vector3d& n = normals_[h];
        if (dot(n, hits_[h].direction) > 0) n = -n;  // seen from inside a thin sheet
    }
}

void LaneTileRenderer::aimShadowRays() {
    shadows_.clear();
    keyLights_.resize(hits_.size());
    for (size_t h = 0; h < hits_.size(); ++h) {
        const Vector3d& n = normals_[h];
        const KeyLight& key = keyLights_[h] = shader_->keyLight(hits_[h].outside);
        if (shader_->shadows() == Shadows::None || !(Shader::keyDiffuse(n, key) > 0)) continue;
        Point3d origin =
            shader_->shadowOrigin(hits_[h].outside, n, camera_->pixelFootprint(hits_[h].t));
        Ray ray{origin, key.toLight};
        auto interval = shader_->shadowInterval(ray, key);
        if (!interval) continue;
        shadows_.push(ray, 0, interval->tFar, int(h));
    }
}

void LaneTileRenderer::marchShadowRays(LaneTileStats& stats) {
    ShadowMarch shadowMarch;
    shadowMarch.minimumStep = shader_->shadowMinimumStep();
    shadowMarch.softness = shader_->shadowSoftness();
    shadowMarch.soft = shader_->shadows() == Shadows::Soft;
    shadowMarch.maxSteps = Shader::kShadowSteps;
    shadowMarch.relaxation = Shader::kShadowRelaxation;
    shadowMarch.maxRelaxation = Shader::kShadowMaxRelaxation;
    if (shadowCylinders_ && shader_->shadows() == Shadows::Hard &&
        shader_->keyLightIsDirectional()) {
        shadows_.marchClippedHardShadows(
            lanes_, march_, shadowMarch, shader_->lightDirection(), boundingRadius_, tileBlocks_,
            [&](int hit) { return hits_[size_t(hit)].block; }, stats.shading);
    } else {
        shadows_.march(lanes_, shadowMarch, stats.shading);
    }
}

void LaneTileRenderer::sampleSurfaces() {
    surfaces_.resize(hits_.size());
    const bool orbit = shader_->albedoUsesOrbit();
    // The shadow rays' owners are in order: the next shadow ray is this hit's or later.
    const std::vector<int>& shadowHit = shadows_.owners();
    size_t nextShadow = 0;
    for (size_t h = 0; h < hits_.size(); ++h) {
        const Vector3d& n = normals_[h];
        const Vector3d& direction = hits_[h].direction;
        const Color albedo = albedoOf(*shader_, lanes_, orbit ? &hitEstimates_[h] : nullptr);
        const KeyLight& key = keyLights_[h];
        double visibility = 1;  // no shadows, or the shadow ray leaves the bounding sphere
        if (!(Shader::keyDiffuse(n, key) > 0)) {
            visibility = 0;
        } else if (nextShadow < shadowHit.size() && shadowHit[nextShadow] == int(h)) {
            visibility = shader_->visibilityFromMarch(shadows_.visibility()[nextShadow++]);
        }
        double occlusion = 1;
        if (this->occlusion()) {
            occlusion = shader_->ambientFromOpenness(shader_->occlusionFromEstimates(
                occlusionDistances_.data() + h * Shader::kOcclusionSamples));
        }
        SurfaceBatch& s = surfaces_;
        s.nx[h] = float(n.x), s.ny[h] = float(n.y), s.nz[h] = float(n.z);
        s.dx[h] = float(direction.x), s.dy[h] = float(direction.y), s.dz[h] = float(direction.z);
        s.lx[h] = float(key.toLight.x), s.ly[h] = float(key.toLight.y),
        s.lz[h] = float(key.toLight.z);
        s.keyScale[h] = float(key.scale);
        s.albedoR[h] = float(albedo.x), s.albedoG[h] = float(albedo.y),
        s.albedoB[h] = float(albedo.z);
        s.visibility[h] = float(visibility);
        s.occlusion[h] = float(occlusion);
    }
}

}  // namespace quaternia
