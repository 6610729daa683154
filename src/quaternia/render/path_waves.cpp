// The paths of path_waves.h: camera rays, then their reflections and refractions, wave by wave.
#include "quaternia/render/path_waves.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace quaternia {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// A child ray whose weight is below this in every channel is not traced: it takes the
// background along its direction (as rays out of bounces do), which keeps the energy (a white
// furnace stays white) and spares the faint branches: a glass's reflections near normal
// incidence (4%) and its internal reflections at exits.
constexpr double kLeastWeight = 0.05;

double largest(const Color& c) {
    return std::max({c.x, c.y, c.z});
}

}  // namespace

void PathWaves::bind(const Shader& shader, const Camera& camera, double boundingRadius,
                     const MaterialSettings& material, const GroundSettings& ground) {
    shader_ = &shader;
    camera_ = &camera;
    boundingRadius_ = boundingRadius;
    material_ = material;
    ground_ = ground;
    active_ = neededFor(material, ground, shader.glowIntensity());
    bypassing_ = ground.enabled || shader.glowIntensity() > 0;
}

double PathWaves::groundDistance(const Ray& ray) const {
    if (!ground_.enabled) return kInfinity;
    const double t = (ground_.height - ray.origin.y) / ray.direction.y;
    return t > 0 ? t : kInfinity;
}

int PathWaves::blockOfPixel(int pixel) const {
    constexpr int kConeBlock = CameraRays::kConeBlock;
    const int width = tile_.x1 - tile_.x0;
    const int across = (width + kConeBlock - 1) / kConeBlock;
    return pixel / width / kConeBlock * across + pixel % width / kConeBlock;
}

void PathWaves::trace(WaveEngine& engine, const Tile& tile, int sampleKey,
                      const CameraRayBatch& camera, std::vector<PixelSamples>& pixels,
                      const DeviationTracking* tracking) {
    engine_ = &engine;
    tile_ = tile;
    sampleKey_ = sampleKey;
    tracking_ = tracking;
    // The camera batch becomes the first wave's (its vectors this one's scratch in turn).
    std::swap(rays_, camera.rays);
    std::swap(rayPath_, camera.pixel);
    std::swap(rayBlock_, camera.block);
    sampleResults_.clear();
    outside_.clear();
    inside_.clear();
    const size_t bypassCount = camera.bypass ? camera.bypass->size() : 0;
    sampleResults_.reserve(rays_.size() + bypassCount);
    outside_.reserve(rays_.size() + bypassCount);
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
                    rayPath_[i], rays_.tNear[i], rayBlock_[i]);
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
    for (size_t i = 0; i < bypassCount; ++i) {
        const BypassRay& b = (*camera.bypass)[i];
        const double ground = glowing ? kInfinity : groundDistance(b.ray);
        if (groundEnds && ground < kInfinity) {
            cameraGround_.push_back({i, ground});
        } else if (glowing || ground < kInfinity) {
            startSample(b.ray, b.pixel, bypassNear, -1);
        }
    }
    if (!cameraGround_.empty()) shadeCameraGround(*camera.bypass, pixels);
    for (bool first = true; !outside_.empty() || !inside_.empty(); first = false) {
        nextOutside_.clear();
        nextInside_.clear();
        if (!outside_.empty()) traceOutsideWave(first, first && !glowing);
        if (!inside_.empty()) traceInsideWave();
        outside_.swap(nextOutside_);
        inside_.swap(nextInside_);
    }
    addEscapes();
    for (const SampleResult& sample : sampleResults_)
        addSample(pixels, sample);
    engine_ = nullptr;
    tracking_ = nullptr;
}

