// What becomes of the paths' rays at surfaces (path_waves.h): at the set's hits the split into
// the surface's own light, the mirror and the refraction (Schlick's and the dielectric's
// reflectance, glossy lobes); inside the set the fixed steps to the exit, Snell's law and
// Beer-Lambert absorption there; at the ground its light, the shadow catcher and its mirror.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "quaternia/render/optics.h"
#include "quaternia/render/path_waves.h"
#include "quaternia/render/sample_pattern.h"

namespace quaternia {
namespace {

// Bisection rounds of a refracted ray's exit: the step over 64.
constexpr int kExitBisections = 6;

Color exponential(const Color& c) {
    return Color(std::exp(c.x), std::exp(c.y), std::exp(c.z));
}

}  // namespace

Vector3d PathWaves::glossy(const Vector3d& mirror, const Vector3d& n, const SampleResult& sample,
                           int depth) const {
    // The pixel's samples share the lobe out: one point of the ball per pixel sample.
    const uint32_t key = uint32_t(sample.key), salt = uint32_t(depth);
    const uint32_t pixel =
        uint32_t(sample.pixel) + 7919u * uint32_t(tile_.x0) + 104729u * uint32_t(tile_.y0);
    const double u = hashUnit(pixel, key, salt), v = hashUnit(pixel, key, salt + 97);
    const double w = hashUnit(pixel, key, salt + 193);
    const double z = 2 * u - 1, phi = 2 * M_PI * v, r = std::sqrt(1 - z * z);
    const Vector3d ball = Vector3d(r * std::cos(phi), r * std::sin(phi), z) * std::cbrt(w);
    const Vector3d direction = normalize(mirror + ball * material_.roughness);
    return dot(direction, n) > 0 ? direction : mirror;
}

void PathWaves::shadeSetHits() {
    const double transparency = material_.transparency;
    const bool traps = passes_ || shader_->albedoUsesOrbit();
    const std::vector<Vector3d>& normals = engine_->normals();
    for (size_t h = 0; h < hits_.size(); ++h) {
        const PathRay& path = outside_[size_t(hits_[h].owner)];
        SampleResult& sample = sampleResults_[size_t(path.sample)];
        const double t = hits_[h].t - path.travelled;  // along this ray
        const Vector3d& n = normals[h];
        const Vector3d& d = hits_[h].direction;
        if (path.camera) {
            sample.object = 1;
            sample.alpha = 1;
            sample.depth = t;
            sample.normal = n;
            if (traps) sample.trap = engine_->trap(h);
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
        const Color local = engine_->colour(h);
        sample.color += path.weight * (local * (kept * own) + shader_->fogColor() * (1 - kept));
        const double travelled = hits_[h].t;
        const double footprint = camera_->pixelFootprint(travelled);
        if (reflected > 0) {
            Vector3d direction = reflect(d, n);
            if (material_.roughness > 0) direction = glossy(direction, n, sample, path.depth);
            const Ray ray{shader_->shadowOrigin(hits_[h].outside, n, footprint), direction};
            // Half the lobe's blur from the environment's pre-filtered levels, so that one
            // sample already shows it smooth; the rest from the sampled directions, as the set's
            // own reflections get it.
            spawn(path, ray, path.weight * (kept * reflected), travelled, false,
                  0.5 * material_.roughness);
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

void PathWaves::traceInsideWave() {
    // Fixed steps of h from each ray's origin until a point escapes, then bisection of the
    // last step: the exit lies within h / 2^kExitBisections of the point found, and any gap of
    // the set narrower than h may be stepped over (docs/rendering.md, Transparency).
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
    // than the batches saved).
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
        engine_->outsideDistances(points, distances);
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
        engine_->outsideDistances(insidePoints_, distances);
        for (size_t p = 0; p < count; ++p)
            bracket[p][distances[p] > 0] = 0.5 * (bracket[p][0] + bracket[p][1]);
    }
    // The outward normal where each ray leaves.
    insidePoints_.clear();
    for (size_t p = 0; p < count; ++p)
        insidePoints_.push(inside_[p].ray.at(bracket[p][1]));
    engine_->outwardNormals(insidePoints_, exitNormals_);
    for (size_t p = 0; p < count; ++p) {
        const PathRay& path = inside_[p];
        const Vector3d& d = path.ray.direction;
        Vector3d n = exitNormals_[p];
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

void PathWaves::shadeGround(bool firstWave) {
    groundPoints_.clear();
    for (const GroundHit& hit : groundHits_) {
        const PathRay& path = outside_[hit.path];
        const int block =
            path.camera ? blockOfPixel(sampleResults_[size_t(path.sample)].pixel) : -1;
        groundPoints_.push_back({path.ray.at(hit.t), path.ray.direction, block});
    }
    engine_->lightGround(groundPoints_, firstWave);
    const std::vector<Color>& colour = engine_->groundColour();
    const std::vector<double>& keyVisibility = engine_->groundKeyVisibility();
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
                sample.alpha = 1 - keyVisibility[g];
                continue;
            }
            sample.alpha = 1;
        }
        const double cosine = std::abs(path.ray.direction.y);
        const double reflected =
            ground_.reflectivity > 0 ? fresnelSchlick(cosine, ground_.reflectivity) : 0.0;
        const double kept = shader_->fogKept(t);
        sample.color +=
            path.weight * (colour[g] * (kept * (1 - reflected)) + shader_->fogColor() * (1 - kept));
        if (reflected > 0) {
            const Ray ray{groundPoints_[g].x + n * offset, reflect(path.ray.direction, n)};
            spawn(path, ray, path.weight * (kept * reflected), path.travelled + t, false);
        }
    }
}

void PathWaves::shadeCameraGround(const std::vector<BypassRay>& bypass,
                                  std::vector<PixelSamples>& pixels) {
    groundPoints_.clear();
    for (const GroundHit& hit : cameraGround_) {
        const BypassRay& camera = bypass[hit.path];
        groundPoints_.push_back(
            {camera.ray.at(hit.t), camera.ray.direction, blockOfPixel(camera.pixel)});
    }
    engine_->lightGround(groundPoints_, true);
    const std::vector<Color>& colour = engine_->groundColour();
    const std::vector<double>& keyVisibility = engine_->groundKeyVisibility();
    // As shadeGround's camera rays, with nothing reflected. (One sample result for all: a new
    // one per point cost more than the rest of the loop.)
    SampleResult sample;
    sample.object = 2;
    for (size_t g = 0; g < cameraGround_.size(); ++g) {
        sample.pixel = bypass[cameraGround_[g].path].pixel;
        sample.depth = cameraGround_[g].t;
        sample.normal = groundPoints_[g].normal();
        if (ground_.shadowCatcher) {
            sample.alpha = 1 - keyVisibility[g];
        } else {
            sample.alpha = 1;
            const double kept = shader_->fogKept(sample.depth);
            sample.color = colour[g] * kept + shader_->fogColor() * (1 - kept);
        }
        addSample(pixels, sample);
    }
}

}  // namespace quaternia
