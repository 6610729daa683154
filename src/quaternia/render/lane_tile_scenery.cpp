// The scene around the set in the SIMD path (lane_tile_renderer.h): paths of rays that reflect
// off the set and the ground, refract into the set and out of it, and see the ground, the
// background, the fog and the glow. Each wave of rays is one batch of the lanes: the rays
// outside the set are marched as camera rays are and their hits shaded by the same batches
// (shadeHits); the rays inside march by fixed steps (no distance estimate bounds a step inside
// the set, docs/methods.md) and find where they leave it by bisection.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "quaternia/render/lane_tile_renderer.h"
#include "quaternia/render/render.h"

namespace quaternia {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// A child ray whose weight is below this in every channel is not traced: it takes the
// background along its direction (as rays out of bounces do), which keeps the energy (a white
// furnace stays white) and spares the faint branches: a glass's reflections near normal
// incidence (4%) and its internal reflections at exits.
constexpr double kLeastWeight = 0.05;
// Bisection rounds of a refracted ray's exit: the step over 64.
constexpr int kExitBisections = 6;

double largest(const Color& c) {
    return std::max({c.x, c.y, c.z});
}

Color exponential(const Color& c) {
    return Color(std::exp(c.x), std::exp(c.y), std::exp(c.z));
}

// A hash of three integers to [0, 1) (Wang-style integer mixing), for the glossy directions:
// the same for the same pixel sample in every run.
double hashUnit(uint32_t a, uint32_t b, uint32_t c) {
    uint32_t h =
        a * 0x9E3779B1u ^ (b + 0x7F4A7C15u) * 0x85EBCA77u ^ (c + 0x165667B1u) * 0xC2B2AE3Du;
    h ^= h >> 16;
    h *= 0x7FEB352Du;
    h ^= h >> 15;
    h *= 0x846CA68Bu;
    h ^= h >> 16;
    return double(h) / 4294967296.0;
}

}  // namespace

void LaneTileRenderer::setScenery(const MaterialSettings& material, const GroundSettings& ground) {
    material_ = material;
    ground_ = ground;
    scenery_ = material.reflectivity > 0 || material.transparency > 0 || ground.enabled ||
               shader_->glowIntensity() > 0;
    bypassing_ = ground.enabled || shader_->glowIntensity() > 0;
}

double LaneTileRenderer::groundDistance(const Ray& ray) const {
    if (!ground_.enabled) return kInfinity;
    const double t = (ground_.height - ray.origin.y) / ray.direction.y;
    return t > 0 ? t : kInfinity;
}

void LaneTileRenderer::tracePaths(std::vector<PixelSamples>& pixels, LaneTileStats& stats) {
    sampleResults_.clear();
    outside_.clear();
    inside_.clear();
    sampleResults_.reserve(rays_.size() + bypass_.size());
    outside_.reserve(rays_.size() + bypass_.size());
    auto startSample = [&](const Ray& ray, int pixel, double tNear, int block) {
        SampleResult& result = sampleResults_.emplace_back();
        result.pixel = pixel;
        result.key = sampleKey_ >= 0 ? sampleKey_ : pixels[size_t(pixel)].samples;
        PathRay& path = outside_.emplace_back();
        path.ray = ray;
        path.tNear = tNear;
        path.sample = int(sampleResults_.size() - 1);
        path.weight = Color(1, 1, 1);
        path.camera = true;
        path.block = block;
    };
    for (size_t i = 0; i < rays_.size(); ++i) {
        startSample(Ray{Point3d(rays_.ox[i], rays_.oy[i], rays_.oz[i]),
                        Vector3d(rays_.dx[i], rays_.dy[i], rays_.dz[i])},
                    rayPixel_[i], rays_.tNear[i], rayBlock_[i]);
    }
    // The rays that skip the set: never marched (tNear infinite), but for the glow, which
    // reaches past the bounding sphere.
    const bool glowing = shader_->glowIntensity() > 0;
    const double bypassNear = glowing ? 0.0 : kInfinity;
    // Without the glow, a camera ray that skips the set and the ground sees the pixel's
    // background: nothing to follow; one that sees the ground, which reflects nothing, ends
    // there (shadeCameraGround).
    const bool groundEnds = groundShortcut_ && !glowing && !(ground_.reflectivity > 0);
    cameraGround_.clear();
    for (size_t i = 0; i < bypass_.size(); ++i) {
        const BypassRay& b = bypass_[i];
        const double ground = glowing ? kInfinity : groundDistance(b.ray);
        if (groundEnds && ground < kInfinity) {
            cameraGround_.push_back({i, ground});
        } else if (glowing || ground < kInfinity) {
            startSample(b.ray, b.pixel, bypassNear, -1);
        }
    }
    if (!cameraGround_.empty()) shadeCameraGround(pixels, stats);
    const bool cylinders = shadowCylinders_;
    for (bool first = true; !outside_.empty() || !inside_.empty(); first = false) {
        nextOutside_.clear();
        nextInside_.clear();
        // Shadow cylinders group a block's camera rays: the first wave only.
        shadowCylinders_ = cylinders && first;
        secondaryWave_ = !first;
        if (!outside_.empty()) traceOutsideWave(stats, first && !glowing);
        shadowCylinders_ = cylinders;
        secondaryWave_ = false;
        if (!inside_.empty()) traceInsideWave(stats);
        outside_.swap(nextOutside_);
        inside_.swap(nextInside_);
    }
    for (const SampleResult& sample : sampleResults_)
        addSample(pixels, sample);
}

