// The ground plane in the SIMD path (lane_tile_renderer.h): the points where rays meet it, lit
// as the set's hits are (shadow rays in lanes, lightSurfaces), the shadow rays of a directional
// light cleared by a cone per block where it proves them lit. The camera rays that see the
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
    const size_t count = groundPoints_.size();
    const double offset = 1e-6 * boundingRadius_;
    // Each light's visibility at every ground point (1 where it needs no shadow ray).
    auto visibilities = [&](const LightSource& light, std::vector<double>& out) {
        shadows_.clear();
        out.assign(count, 1.0);
        if (light.shadows == Shadows::None) return;
        // A directional light is the same at every point.
        const bool directional = light.kind == LightKind::Directional;
        KeyLight at = Shader::illumination(light, Point3d());
        for (size_t g = 0; g < count; ++g) {
            const GroundPoint& p = groundPoints_[g];
            if (!directional) at = Shader::illumination(light, p.x);
            const Vector3d n = p.normal();
            if (!(Shader::keyDiffuse(n, at) > 0)) continue;
            const Ray ray{p.x + n * offset, at.toLight};
            auto interval = shader_->shadowIntervalOf(ray, at, light);
            if (!interval) continue;
            shadows_.push(ray, interval->tNear, interval->tFar, int(g));
        }
        clearLitGroundShadows(light, stats);
        marchShadowsOf(light, stats);
        for (size_t r = 0; r < shadows_.size(); ++r)
            out[size_t(shadows_.owners()[r])] =
                shader_->visibilityOf(light, shadows_.visibility()[r]);
    };
    visibilities(shader_->keySource(), groundKeyVisibility_);
    groundColor_.assign(count, Color());
    for (const LightSource& light : shader_->extraLights()) {
        visibilities(light, groundOtherVisibility_);
        for (size_t g = 0; g < count; ++g) {
            const GroundPoint& p = groundPoints_[g];
            groundColor_[g] +=
                shader_->lightOther(light, Shader::illumination(light, p.x), p.normal(),
                                    ground_.color, p.direction, groundOtherVisibility_[g]);
        }
    }
    // The key light, in lanes as the set's hits are lit (lightSurfaces).
    SurfaceBatch& lit = groundSurfaces_;
    lit.resize(count);
    const bool directional = shader_->keySource().kind == LightKind::Directional;
    KeyLight key = shader_->keyLight(Point3d());
    for (size_t g = 0; g < count; ++g) {
        const GroundPoint& p = groundPoints_[g];
        if (!directional) key = shader_->keyLight(p.x);
        const Vector3d n = p.normal();
        const bool facing = Shader::keyDiffuse(n, key) > 0;
        lit.nx[g] = float(n.x), lit.ny[g] = float(n.y), lit.nz[g] = float(n.z);
        lit.dx[g] = float(p.direction.x), lit.dy[g] = float(p.direction.y),
        lit.dz[g] = float(p.direction.z);
        lit.lx[g] = float(key.toLight.x), lit.ly[g] = float(key.toLight.y),
        lit.lz[g] = float(key.toLight.z);
        lit.keyScale[g] = float(key.scale);
        lit.albedoR[g] = float(ground_.color.x), lit.albedoG[g] = float(ground_.color.y),
        lit.albedoB[g] = float(ground_.color.z);
        // Where the key light is behind the plane: no light, and no shadow to catch.
        lit.visibility[g] = facing ? float(groundKeyVisibility_[g]) : 0.0f;
        if (!facing) groundKeyVisibility_[g] = 1;
        lit.occlusion[g] = 1;
    }
    lightSurfaces(lightConstants_, lit);
    for (size_t g = 0; g < count; ++g)
        groundColor_[g] += Color(lit.red[g], lit.green[g], lit.blue[g]);
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
                sample.alpha = 1 - groundKeyVisibility_[g];
                continue;
            }
            sample.alpha = 1;
        }
        const double cosine = std::abs(path.ray.direction.y);
        const double reflected =
            ground_.reflectivity > 0 ? fresnelSchlick(cosine, ground_.reflectivity) : 0.0;
        const double kept = shader_->fogKept(t);
        sample.color += path.weight * (groundColor_[g] * (kept * (1 - reflected)) +
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
            sample.alpha = 1 - groundKeyVisibility_[g];
        } else {
            sample.alpha = 1;
            const double kept = shader_->fogKept(sample.depth);
            sample.color = groundColor_[g] * kept + shader_->fogColor() * (1 - kept);
        }
        addSample(pixels, sample);
    }
}

void LaneTileRenderer::clearLitGroundShadows(const LightSource& light, LaneTileStats& stats) {
    // A cone per block of 4x4 camera pixels (ShadowRays::clearLitByCones). Only in a uniform pass
    // (one sample of every pixel of the tile in the batch, sampleKey_): adaptive sampling's batches
    // hold the tile's border (its first samples, whose pixels are not on the tile's grid of blocks)
    // or several samples of some pixels, as many as the tile's size lets a batch hold; rays that
    // start where a cone of such a group was clear would change with the tile size by a rounding,
    // and the decisions with them.
    if (!shadowCylinders_ || sampleKey_ < 0) return;
    shadows_.clearLitByCones(
        lanes_, march_, light, boundingRadius_,
        [&](int point) { return groundPoints_[size_t(point)].block; }, stats.shading);
}

}  // namespace quaternia