void PathWaves::addSample(std::vector<PixelSamples>& pixels, const SampleResult& s) {
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

void PathWaves::seeBackground(const PathRay& path) {
    // A camera ray's background is the pixel's, composited when it is finished.
    if (path.camera) return;
    addBackground(path.sample, path.weight, path.ray, path.spread);
}

void PathWaves::addBackground(int sample, const Color& weight, const Ray& ray, double spread) {
    if (!shader_->environmentSeen()) {
        sampleResults_[size_t(sample)].color += weight * shader_->background(ray, spread);
        return;
    }
    escapes_.push_back({sample, weight});
    escapeDirections_.push_back(ray.direction);
    escapeSpreads_.push_back(spread);
}

void PathWaves::addEscapes() {
    if (escapes_.empty()) return;  // none without an environment (addBackground)
    escapeRadiance_.resize(escapes_.size());
    shader_->environment()->radianceBatch(escapeDirections_, escapeSpreads_, escapeRadiance_);
    for (size_t i = 0; i < escapes_.size(); ++i)
        sampleResults_[size_t(escapes_[i].sample)].color += escapes_[i].weight * escapeRadiance_[i];
    escapes_.clear();
    escapeDirections_.clear();
    escapeSpreads_.clear();
}

void PathWaves::spawn(const PathRay& parent, const Ray& ray, const Color& weight, double travelled,
                      bool inside, double spread) {
    if (!(largest(weight) > 0)) return;
    if (parent.depth + 1 > material_.maxDepth || largest(weight) < kLeastWeight) {
        // Out of bounces: what is left sees the background, as if it escaped.
        addBackground(parent.sample, weight, ray, spread);
        return;
    }
    // A ray outside the set that meets neither the ground nor the bounding sphere sees the
    // background, as the next wave would find (traceOutsideWave): added now, without a path (a
    // reflecting floor sends millions of them up and away).
    if (!inside) {
        const double ground = ground_.shadowCatcher ? kInfinity : groundDistance(ray);
        if (ground == kInfinity) {
            const auto interval = intersectSphere(ray, boundingRadius_);
            if (!interval || !(std::max(interval->tNear, 0.0) <= interval->tFar)) {
                addBackground(parent.sample, weight, ray, spread);
                return;
            }
        }
    }
    // Made in place: a PathRay is 120 bytes, and a wave spawns millions.
    PathRay& child = (inside ? nextInside_ : nextOutside_).emplace_back();
    child.ray = ray;
    child.sample = parent.sample;
    child.weight = weight;
    child.travelled = travelled;
    child.depth = parent.depth + 1;
    child.spread = spread;
}

size_t PathWaves::keepCameraBatch() {
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
    rayPath_.resize(count);
    for (size_t p = 0; p < count; ++p)
        rayPath_[p] = int(p);
    if (hiddenCount > 0) {
        rays_.removeFlagged(hidden);
        size_t kept = 0;
        for (size_t p = 0; p < count; ++p)
            if (!hidden[p]) rayPath_[kept] = rayPath_[p], rayBlock_[kept++] = rayBlock_[p];
        rayPath_.resize(kept);
        rayBlock_.resize(kept);
    }
    marchedPaths_.assign(rayPath_.begin(), rayPath_.end());
    return count;
}

void PathWaves::collectHits() {
    hits_.clear();
    for (size_t i = 0; i < traced_.size(); ++i) {
        const TraceResult& r = traced_[i];
        if (r.end == TraceEnd::Miss) continue;
        const Ray ray{Point3d(rays_.ox[i], rays_.oy[i], rays_.oz[i]),
                      Vector3d(rays_.dx[i], rays_.dy[i], rays_.dz[i])};
        hits_.push_back({rayPath_[i], rayBlock_[i], r.t, ray.direction, ray.at(r.tOutside)});
    }
}

void PathWaves::traceOutsideWave(bool firstWave, bool cameraBatch) {
    // Only the camera's rays glow (the first wave: all of them camera rays).
    const bool glowing = shader_->glowIntensity() > 0 && !outside_.empty() && outside_[0].camera;
    // The batch: the rays that enter the bounding sphere before the ground.
    if (!cameraBatch) {
        rays_.clear();
        rayPath_.clear();
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
            // behind, its epsilon (the pixel angle times t) is the camera's footprint there.
            const double back = path.travelled;
            rays_.push(Ray{path.ray.at(-back), path.ray.direction}, near + back, far + back);
            rayPath_.push_back(int(p));
            rayBlock_.push_back(path.block);
            marched.push_back(p);
        } else if (ground < kInfinity) {
            groundHits_.push_back({p, ground});
        } else {
            seeBackground(path);
        }
    }
    traced_.clear();
    hits_.clear();
    if (rays_.size() > 0) {
        engine_->marchWave(rays_, glowing, traced_);
        collectHits();  // hits_[h].owner: the index of the path in outside_
    }
    for (size_t i = 0; i < traced_.size(); ++i) {
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
        WaveEngine::HitShading how;
        how.firstWave = firstWave;
        how.lit = material_.transparency < 1 && material_.reflectivity < 1;
        how.traps = passes_ || shader_->albedoUsesOrbit();
        engine_->shadeWave(hits_, how);
        shadeSetHits();
    }
    if (!groundHits_.empty()) shadeGround(firstWave);
}

}  // namespace quaternia