void LaneTileRenderer::addSample(std::vector<PixelSamples>& pixels, const SampleResult& s) {
    // The glow is a layer in front of what the camera ray saw.
    const Color color =
        shader_->glowColor() * shader_->glowIntensity() * s.glow + s.color * (1 - s.glow);
    const double alpha = s.glow + s.alpha * (1 - s.glow);
    if (s.object == 0 && !(alpha > 0)) return;
    PixelSamples& pixel = pixels[size_t(s.pixel)];
    pixel.sum += color;
    ++pixel.hits;
    pixel.uncovered += 1 - alpha;
    if (s.object == 0) {
        ++pixel.layerHits;
        return;
    }
    pixel.depthSum += s.depth;
    if (s.object == 2) ++pixel.groundHits;
    if (passes_) {
        pixel.normalSum += s.normal;
        pixel.trapSum += s.trap;
    }
    if (tracking_) tracking_->add(s.pixel, color, *shader_);
}

void LaneTileRenderer::seeBackground(const PathRay& path) {
    // A camera ray's background is the pixel's, composited when it is finished.
    if (path.camera) return;
    sampleResults_[size_t(path.sample)].color += path.weight * shader_->background(path.ray);
}

void LaneTileRenderer::spawn(const PathRay& parent, const Ray& ray, const Color& weight,
                             double travelled, bool inside) {
    if (!(largest(weight) > 0)) return;
    if (parent.depth + 1 > material_.maxDepth || largest(weight) < kLeastWeight) {
        // Out of bounces: what is left sees the background, as if it escaped.
        sampleResults_[size_t(parent.sample)].color += weight * shader_->background(ray);
        return;
    }
    PathRay child;
    child.ray = ray;
    child.sample = parent.sample;
    child.weight = weight;
    child.travelled = travelled;
    child.depth = parent.depth + 1;
    (inside ? nextInside_ : nextOutside_).push_back(child);
}

size_t LaneTileRenderer::keepCameraBatch() {
    const size_t count = rays_.size();
    std::vector<uint8_t>& hidden = groundHidden_;
    hidden.assign(count, 0);
    size_t hiddenCount = 0;
    for (size_t p = 0; p < count; ++p) {
        const double ground = groundDistance(outside_[p].ray);
        if (ground < rays_.tNear[p]) {
            hidden[p] = 1;
            ++hiddenCount;
            groundHits_.push_back({p, ground});
        } else {
            rays_.tFar[p] = std::min(rays_.tFar[p], ground);
        }
    }
    rayPixel_.resize(count);  // hits_[h].pixel: the path
    for (size_t p = 0; p < count; ++p)
        rayPixel_[p] = int(p);
    if (hiddenCount > 0) {
        rays_.removeFlagged(hidden);
        size_t kept = 0;
        for (size_t p = 0; p < count; ++p)
            if (!hidden[p]) rayPixel_[kept] = rayPixel_[p], rayBlock_[kept++] = rayBlock_[p];
        rayPixel_.resize(kept);
        rayBlock_.resize(kept);
    }
    marchedPaths_.assign(rayPixel_.begin(), rayPixel_.end());
    return count;
}

