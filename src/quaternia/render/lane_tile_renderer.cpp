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
      lightConstants_(shader.lightConstants()),
      coneRatio_(coneRatio(camera)) {}

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
    coneRatio_ = coneRatio(camera);
}

double LaneTileRenderer::coneRatio(const Camera& camera) {
    // The cone about a block's central ray holds every ray through the block: points at the same
    // t lie within t |d - d_centre| of each other, largest at the block's corners. Through a
    // pinhole, a block subtends the widest angle at the image centre (its angular size falls as
    // cos^2 of the angle off the axis radially, as cos tangentially); the blocks at the centre
    // and the four image corners are measured, and the widest, with a margin, serves all.
    const double width = camera.width(), height = camera.height();
    const double block = kConeBlock;
    double ratio = 0;
    for (auto [cx, cy] :
         {std::pair{0.5 * width, 0.5 * height}, std::pair{0.5 * block, 0.5 * block},
          std::pair{width - 0.5 * block, 0.5 * block}, std::pair{0.5 * block, height - 0.5 * block},
          std::pair{width - 0.5 * block, height - 0.5 * block}}) {
        const Vector3d centre = camera.generateRay(cx, cy).direction;
        for (double dx : {-0.5 * block, 0.5 * block}) {
            for (double dy : {-0.5 * block, 0.5 * block})
                ratio = std::max(ratio,
                                 length(camera.generateRay(cx + dx, cy + dy).direction - centre));
        }
    }
    return ratio * 1.01 + 1e-12;
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
    marchCones(tile, stats);
    for (int k = taken.first; k < taken.end; ++k) {
        sampleKey_ = k;
        sampleRays(tile, k);
        traceInto(pixels, stats);
    }
}

void LaneTileRenderer::sampleRays(const Tile& tile, int k) {
    const int width = tile.x1 - tile.x0;
    const int blocksAcross = (width + kConeBlock - 1) / kConeBlock;
    clearRays();
    for (int py = tile.y0; py < tile.y1; ++py) {
        const double* blockRow =
            blockStart_.data() + size_t((py - tile.y0) / kConeBlock * blocksAcross);
        // A row whose blocks' cones all missed has no ray to march (but its rays may see the
        // ground).
        if (!bypassing_ && std::all_of(blockRow, blockRow + blocksAcross, [](double start) {
                return start == std::numeric_limits<double>::infinity();
            })) {
            continue;
        }
        if (samples_ == 1 && !camera_->thinLens()) {
            rowRays(tile, py, blockRow);
        } else {
            sampleRowRays(tile, py, k);
        }
        pushRowRays(tile, py, blockRow);
    }
}

void LaneTileRenderer::sampleRowRays(const Tile& tile, int py, int k) {
    rowRays_.resize(size_t(tile.x1 - tile.x0));
    for (int px = tile.x0; px < tile.x1; ++px) {
        auto [sx, sy] = samplePosition(k, samples_, px, py);
        const Ray ray = camera_->generateRay(px + sx, py + sy, lensSample(k, px, py));
        RowRay& r = rowRays_[size_t(px - tile.x0)];
        r.origin = ray.origin;
        r.direction = ray.direction;
        auto interval = intersectSphere(ray, boundingRadius_);
        r.tNear = interval ? interval->tNear : 1;
        r.tFar = interval ? interval->tFar : -1;  // none: tNear > tFar
    }
}

