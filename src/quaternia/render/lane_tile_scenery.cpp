// The scene around the set in the SIMD path (lane_tile_renderer.h): paths of rays that reflect
// off the set and the ground, refract into the set and out of it, and see the ground, the
// background, the fog and the glow. Each wave of rays is one batch of the lanes: the rays
// outside the set are marched as camera rays are and their hits shaded by the same batches
// (shadeHits); the rays inside march by fixed steps (no distance estimate bounds a step inside
// the set, docs/methods.md) and find where they leave it by bisection.
#include <algorithm>
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
    for (const BypassRay& b : bypass_) {
        // Without the glow, a camera ray that skips the set and the ground sees the pixel's
        // background: nothing to follow.
        if (glowing || groundDistance(b.ray) < kInfinity)
            startSample(b.ray, b.pixel, bypassNear, -1);
    }
    const bool cylinders = shadowCylinders_;
    for (bool first = true; !outside_.empty() || !inside_.empty(); first = false) {
        nextOutside_.clear();
        nextInside_.clear();
        // Shadow cylinders group a block's camera rays: the first wave only.
        shadowCylinders_ = cylinders && first;
        secondaryWave_ = !first;
        if (!outside_.empty()) traceOutsideWave(stats);
        shadowCylinders_ = cylinders;
        secondaryWave_ = false;
        if (!inside_.empty()) traceInsideWave(stats);
        outside_.swap(nextOutside_);
        inside_.swap(nextInside_);
    }
    const Color glow = shader_->glowColor() * shader_->glowIntensity();
    for (const SampleResult& s : sampleResults_) {
        // The glow is a layer in front of what the camera ray saw.
        const Color color = glow * s.glow + s.color * (1 - s.glow);
        const double alpha = s.glow + s.alpha * (1 - s.glow);
        if (s.object == 0 && !(alpha > 0)) continue;
        PixelSamples& pixel = pixels[size_t(s.pixel)];
        pixel.sum += color;
        ++pixel.hits;
        pixel.uncovered += 1 - alpha;
        if (s.object == 0) {
            ++pixel.layerHits;
            continue;
        }
        pixel.depthSum += s.depth;
        if (s.object == 2) ++pixel.groundHits;
        if (passes_) {
            pixel.normalSum += s.normal;
            pixel.trapSum += s.trap;
        }
        if (tracking_) {
            float& deviation = deviation_[size_t(s.pixel)];
            deviation = std::max(
                deviation, sampleDeviation(color, secondReference_[size_t(s.pixel)], *shader_));
        }
    }
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

void LaneTileRenderer::traceOutsideWave(LaneTileStats& stats) {
    // Only the camera's rays glow (the first wave: all of them camera rays).
    const bool glowing = shader_->glowIntensity() > 0 && !outside_.empty() && outside_[0].camera;
    // The batch: the rays that enter the bounding sphere before the ground.
    rays_.clear();
    rayPixel_.clear();
    rayBlock_.clear();
    groundHits_.clear();
    std::vector<size_t>& marched = marchedPaths_;
    marched.clear();
    for (size_t p = 0; p < outside_.size(); ++p) {
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
    std::vector<double>& lo = insideLow_;
    std::vector<double>& hi = insideHigh_;
    std::vector<double>& far = insideFar_;
    lo.assign(count, 0.0);
    hi.assign(count, -1.0);
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
            const double t = std::min(lo[active[i]] + h, far[active[i]]);
            points.x[i] = ray.origin.x + ray.direction.x * t;
            points.y[i] = ray.origin.y + ray.direction.y * t;
            points.z[i] = ray.origin.z + ray.direction.z * t;
        }
        estimateDistances(lanes_, points, distances, stats.shading);
        size_t kept = 0;
        for (size_t i = 0; i < n; ++i) {
            const size_t p = active[i];
            const double t = std::min(lo[p] + h, far[p]);
            if (distances[i] > 0 || t >= far[p]) {
                hi[p] = t;
            } else {
                lo[p] = t;
                active[kept++] = p;
            }
        }
        active.resize(kept);
    }
    for (int round = 0; round < kExitBisections; ++round) {
        insidePoints_.clear();
        for (size_t p = 0; p < count; ++p)
            insidePoints_.push(inside_[p].ray.at(0.5 * (lo[p] + hi[p])));
        estimateDistances(lanes_, insidePoints_, distances, stats.shading);
        for (size_t p = 0; p < count; ++p)
            (distances[p] > 0 ? hi[p] : lo[p]) = 0.5 * (lo[p] + hi[p]);
    }
    // The outward normal where each ray leaves, from the estimate there.
    insidePoints_.clear();
    for (size_t p = 0; p < count; ++p)
        insidePoints_.push(inside_[p].ray.at(hi[p]));
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
        const double length = hi[p];
        const double travelled = path.travelled + length;
        // Beer-Lambert over the way inside.
        const Color weight = path.weight * exponential(material_.absorption * -length);
        const double offset = camera_->pixelFootprint(travelled) + 1e-6 * boundingRadius_;
        const Point3d inner = path.ray.at(lo[p]);
        auto out = refract(d, -n, material_.ior, 1);
        if (!out) {  // total internal reflection
            spawn(path, Ray{inner, reflect(d, n)}, weight, travelled, true);
            continue;
        }
        const double reflectance = fresnelDielectric(dot(d, n), material_.ior, 1);
        // Out from the escaped point, a little along the way out (it leaves the surface).
        const Point3d outer = path.ray.at(hi[p]) + *out * offset;
        spawn(path, Ray{outer, *out}, weight * (1 - reflectance), travelled, false);
        spawn(path, Ray{inner, reflect(d, n)}, weight * reflectance, travelled, true);
    }
}