void LaneTileRenderer::traceOutsideWave(LaneTileStats& stats, bool cameraBatch) {
    // Only the camera's rays glow (the first wave: all of them camera rays).
    const bool glowing = shader_->glowIntensity() > 0 && !outside_.empty() && outside_[0].camera;
    // The batch: the rays that enter the bounding sphere before the ground.
    if (!cameraBatch) {
        rays_.clear();
        rayPixel_.clear();
        rayBlock_.clear();
    }
    groundHits_.clear();
    std::vector<size_t>& marched = marchedPaths_;
    marched.clear();
    // The first wave without the glow: the camera rays of rays_ (the first paths of outside_)
    // are the batch as the loop below would make it, but for the ground, which cuts them short
    // (and takes those it hides the sphere from).
    const size_t kept = cameraBatch ? keepCameraBatch() : 0;
    for (size_t p = kept; p < outside_.size(); ++p) {
        const PathRay& path = outside_[p];
        // A shadow catcher is only for the camera: other rays see through it.
        const double ground =
            ground_.shadowCatcher && !path.camera ? kInfinity : groundDistance(path.ray);
        // The glow reaches glowReach past the bounding sphere (exp(-8) of its opacity).
        const double glowReach = glowing ? 8 * shader_->glowRadius() : 0.0;
        // (A camera ray that skips the set, tNear infinite, needs no sphere.)
        auto interval = path.tNear == kInfinity
                            ? std::nullopt
                            : intersectSphere(path.ray, boundingRadius_ + glowReach);
        const double near = interval ? std::max(interval->tNear, path.tNear) : kInfinity;
        const double far = interval ? std::min(interval->tFar, ground) : -1;
        if (near <= far) {
            // A ray of a path starts where the path has come to; marched from a point as far
            // behind, its epsilon (march_.pixelAngle t) is the camera's footprint there.
            const double back = path.travelled;
            rays_.push(Ray{path.ray.at(-back), path.ray.direction}, near + back, far + back);
            rayPixel_.push_back(int(p));
            rayBlock_.push_back(path.block);
            marched.push_back(p);
        } else if (ground < kInfinity) {
            groundHits_.push_back({p, ground});
        } else {
            seeBackground(path);
        }
    }
    if (rays_.size() > 0) {
        CameraMarch march = march_;
        march.closest = glowing;
        traceCameraRays(lanes_, march, rays_, traced_, stats.camera);
        collectHits(stats);  // hits_[h].pixel: the index of the path in outside_
    } else {
        hits_.clear();
        hitPoints_.clear();
    }
    for (size_t i = 0; i < traced_.size() && rays_.size() > 0; ++i) {
        const PathRay& path = outside_[marched[i]];
        if (traced_[i].end != TraceEnd::Miss) continue;
        // The glow: about the set, on the camera rays that pass it.
        if (path.camera && glowing)
            sampleResults_[size_t(path.sample)].glow = shader_->glowOpacity(traced_[i].closest);
        const double ground =
            ground_.shadowCatcher && !path.camera ? kInfinity : groundDistance(path.ray);
        if (ground < kInfinity) {
            groundHits_.push_back({marched[i], ground});
        } else {
            seeBackground(path);
        }
    }
    if (!hits_.empty()) {
        // hits_[h].t is the length of the whole path (its footprint's). A surface that
        // reflects or refracts all light (a mirror, clear glass) shows none of its own: its
        // hits need their normals but no shadow rays, occlusion or lights.
        if (material_.transparency < 1 && material_.reflectivity < 1) {
            shadeHits(stats);
        } else {
            hitNormals(stats);
            surfaces_.resize(hits_.size());
            std::fill(surfaces_.red.begin(), surfaces_.red.end(), 0.0f);
            std::fill(surfaces_.green.begin(), surfaces_.green.end(), 0.0f);
            std::fill(surfaces_.blue.begin(), surfaces_.blue.end(), 0.0f);
        }
        shadeSetHits();
    }
    if (!groundHits_.empty()) shadeGround(stats);
}

