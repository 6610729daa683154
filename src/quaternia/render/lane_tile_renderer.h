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
#include "quaternia/render/lanes/march_lanes.h"
#include "quaternia/render/march.h"
#include "quaternia/render/optics.h"
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
class LaneTileRenderer : private SampleTracer {
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
    void setPasses(bool passes) { passes_ = passes; }
    // The set's material and the ground (lane_tile_scenery.cpp); call after rebind too.
    void setScenery(const MaterialSettings& material, const GroundSettings& ground);
    // Whether camera rays that see only a ground that reflects nothing end there without the
    // paths (shadeCameraGround), which changes no pixel; false only to check that.
    void setGroundShortcut(bool shortcut) { groundShortcut_ = shortcut; }
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
        return {rays_, rayPixel_, rayBlock_, bypassing_ ? &bypass_ : nullptr};
    }
    static constexpr int kConeBlock = CameraRays::kConeBlock;
    // Marches and shades rays_ and adds each hit to pixels[rayPixel_].
    void traceInto(std::vector<PixelSamples>& pixels, LaneTileStats& stats);

    // ---- The scene around the set (lane_tile_scenery.cpp) ----
    // Whether traceInto follows whole paths: reflection, refraction, the ground, glow. With the
    // ground, the camera rays that skip the set (their cone or the bounding sphere missed) go
    // to bypass_.
    bool scenery_ = false;
    // Whether hits_ are those of reflected or refracted rays: lit without ambient occlusion
    // (a reflection's creases cost as much as the camera's and show far less).
    bool secondaryWave_ = false;
    bool occlusion() const { return shader_->occlusionEnabled() && !secondaryWave_; }
    bool bypassing_ = false;  // the ground or the glow: rays that skip the set still count
    bool groundShortcut_ = true;
    std::vector<BypassRay> bypass_;
    // A ray of a path: where it goes, which camera sample it serves (samples_ index) and with
    // what weight, how far the path has come, and how many bounces it took.
    struct PathRay {
        Ray ray;
        double tNear = 0;  // camera rays: their cone's start
        int sample = 0;
        Color weight;
        double travelled = 0;
        int depth = 0;
        bool camera = false;
        int block = -1;
    };
    // A camera sample's result: colour (premultiplied) and alpha, its first hit (depth,
    // normal, trap) and what it hit.
    struct SampleResult {
        int pixel = 0;
        Color color;
        double alpha = 0, depth = 0, trap = 0;
        Vector3d normal;
        uint8_t object = 0;  // 0 nothing, 1 the set, 2 the ground
        int key = 0;         // the pixel's sample index, for glossy directions
        double glow = 0;     // the glow's opacity in front of it
    };
    std::vector<SampleResult> sampleResults_;
    std::vector<PathRay> outside_, inside_, nextOutside_, nextInside_;
    int sampleKey_ = -1;  // the sample index k of renderUniform's pass (-1: per pixel's count)
    Tile currentTile_{};  // the tile being rendered
    // traceInto with paths: camera rays, then their reflections and refractions, wave by wave.
    void tracePaths(std::vector<PixelSamples>& pixels, LaneTileStats& stats);
    // One wave of rays outside the set: marched, then shaded where they hit the set or the
    // ground, their children queued.
    // cameraBatch: the first wave, its camera rays still in rays_ as pushRowRays left them
    // (without the glow, which marches them from farther out).
    void traceOutsideWave(LaneTileStats& stats, bool cameraBatch);
    // The first wave's batch: rays_ kept, cut at the ground (those it hides the set from into
    // groundHits_), marchedPaths_ set; returns how many paths of outside_ it took.
    size_t keepCameraBatch();
    std::vector<uint8_t> groundHidden_;
    // The hits_ of an outside wave, shaded (shadeHits), into their samples, and their
    // reflected and refracted rays queued.
    void shadeSetHits();

    // One wave of refracted rays inside the set: fixed steps to where they leave it.
    void traceInsideWave(LaneTileStats& stats);
    // What a ray that hits neither the set nor (usable) ground sees: the background.
    void seeBackground(const PathRay& path);
    // Queues a child ray of `parent` (or, past the depth or below the weight worth a ray, adds
    // the background along it to its sample).
    void spawn(const PathRay& parent, const Ray& ray, const Color& weight, double travelled,
               bool inside);
    // The ground: where ray meets the plane (infinity where not ahead).
    double groundDistance(const Ray& ray) const;
    // A sample's result added to its pixel's sums (and, while tracking_, its deviation).
    void addSample(std::vector<PixelSamples>& pixels, const SampleResult& sample);
    // Where a ray meets the ground: outside_[path] (groundHits_) or bypass_[path]
    // (cameraGround_), at t along it.
    struct GroundHit {
        size_t path;
        double t;
    };
    std::vector<GroundHit> groundHits_, cameraGround_;
    std::vector<GroundPoint> groundPoints_;
    int blockOfPixel(int pixel) const;  // the cone block of pixel (of currentTile_)
    // The ground's own light at groundPoints_ (ground_lighting.h), with each light's shadow
    // rays.
    GroundLighting groundLighting_;
    void lightGround(LaneTileStats& stats);
    // The ground hits of a wave (groundHits_), into their samples, their reflections queued.
    void shadeGround(LaneTileStats& stats);
    // The camera rays of cameraGround_, which see the ground and nothing else, into pixels.
    void shadeCameraGround(std::vector<PixelSamples>& pixels, LaneTileStats& stats);
    // The lights of [light1] .. [light7] at the hits of hits_, added to surfaces_' colours.
    void lightOthers(LaneTileStats& stats);
    // Shadow-ray visibility of `light` from points (the rays of shadows_ as aimed by the
    // caller): marched in lanes.
    void marchShadowsOf(const LightSource& light, LaneTileStats& stats);
    // Inside waves: per path, the fixed step index, the bracket of the exit, bisection rounds.
    PointBatch insidePoints_;
    std::vector<PointEstimate> insideEstimates_;
    std::vector<std::array<double, 2>> insideBracket_;
    std::vector<double> insideFar_, insideDistances_;
    std::vector<size_t> marchedPaths_, insideActive_;
    std::vector<KeyLight> otherLights_;
    MaterialSettings material_;
    GroundSettings ground_;

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
    struct HitRecord {
        int pixel, block;
        double t;
        Vector3d direction;
        Point3d outside;
    };
    std::vector<HitRecord> hits_;
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