void LaneTileRenderer::shadeGround(LaneTileStats& stats) {
    const size_t count = groundHits_.size();
    const Vector3d up(0, 1, 0);
    auto pointOf = [&](size_t g) { return outside_[groundHits_[g].path].ray.at(groundHits_[g].t); };
    auto normalOf = [&](size_t g) {
        return outside_[groundHits_[g].path].ray.direction.y < 0 ? up : -up;
    };
    const double offset = 1e-6 * boundingRadius_;
    // Each light's visibility at every ground point (1 where it needs no shadow ray).
    auto visibilities = [&](const LightSource& light, std::vector<double>& out) {
        shadowRays_.clear();
        shadowHit_.clear();
        out.assign(count, 1.0);
        if (light.shadows == Shadows::None) return;
        for (size_t g = 0; g < count; ++g) {
            const Point3d x = pointOf(g);
            const KeyLight at = Shader::illumination(light, x);
            if (!(Shader::keyDiffuse(normalOf(g), at) > 0)) continue;
            const Ray ray{x + normalOf(g) * offset, at.toLight};
            auto interval = shader_->shadowIntervalOf(ray, at, light);
            if (!interval) continue;
            shadowRays_.push(ray, interval->tNear, interval->tFar);
            shadowHit_.push_back(int(g));
        }
        clearLitGroundShadows(light, stats);
        marchShadowsOf(light, stats);
        for (size_t r = 0; r < shadowHit_.size(); ++r)
            out[size_t(shadowHit_[r])] = shader_->visibilityOf(light, shadowVisibility_[r]);
    };
    visibilities(shader_->keySource(), groundKeyVisibility_);
    groundColor_.assign(count, Color());
    for (const LightSource& light : shader_->extraLights()) {
        visibilities(light, groundOtherVisibility_);
        for (size_t g = 0; g < count; ++g) {
            const Point3d x = pointOf(g);
            groundColor_[g] += shader_->lightOther(
                light, Shader::illumination(light, x), normalOf(g), ground_.color,
                outside_[groundHits_[g].path].ray.direction, groundOtherVisibility_[g]);
        }
    }
    // The ground's own light, lit in lanes as the set's hits are (lightSurfaces).
    SurfaceBatch& lit = groundSurfaces_;
    lit.resize(count);
    for (size_t g = 0; g < count; ++g) {
        const Vector3d n = normalOf(g);
        const Vector3d& d = outside_[groundHits_[g].path].ray.direction;
        const KeyLight key = shader_->keyLight(pointOf(g));
        const bool facing = Shader::keyDiffuse(n, key) > 0;
        lit.nx[g] = float(n.x), lit.ny[g] = float(n.y), lit.nz[g] = float(n.z);
        lit.dx[g] = float(d.x), lit.dy[g] = float(d.y), lit.dz[g] = float(d.z);
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
    for (size_t g = 0; g < count; ++g) {
        const PathRay& path = outside_[groundHits_[g].path];
        SampleResult& sample = sampleResults_[size_t(path.sample)];
        const double t = groundHits_[g].t;
        const Vector3d n = normalOf(g);
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
        const Color local = Color(lit.red[g], lit.green[g], lit.blue[g]) + groundColor_[g];
        const double cosine = std::abs(path.ray.direction.y);
        const double reflected =
            ground_.reflectivity > 0 ? fresnelSchlick(cosine, ground_.reflectivity) : 0.0;
        const double kept = shader_->fogKept(t);
        sample.color +=
            path.weight * (local * (kept * (1 - reflected)) + shader_->fogColor() * (1 - kept));
        if (reflected > 0) {
            const Ray ray{pointOf(g) + n * offset, reflect(path.ray.direction, n)};
            spawn(path, ray, path.weight * (kept * reflected), path.travelled + t, false);
        }
    }
}

void LaneTileRenderer::marchShadowsOf(const LightSource& light, LaneTileStats& stats) {
    ShadowMarch shadowMarch;
    shadowMarch.minimumStep = shader_->shadowMinimumStep();
    shadowMarch.softness = light.softness;
    shadowMarch.soft = light.shadows == Shadows::Soft;
    shadowMarch.maxSteps = Shader::kShadowSteps;
    shadowMarch.relaxation = Shader::kShadowRelaxation;
    shadowMarch.maxRelaxation = Shader::kShadowMaxRelaxation;
    traceShadowRays(lanes_, shadowMarch, shadowRays_, shadowVisibility_, stats.shading);
}

void LaneTileRenderer::lightOthers(LaneTileStats& stats) {
    for (const LightSource& light : shader_->extraLights()) {
        shadowRays_.clear();
        shadowHit_.clear();
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
            shadowRays_.push(ray, 0, interval->tFar);
            shadowHit_.push_back(int(h));
        }
        marchShadowsOf(light, stats);
        size_t next = 0;
        for (size_t h = 0; h < hits_.size(); ++h) {
            double visibility = 1;
            if (next < shadowHit_.size() && shadowHit_[next] == int(h))
                visibility = shader_->visibilityOf(light, shadowVisibility_[next++]);
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

void LaneTileRenderer::clearLitGroundShadows(const LightSource& light, LaneTileStats& stats) {
    // The shadow rays of a directional light from the ground points of one block of 4x4 camera
    // pixels are parallel and start close together. A cone about them, from the nearest origin
    // along the light, of radius r + s / k at s along it (r holding every origin off its axis,
    // k the penumbra's sharpness; 0 for hard shadows), marched as the camera's cones are (steps
    // of the estimate less the radius, ending where the estimate falls below 1.2 radii), proves
    // where it gets through that every ray of the block passes at h >= t / k from the set at
    // every t along it: min k h / t >= 1, fully lit, and no ray of it need be marched.
    // (Most of the ground sees the light past the set's bounding sphere but far from the set.)
    if (light.kind != LightKind::Directional || shadowHit_.size() < kMinCylinderRays) return;
    const int width = currentTile_.x1 - currentTile_.x0;
    const int across = (width + kConeBlock - 1) / kConeBlock;
    const size_t count = shadowHit_.size();
    std::vector<int>& block = groundBlock_;
    block.resize(count);
    for (size_t r = 0; r < count; ++r) {
        const PathRay& path = outside_[groundHits_[size_t(shadowHit_[r])].path];
        const int pixel = sampleResults_[size_t(path.sample)].pixel;
        block[r] =
            path.camera ? pixel / width / kConeBlock * across + pixel % width / kConeBlock : -1;
    }
    std::vector<int>& order = shadowOrder_;
    order.resize(count);
    for (size_t r = 0; r < count; ++r)
        order[r] = int(r);
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return block[size_t(a)] < block[size_t(b)]; });
    const Vector3d& l = light.direction;
    cylinders_.clear();
    cylinderRays_.clear();
    for (size_t first = 0; first < count;) {
        size_t end = first + 1;
        while (end < count && block[size_t(order[end])] == block[size_t(order[first])])
            ++end;
        if (block[size_t(order[first])] >= 0 && end - first >= kMinCylinderRays) {
            const RayBundle bundle = bundleOf(first, end, l);
            cylinders_.push(Ray{bundle.centre + l * bundle.nearest, l}, 0,
                            bundle.farthest - bundle.nearest);
            cylinders_.spread.push_back(bundle.radius);
            cylinderRays_.push_back({first, end});
        }
        first = end;
    }
    if (cylinders_.size() == 0) return;
    CameraMarch coneMarch = march_;
    coneMarch.cone = true;
    coneMarch.epsilon = 1.2;
    coneMarch.pixelAngle = light.shadows == Shadows::Soft ? 1 / light.softness : 0.0;
    traceCameraRays(lanes_, coneMarch, cylinders_, cylinderResults_, stats.shading);
    shadowClear_.assign(count, 0);
    size_t cleared = 0;
    for (size_t c = 0; c < cylinders_.size(); ++c) {
        const TraceResult& result = cylinderResults_[c];
        const bool whole = result.end == TraceEnd::Miss && result.steps < march_.maxSteps;
        // The cone's start and where it was last clear: before that, every ray of it is lit
        // (k h / t >= 1 there), so its own march starts there.
        const Point3d start(cylinders_.ox[c], cylinders_.oy[c], cylinders_.oz[c]);
        for (size_t i = cylinderRays_[c].first; i < cylinderRays_[c].second; ++i) {
            const size_t r = size_t(order[i]);
            const double clearTo = result.tOutside - dot(shadowRayOrigin(r) - start, l);
            if (whole || clearTo >= shadowRays_.tFar[r]) {
                shadowClear_[r] = 1;
                ++cleared;
            } else {
                shadowRays_.tNear[r] = std::max(shadowRays_.tNear[r], clearTo);
            }
        }
    }
    if (cleared == 0) return;
    shadowRays_.removeFlagged(shadowClear_);
    size_t kept = 0;
    for (size_t r = 0; r < count; ++r)
        if (!shadowClear_[r]) shadowHit_[kept++] = shadowHit_[r];
    shadowHit_.resize(kept);
}

}  // namespace quaternia
