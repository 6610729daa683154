// The SIMD path of render(): a tile's camera rays marched together in lanes, then its hits
// shaded in batches (normals, shadow rays, ambient occlusion), each batch one call of the lanes
// (lanes/march_lanes.h), and lit together (shading_lanes.h, Shader::light's formula), so
// both paths make the same picture up to the precision of the lanes.
#pragma once

#include <array>
#include <utility>
#include <vector>

#include "quaternia/render/adaptive_driver.h"
#include "quaternia/render/adaptive_sampling.h"
#include "quaternia/render/camera.h"
#include "quaternia/render/camera_rays.h"
#include "quaternia/render/ground_lighting.h"
#include "quaternia/render/lane_environment.h"
#include "quaternia/render/lanes/march_lanes.h"
#include "quaternia/render/march.h"
#include "quaternia/render/path_waves.h"
#include "quaternia/render/sample_pattern.h"
#include "quaternia/render/shade.h"
#include "quaternia/render/shadow_rays.h"
#include "quaternia/util/parallel.h"

namespace quaternia {

// Work of one tile, for RenderStats.
struct LaneTileStats {
    int64_t rays = 0;  // camera rays (samples taken, the border's of adaptive sampling among them)
    int64_t marchSteps = 0;
    LaneCounters camera, shading;
};

// One per thread: owns the batches, so that after the first tiles nothing is allocated.
class LaneTileRenderer : private SampleTracer, private WaveEngine {
  public:
    // shadowCylinders: hard shadow rays are shortened by a cylinder per block (clipShadowRays),
    // which changes no pixel; false only to check that. adaptive: adaptive sampling
    // (adaptive_sampling.h) where samples > 1.
    LaneTileRenderer(const LaneFractal& lanes, const Camera& camera, const Shader& shader,
                     const MarchSettings& march, int samples, bool shadowCylinders = true,
                     bool adaptive = false);

    // The renderer of another frame, its batches kept: the same pixels as a new one would
    // make (shadowCylinders stays).
    void rebind(const LaneFractal& lanes, const Camera& camera, const Shader& shader,
                const MarchSettings& march, int samples, bool adaptive = false);
    // Whether the pixels also sum their hits' normals and orbit traps (RenderOptions::passes).
    void setPasses(bool passes) {
        passes_ = passes;
        paths_.setPasses(passes);
    }
    // The set's material and the ground (path_waves.h); call after rebind too.
    void setScenery(const MaterialSettings& material, const GroundSettings& ground) {
        paths_.bind(*shader_, *camera_, boundingRadius_, material, ground);
    }
    // Whether camera rays that see only a ground that reflects nothing end there without the
    // paths (PathWaves::setGroundShortcut), which changes no pixel; false only to check that.
    void setGroundShortcut(bool shortcut) { paths_.setGroundShortcut(shortcut); }
    // Uniform sampling's sample k of the `samples` alone in every pixel (RenderOptions::
    // onlySample); -1: every sample (or adaptive sampling where asked for).
    void setOnlySample(int k) { onlySample_ = k; }

    // Marches and shades the samples of every pixel of the tile (all of them, or adaptively);
    // pixels[(y - y0) * width + (x - x0)] receives the sums of pixel (x, y).
    void render(const Tile& tile, std::vector<PixelSamples>& pixels, LaneTileStats& stats);

  private:
    void renderUniform(const Tile& tile, std::vector<PixelSamples>& pixels, LaneTileStats& stats);
    // Adaptive sampling: renderAdaptively (adaptive_driver.h) with this renderer as its tracer
    // (lane_tile_adaptive.cpp): the first samples of the tile and of its border in one batch,
    // then the rounds of later samples in batches of about a tile's rays.
    void renderAdaptive(const Tile& tile, std::vector<PixelSamples>& pixels, LaneTileStats& stats);
    void traceFirstSamples(const Tile& tile, std::span<const SampleRequest> requests,
                           std::vector<PixelSamples>& firstPass) override;
    void traceRound(std::span<const SampleRequest> round, std::vector<PixelSamples>& pixels,
                    const DeviationTracking* tracking, bool last) override;
    AdaptiveScratch adaptiveScratch_;
    Tile adaptiveBlocks_{};                   // the cone blocks of the tile and its border
    LaneTileStats* adaptiveStats_ = nullptr;  // the tile's, while renderAdaptive runs
    void clearRays();
    // The camera rays of the tile (camera_rays.h), into rays_, rayPixel_, rayBlock_ and, where
    // rays that skip the set still count (bypassing_), bypass_.
    CameraRays cameraRays_;
    CameraRayBatch cameraRayTargets() {
        return {rays_, rayPixel_, rayBlock_, paths_.bypassing() ? &bypass_ : nullptr};
    }
    static constexpr int kConeBlock = CameraRays::kConeBlock;
    // Marches and shades rays_ and adds each hit to pixels[rayPixel_] (with the paths where the
    // scene has them).
    void traceInto(std::vector<PixelSamples>& pixels, LaneTileStats& stats);
    int sampleKey_ = -1;  // the sample index k of renderUniform's pass (-1: per pixel's count)
    Tile currentTile_{};  // the tile being rendered