void LaneTileRenderer::shadeSetHits() {
    const double transparency = material_.transparency;
    for (size_t h = 0; h < hits_.size(); ++h) {
        const PathRay& path = outside_[size_t(hits_[h].pixel)];
        SampleResult& sample = sampleResults_[size_t(path.sample)];
        const double t = hits_[h].t - path.travelled;  // along this ray
        const Vector3d& n = normals_[h];
        const Vector3d& d = hits_[h].direction;
        if (path.camera) {
            sample.object = 1;
            sample.alpha = 1;
            sample.depth = t;
            sample.normal = n;
            if (passes_ || shader_->albedoUsesOrbit()) sample.trap = hitEstimates_[h].trap;
        }
        const double cosine = std::max(0.0, -dot(d, n));
        // The light that leaves: the surface's own (1 - transparency), of which Schlick's
        // reflectance reflects, and the glass's (transparency), of which the dielectric's
        // reflects and the rest refracts in.
        const double mirror =
            material_.reflectivity > 0 ? fresnelSchlick(cosine, material_.reflectivity) : 0.0;
        const double dielectric =
            transparency > 0 ? fresnelDielectric(cosine, 1, material_.ior) : 0.0;
        const double reflected = (1 - transparency) * mirror + transparency * dielectric;
        const double refracted = transparency * (1 - dielectric);
        const double own = (1 - transparency) * (1 - mirror);
        const double kept = shader_->fogKept(t);
        const Color local(surfaces_.red[h], surfaces_.green[h], surfaces_.blue[h]);
        sample.color += path.weight * (local * (kept * own) + shader_->fogColor() * (1 - kept));
        const double travelled = hits_[h].t;
        const double footprint = camera_->pixelFootprint(travelled);
        if (reflected > 0) {
            Vector3d direction = reflect(d, n);
            if (material_.roughness > 0) {
                // Glossy: the mirror direction moved by a point of the ball of radius
                // roughness, one per pixel sample (the pixel's samples share the lobe out).
                const uint32_t key = uint32_t(sample.key), salt = uint32_t(path.depth);
                const uint32_t pixel = uint32_t(sample.pixel) + 7919u * uint32_t(currentTile_.x0) +
                                       104729u * uint32_t(currentTile_.y0);
                const double u = hashUnit(pixel, key, salt), v = hashUnit(pixel, key, salt + 97);
                const double w = hashUnit(pixel, key, salt + 193);
                const double z = 2 * u - 1, phi = 2 * M_PI * v, r = std::sqrt(1 - z * z);
                const Vector3d ball =
                    Vector3d(r * std::cos(phi), r * std::sin(phi), z) * std::cbrt(w);
                const Vector3d glossy = normalize(direction + ball * material_.roughness);
                if (dot(glossy, n) > 0) direction = glossy;
            }
            const Ray ray{shader_->shadowOrigin(hits_[h].outside, n, footprint), direction};
            spawn(path, ray, path.weight * (kept * reflected), travelled, false);
        }
        if (refracted > 0) {
            // Entering from outside never reflects totally.
            // From the ray's end, the first point inside (or within epsilon of the surface),
            // not moved off the ray: a move along the normal would shift the refracted line by
            // a footprint and lengthen a grazing chord.
            const Vector3d direction = *refract(d, n, 1, material_.ior);
            spawn(path, Ray{path.ray.at(t), direction}, path.weight * (kept * refracted), travelled,
                  true);
        }
    }
}