void LaneTileRenderer::pushRowRays(const Tile& tile, int py, const double* blockStart) {
    const int width = tile.x1 - tile.x0;
    const int rowBlock = (py - tile.y0) / kConeBlock * ((width + kConeBlock - 1) / kConeBlock);
    for (int px = tile.x0; px < tile.x1; ++px) {
        const int column = (px - tile.x0) / kConeBlock;
        const double start = blockStart[column];
        const RowRay& r = rowRays_[size_t(px - tile.x0)];
        const double near = std::max(r.tNear, start);
        // Not r.tNear <= r.tFar: the sphere or the cone missed, or the cone found nothing on it.
        if (!(near <= r.tFar)) {
            if (bypassing_)
                bypass_.push_back(
                    {Ray{r.origin, r.direction}, (py - tile.y0) * width + (px - tile.x0)});
            continue;
        }
        rays_.push(Ray{r.origin, r.direction}, near, r.tFar);
        rayPixel_.push_back((py - tile.y0) * width + (px - tile.x0));
        rayBlock_.push_back(rowBlock + column);
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

void LaneTileRenderer::rowRays(const Tile& tile, int py, const double* blockStart) {
    // The rays through the pixel centres of the row, as generateRay and intersectSphere give
    // them (the same formulas in the same order), for the pixels of the blocks whose cones did
    // not miss: each run of such blocks in one loop without branches (the square roots and
    // divisions of neighbouring pixels overlap in the pipeline; GCC keeps them scalar, and the
    // branches between them were what cost).
    const int width = tile.x1 - tile.x0;
    const int blocks = (width + kConeBlock - 1) / kConeBlock;
    rowRays_.resize(size_t(width));
    const Camera::RowDirections row = camera_->rowDirections(py);
    const Point3d& o = camera_->position();
    const double c = dot(o, o) - boundingRadius_ * boundingRadius_;
    RowRay* out = rowRays_.data();
    constexpr double kMissed = std::numeric_limits<double>::infinity();
    for (int block = 0; block < blocks;) {
        if (blockStart[block] == kMissed) {
            // Where rays that skip the set still count (bypassing_), their directions alone.
            if (bypassing_) {
                const int end = std::min(width, (block + 1) * kConeBlock);
                for (int i = block * kConeBlock; i < end; ++i) {
                    out[i].origin = o;
                    out[i].direction = normalize(row.first + row.step * double(tile.x0 + i));
                    out[i].tNear = kMissed;
                    out[i].tFar = -1;
                }
            }
            ++block;
            continue;
        }
        const int first = block * kConeBlock;
        while (block < blocks && blockStart[block] != kMissed)
            ++block;
        const int end = std::min(width, block * kConeBlock);
        for (int i = first; i < end; ++i) {
            const Vector3d d = normalize(row.first + row.step * double(tile.x0 + i));
            const double b = dot(o, d);
            const double discriminant = b * b - c;
            const double root = std::sqrt(std::max(0.0, discriminant));
            const double tFar = -b + root;
            out[i].origin = o;
            out[i].direction = d;
            out[i].tNear = std::max(0.0, -b - root);
            // A miss (no real root, or the sphere behind the camera) as an empty interval.
            out[i].tFar = discriminant < 0 || tFar < 0 ? -1.0 : tFar;
        }
    }
}

void LaneTileRenderer::marchCones(const Tile& tile, LaneTileStats& stats) {
    const int width = tile.x1 - tile.x0, height = tile.y1 - tile.y0;
    const int across = (width + kConeBlock - 1) / kConeBlock;
    const int down = (height + kConeBlock - 1) / kConeBlock;
    blockStart_.assign(size_t(across * down), 0.0);
    // A thin lens's rays leave from all over the lens: no cone from the pinhole holds them, so
    // each starts where it enters the bounding sphere.
    if (camera_->thinLens()) return;
    cones_.clear();
    coneBlock_.clear();
    std::vector<Ray>& centres = coneCentres_;
    centres.clear();
    for (int by = 0; by < down; ++by) {
        for (int bx = 0; bx < across; ++bx) {
            const double x0 = tile.x0 + bx * kConeBlock, y0 = tile.y0 + by * kConeBlock;
            const double x1 = std::min<double>(x0 + kConeBlock, tile.x1);
            const double y1 = std::min<double>(y0 + kConeBlock, tile.y1);
            centres.push_back(camera_->generateRay(0.5 * (x0 + x1), 0.5 * (y0 + y1)));
        }
    }
    const double ratio = coneRatio_;
    // Every ray of the block is inside the bounding sphere only where the central ray is inside
    // the sphere grown by the cone's widest radius there.
    const double farthest = length(centres.front().origin) + boundingRadius_;
    for (size_t b = 0; b < centres.size(); ++b) {
        auto interval = intersectSphere(centres[b], boundingRadius_ + ratio * farthest);
        if (!interval) {
            blockStart_[b] = std::numeric_limits<double>::infinity();
            continue;
        }
        cones_.push(centres[b], interval->tNear, interval->tFar);
        coneBlock_.push_back(int(b));
    }
    CameraMarch coneMarch = march_;
    coneMarch.cone = true;
    // Cones stop at 1.2 radii: at 1.5, case01 took 2.7% and the default scene 3.5% more march
    // steps in all (2 took 9% more steps of the pixel rays than 1.5); below 1.2 little changes.
    coneMarch.epsilon = 1.2;
    coneMarch.pixelAngle = ratio;
    traceCameraRays(lanes_, coneMarch, cones_, coneResults_, stats.camera);
    for (size_t i = 0; i < coneResults_.size(); ++i) {
        const TraceResult& r = coneResults_[i];
        stats.marchSteps += r.steps;
        double& start = blockStart_[size_t(coneBlock_[i])];
        if (r.end == TraceEnd::Miss && r.steps < march_.maxSteps) {
            // With a glow, the rays near the set that it missed are marched all the same: their
            // least estimates are the glow's.
            start = shader_->glowIntensity() > 0 ? 0.0 : std::numeric_limits<double>::infinity();
        } else {
            // Start the block's rays at the cone's last point whose ball was clear: the set is
            // not on them before it, and the point itself is outside, where normals are taken.
            start = r.tOutside;
        }
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
}

void LaneTileRenderer::hitNormals(LaneTileStats& stats) {
    const size_t count = hits_.size();
    // The estimate at each hit's outside point, where the orbit colours the surface: its
    // iteration count is then the M of the analytic normal (JuliaSet::gradientIterations).
    // Without orbit colouring, the normals find their M themselves.
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