    // ---- The scene around the set: the paths (path_waves.h), with this renderer as their
    // engine (lane_tile_waves.cpp) ----
    PathWaves paths_;
    std::vector<BypassRay> bypass_;
    // Whether hits_ are those of reflected or refracted rays: lit without ambient occlusion
    // (a reflection's creases cost as much as the camera's and show far less).
    bool secondaryWave_ = false;
    bool occlusion() const { return shader_->occlusionEnabled() && !secondaryWave_; }
    void marchWave(const RayBatch& rays, bool closest, std::vector<TraceResult>& traced) override;
    void shadeWave(const std::vector<WaveHit>& hits, const HitShading& how) override;
    const std::vector<Vector3d>& normals() const override { return normals_; }
    Color colour(size_t hit) const override {
        return Color(surfaces_.red[hit], surfaces_.green[hit], surfaces_.blue[hit]);
    }
    double trap(size_t hit) const override { return hitEstimates_[hit].trap; }
    void outsideDistances(const PointBatch& points, std::vector<double>& distances) override;
    void outwardNormals(const PointBatch& points, std::vector<Vector3d>& normals) override;
    void lightGround(const std::vector<GroundPoint>& points, bool firstWave) override;
    const std::vector<Color>& groundColour() const override { return groundLighting_.colour(); }
    const std::vector<double>& groundKeyVisibility() const override {
        return groundLighting_.keyVisibility();
    }
    LaneTileStats* waveStats_ = nullptr;  // the batch's, while the paths run
    // The ground's own light at ground points (ground_lighting.h), with each light's shadow
    // rays.
    GroundLighting groundLighting_;
    // The lights of [light1] .. [light7] at the hits of hits_, added to surfaces_' colours.
    void lightOthers(LaneTileStats& stats);
    std::vector<KeyLight> otherLights_;
    // The environment's light at the hits of hits_ (lane_environment.h), added to surfaces_'.
    void lightByEnvironment(LaneTileStats& stats);
    EnvironmentShadows environmentShadows_;
    std::vector<EnvironmentPoint> environmentPoints_;
    std::vector<Color> environmentLight_;
    std::vector<PointEstimate> exitEstimates_;  // outwardNormals'

    // The rays of traced_ that ended on the set, into hits_ and hitPoints_.
    void collectHits(LaneTileStats& stats);
    // The hits' colours, in surfaces_ (red, green, blue), from their normals, shadow rays and
    // ambient occlusion.
    void shadeHits(LaneTileStats& stats);
    // The hits' normals, in normals_, facing the camera; with orbit colouring also the
    // estimates at the hits (hitEstimates_).
    void hitNormals(LaneTileStats& stats);
    // The shadow rays of the hits whose surface faces the key light, in shadows_: none where the
    // ray misses the bounding sphere.
    void aimShadowRays();
    // The key light's shadow rays marched (hard shadows of a directional light through
    // cylinders per block, ShadowRays::marchClippedHardShadows).
    void marchShadowRays(LaneTileStats& stats);
    // Each hit's surface sample (normal, view direction, albedo, visibility, occlusion), in
    // surfaces_.
    void sampleSurfaces();

    LaneFractal lanes_;
    const Camera* camera_;
    const Shader* shader_;
    CameraMarch march_;
    int samples_;
    bool shadowCylinders_;
    int onlySample_ = -1;
    bool adaptive_;
    bool passes_ = false;              // setPasses
    std::vector<KeyLight> keyLights_;  // the key light at each hit (aimShadowRays)
    // Step 2 of adaptive sampling: where given, traceInto keeps each pixel's largest
    // sampleDeviation there.
    const DeviationTracking* tracking_ = nullptr;
    double boundingRadius_;
    LightConstants lightConstants_;

    // The batches of the current sample of the tile.
    RayBatch rays_;
    std::vector<int> rayPixel_;  // which pixel of the tile each ray belongs to
    std::vector<int> rayBlock_;  // and which of its cone blocks
    std::vector<TraceResult> traced_;
    std::vector<WaveHit> hits_;  // owner: the pixel, or the path
    PointBatch hitPoints_;
    std::vector<PointEstimate> hitEstimates_;
    std::vector<int> gradientIterations_;
    std::vector<Vector3d> normals_;
    // The shadow rays of the batch's points (shadow_rays.h); their owners are indices of hits_
    // or groundPoints_.
    ShadowRays shadows_;
    int tileBlocks_ = 0;
    PointBatch occlusionPoints_;
    std::vector<double> occlusionDistances_;
    SurfaceBatch surfaces_;  // each hit's surface sample and, once lit, its colour
};

}  // namespace quaternia