void LaneTileRenderer::traceInsideWave(LaneTileStats& stats) {
    // Fixed steps of h from each ray's origin until a point escapes, then bisection of the
    // last step: the exit lies within h / 2^kExitBisections of the point found, and any gap of
    // the set narrower than h may be stepped over (docs/methods.md, Transparency).
    const double h = 2 * boundingRadius_ / material_.insideSteps;
    const size_t count = inside_.size();
    // Each ray's bracket of its exit: [0] the last point inside, [1] the first outside (-1
    // until found). Indexed by a comparison, so that the loops below update it without
    // branches: which way each ray goes is as good as random, and the branches cost more than
    // the rest of the loops.
    std::vector<std::array<double, 2>>& bracket = insideBracket_;
    std::vector<double>& far = insideFar_;
    bracket.assign(count, {0.0, -1.0});
    far.resize(count);
    std::vector<size_t>& active = insideActive_;
    active.clear();
    for (size_t p = 0; p < count; ++p) {
        auto interval = intersectSphere(inside_[p].ray, boundingRadius_);
        far[p] = interval ? std::max(0.0, interval->tFar) : 0.0;
        active.push_back(p);
    }
    // Step by step, the rays still inside in one batch each (a batch of every step's points at
    // once, to the sphere's far side, took 1.6x as long: the points past the exits cost more
    // than the batches saved). Membership alone (the distance is 0 exactly inside K_N):
    // estimateDistances skips the orbit's bookkeeping.
    std::vector<double>& distances = insideDistances_;
    PointBatch& points = insidePoints_;
    while (!active.empty()) {
        const size_t n = active.size();
        points.x.resize(n), points.y.resize(n), points.z.resize(n);
        for (size_t i = 0; i < n; ++i) {
            const Ray& ray = inside_[active[i]].ray;
            const double t = std::min(bracket[active[i]][0] + h, far[active[i]]);
            points.x[i] = ray.origin.x + ray.direction.x * t;
            points.y[i] = ray.origin.y + ray.direction.y * t;
            points.z[i] = ray.origin.z + ray.direction.z * t;
        }
        estimateDistances(lanes_, points, distances, stats.shading);
        size_t kept = 0;
        for (size_t i = 0; i < n; ++i) {
            const size_t p = active[i];
            const double t = std::min(bracket[p][0] + h, far[p]);
            const bool left = distances[i] > 0 || t >= far[p];
            bracket[p][left] = t;
            active[kept] = p;
            kept += !left;
        }
        active.resize(kept);
    }
    for (int round = 0; round < kExitBisections; ++round) {
        insidePoints_.clear();
        for (size_t p = 0; p < count; ++p)
            insidePoints_.push(inside_[p].ray.at(0.5 * (bracket[p][0] + bracket[p][1])));
        estimateDistances(lanes_, insidePoints_, distances, stats.shading);
        for (size_t p = 0; p < count; ++p)
            bracket[p][distances[p] > 0] = 0.5 * (bracket[p][0] + bracket[p][1]);
    }
    // The outward normal where each ray leaves, from the estimate there.
    insidePoints_.clear();
    for (size_t p = 0; p < count; ++p)
        insidePoints_.push(inside_[p].ray.at(bracket[p][1]));
    estimatePoints(lanes_, insidePoints_, insideEstimates_, stats.shading);
    gradientIterations_.resize(count);
    for (size_t p = 0; p < count; ++p)
        gradientIterations_[p] = gradientIterationsOf(insideEstimates_[p], lanes_.maxIterations);
    potentialNormals(lanes_, insidePoints_, gradientIterations_, normals_, stats.shading);
    for (size_t p = 0; p < count; ++p) {
        const PathRay& path = inside_[p];
        const Vector3d& d = path.ray.direction;
        Vector3d n = normals_[p];
        if (dot(n, d) < 0) n = -n;  // outward, along the ray
        const double length = bracket[p][1];
        const double travelled = path.travelled + length;
        // Beer-Lambert over the way inside.
        const Color weight = path.weight * exponential(material_.absorption * -length);
        const double offset = camera_->pixelFootprint(travelled) + 1e-6 * boundingRadius_;
        const Point3d inner = path.ray.at(bracket[p][0]);
        auto out = refract(d, -n, material_.ior, 1);
        if (!out) {  // total internal reflection
            spawn(path, Ray{inner, reflect(d, n)}, weight, travelled, true);
            continue;
        }
        const double reflectance = fresnelDielectric(dot(d, n), material_.ior, 1);
        // Out from the escaped point, a little along the way out (it leaves the surface).
        const Point3d outer = path.ray.at(bracket[p][1]) + *out * offset;
        spawn(path, Ray{outer, *out}, weight * (1 - reflectance), travelled, false);
        spawn(path, Ray{inner, reflect(d, n)}, weight * reflectance, travelled, true);
    }
}

void LaneTileRenderer::marchShadowsOf(const LightSource& light, LaneTileStats& stats) {
    shadows_.march(lanes_, shadowMarchOf(light, *shader_), stats.shading);
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
        marchShadowsOf(light, stats);
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
