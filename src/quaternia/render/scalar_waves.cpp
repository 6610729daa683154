#include "quaternia/render/scalar_waves.h"

#include "quaternia/render/sample_pattern.h"

namespace quaternia {

void ScalarWaves::marchWave(const RayBatch& rays, bool, std::vector<TraceResult>& traced) {
    // The least estimate (MarchResult::closest) is always kept: it costs a comparison.
    traced.resize(rays.size());
    for (size_t i = 0; i < rays.size(); ++i) {
        const Ray ray{Point3d(rays.ox[i], rays.oy[i], rays.oz[i]),
                      Vector3d(rays.dx[i], rays.dy[i], rays.dz[i])};
        const MarchResult m = march(fractal_, ray, march_, {rays.tNear[i], rays.tFar[i]});
        stats_.marchSteps += m.steps;
        stats_.iterations += m.iterations;
        TraceResult& r = traced[i];
        r = TraceResult();
        r.steps = m.steps;
        r.closest = float(m.closest);
        if (m.hit) {
            r.end = TraceEnd::Inside;
            r.t = m.hit->t;
            r.tOutside = m.hit->tOutside;
        }
    }
}

void ScalarWaves::shadeWave(const std::vector<WaveHit>& hits, const HitShading& how) {
    const size_t count = hits.size();
    normals_.resize(count);
    colours_.assign(count, Color());
    traps_.assign(count, 0.0);
    for (size_t h = 0; h < count; ++h) {
        const WaveHit& w = hits[h];
        const Ray ray{w.outside, w.direction};
        if (!how.lit) {
            Vector3d n = fractal_.normal(w.outside);
            if (dot(n, w.direction) > 0) n = -n;  // seen from inside a thin sheet
            normals_[h] = n;
            if (how.traps) traps_[h] = fractal_.estimate(w.outside).trap;
            continue;
        }
        Hit hit;
        hit.t = w.t;
        hit.position = hit.outside = w.outside;
        hit.estimate = fractal_.estimate(w.outside);
        SurfaceSample surface;
        colours_[h] =
            shader_.shade(hit, ray, camera_.pixelFootprint(w.t), shading_, &surface, how.firstWave);
        normals_[h] = surface.normal;
        traps_[h] = hit.estimate.trap;
    }
}

void ScalarWaves::outsideDistances(const PointBatch& points, std::vector<double>& distances) {
    distances.resize(points.size());
    for (size_t i = 0; i < points.size(); ++i) {
        const bool inside = fractal_.contains(Point3d(points.x[i], points.y[i], points.z[i]));
        ++shading_.estimates;
        distances[i] = inside ? 0.0 : 1.0;
    }
}

void ScalarWaves::outwardNormals(const PointBatch& points, std::vector<Vector3d>& normals) {
    normals.resize(points.size());
    for (size_t i = 0; i < points.size(); ++i)
        normals[i] = fractal_.normal(Point3d(points.x[i], points.y[i], points.z[i]));
}

void ScalarWaves::lightGround(const std::vector<GroundPoint>& points, bool) {
    // As GroundLighting lights the ground in the lanes: every light with its shadow ray from a
    // little above the plane, the key light by Shader::light on an unoccluded surface.
    const size_t count = points.size();
    groundColour_.assign(count, Color());
    keyVisibility_.assign(count, 1.0);
    const double offset = 1e-6 * fractal_.boundingRadius();
    const Color& albedo = ground_.color;
    for (size_t g = 0; g < count; ++g) {
        const GroundPoint& p = points[g];
        const Vector3d n = p.normal();
        const Point3d origin = p.x + n * offset;
        for (const LightSource& light : shader_.extraLights()) {
            const KeyLight at = Shader::illumination(light, p.x);
            const double visibility =
                Shader::keyDiffuse(n, at) > 0 ? shader_.shadowOf(origin, at, light, shading_) : 1.0;
            groundColour_[g] += shader_.lightOther(light, at, n, albedo, p.direction, visibility);
        }
        const KeyLight key = shader_.keyLight(p.x);
        SurfaceSample surface;
        surface.normal = n;
        surface.toLight = key.toLight;
        surface.keyScale = key.scale;
        surface.albedo = albedo;
        // Where the key light is behind the plane: no light, and no shadow to catch.
        const bool facing = Shader::keyDiffuse(n, key) > 0;
        surface.visibility =
            facing ? shader_.shadowOf(origin, key, shader_.keySource(), shading_) : 0.0;
        surface.occlusion = 1;
        if (facing) keyVisibility_[g] = surface.visibility;
        groundColour_[g] += shader_.light(surface, Ray{p.x, p.direction});
        if (shader_.environmentLighting())
            groundColour_[g] += shader_.environmentLight(p.x, origin, n, albedo, shading_);
    }
}

ScalarPaths::ScalarPaths(const Frame& frame, const Tile& tile, RenderStats& stats,
                         ShadingStats& shading)
    : frame_(frame), tile_(tile), stats_(stats), shading_(shading) {
    paths_.bind(frame.shader, frame.camera, frame.fractal.boundingRadius(), frame.material,
                frame.ground);
    paths_.setPasses(frame.passes);
}

void ScalarPaths::traceUniform(const UniformSamples& taken, std::vector<PixelSamples>& pixels) {
    const int width = tile_.x1 - tile_.x0;
    pixels.assign(size_t(width) * size_t(tile_.y1 - tile_.y0),
                  PixelSamples{.samples = taken.count()});
    for (int k = taken.first; k < taken.end; ++k) {
        requests_.clear();
        for (int py = tile_.y0; py < tile_.y1; ++py)
            for (int px = tile_.x0; px < tile_.x1; ++px)
                requests_.push_back({px, py, k, (py - tile_.y0) * width + (px - tile_.x0)});
        trace(k, requests_, pixels, nullptr);
    }
}

void ScalarPaths::traceFirstSamples(const Tile&, std::span<const SampleRequest> requests,
                                    std::vector<PixelSamples>& firstPass) {
    trace(-1, requests, firstPass, nullptr);
}

void ScalarPaths::traceRound(std::span<const SampleRequest> round,
                             std::vector<PixelSamples>& pixels, const DeviationTracking* tracking,
                             bool last) {
    // Rounds gathered into batches as the lanes gather theirs: each sample's glossy direction
    // depends on its pixel's count of samples when its batch is traced.
    requests_.insert(requests_.end(), round.begin(), round.end());
    if (requests_.size() >= kRefinementBatch || last) {
        trace(-1, requests_, pixels, tracking);
        requests_.clear();
    }
}

void ScalarPaths::trace(int sampleKey, std::span<const SampleRequest> requests,
                        std::vector<PixelSamples>& pixels, const DeviationTracking* tracking) {
    // The camera batch as the lanes make theirs: the rays that enter the bounding sphere from
    // where they enter it (from the camera where the glow reaches past it), the others aside
    // for the ground and the glow.
    rays_.clear();
    pixel_.clear();
    block_.clear();
    bypass_.clear();
    const bool glowing = frame_.shader.glowIntensity() > 0;
    const double radius = frame_.fractal.boundingRadius();
    for (const SampleRequest& r : requests) {
        const auto [sx, sy] = samplePosition(r.k, frame_.samples, r.px, r.py);
        const Ray ray =
            frame_.camera.generateRay(r.px + sx, r.py + sy, lensSample(r.k, r.px, r.py));
        auto interval = intersectSphere(ray, radius);
        if (interval) {
            rays_.push(ray, glowing ? 0.0 : interval->tNear, interval->tFar);
            pixel_.push_back(r.target);
            block_.push_back(-1);
        } else if (paths_.bypassing()) {
            bypass_.push_back({ray, r.target});
        }
    }
    stats_.rays += int64_t(requests.size());
    ScalarWaves engine(frame_.fractal, frame_.shader, frame_.camera, frame_.march, frame_.ground,
                       stats_, shading_);
    paths_.trace(engine, tile_, sampleKey, {rays_, pixel_, block_, &bypass_}, pixels, tracking);
}

}  // namespace quaternia
