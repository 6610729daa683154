// The double-precision reference as the engine of the paths (path_waves.h): each wave's rays
// marched one by one (march.h), their hits lit by Shader::shade, the exits of refracted rays found
// by membership tests of the Fractal, the ground lit by the Shader's lights with shadow rays in
// double. So the scalar engine draws every look the lanes draw (reflection, refraction with
// absorption, the ground and its reflections, the shadow catcher, fog, glow, depth of field),
// and is the reference the lanes are held to (render_engines_test.cpp).
#pragma once

#include <span>
#include <vector>

#include "quaternia/render/march.h"
#include "quaternia/render/path_waves.h"
#include "quaternia/render/render.h"

namespace quaternia {

class ScalarWaves final : public WaveEngine {
  public:
    // Counts its work into stats (march steps, iterations) and shading (shadow and occlusion
    // estimates).
    ScalarWaves(const Fractal& fractal, const Shader& shader, const Camera& camera,
                const MarchSettings& march, const GroundSettings& ground, RenderStats& stats,
                ShadingStats& shading)
        : fractal_(fractal),
          shader_(shader),
          camera_(camera),
          march_(march),
          ground_(ground),
          stats_(stats),
          shading_(shading) {}

    void marchWave(const RayBatch& rays, bool closest, std::vector<TraceResult>& traced) override;
    void shadeWave(const std::vector<WaveHit>& hits, const HitShading& how) override;
    const std::vector<Vector3d>& normals() const override { return normals_; }
    Color colour(size_t hit) const override { return colours_[hit]; }
    double trap(size_t hit) const override { return traps_[hit]; }
    void outsideDistances(const PointBatch& points, std::vector<double>& distances) override;
    void outwardNormals(const PointBatch& points, std::vector<Vector3d>& normals) override;
    void lightGround(const std::vector<GroundPoint>& points, bool firstWave) override;
    const std::vector<Color>& groundColour() const override { return groundColour_; }
    const std::vector<double>& groundKeyVisibility() const override { return keyVisibility_; }

  private:
    const Fractal& fractal_;
    const Shader& shader_;
    const Camera& camera_;
    MarchSettings march_;
    GroundSettings ground_;
    RenderStats& stats_;
    ShadingStats& shading_;
    std::vector<Vector3d> normals_;
    std::vector<Color> colours_, groundColour_;
    std::vector<double> traps_, keyVisibility_;
};

// The scalar engine's samples where the scene has paths (PathWaves::active): the camera rays of a
// batch of samples, traced with ScalarWaves as the lanes trace theirs, uniformly or as adaptive
// sampling's tracer (adaptive_driver.h). One per tile.
class ScalarPaths final : public SampleTracer {
  public:
    struct Frame {
        const Fractal& fractal;
        const Shader& shader;
        const Camera& camera;
        const MarchSettings& march;
        const MaterialSettings& material;
        const GroundSettings& ground;
        int samples;
        bool passes;
    };
    ScalarPaths(const Frame& frame, const Tile& tile, RenderStats& stats, ShadingStats& shading);
    // Uniform sampling: the samples `taken` of every pixel of the tile, pass by pass, into
    // pixels (which this sizes and counts).
    void traceUniform(const UniformSamples& taken, std::vector<PixelSamples>& pixels);
    void traceFirstSamples(const Tile& tile, std::span<const SampleRequest> requests,
                           std::vector<PixelSamples>& firstPass) override;
    void traceRound(std::span<const SampleRequest> round, std::vector<PixelSamples>& pixels,
                    const DeviationTracking* tracking, bool last) override;

  private:
    // The samples `requests` traced into pixels[target] (hits and colours; the caller counts
    // the samples). sampleKey and tracking as PathWaves::trace takes them.
    void trace(int sampleKey, std::span<const SampleRequest> requests,
               std::vector<PixelSamples>& pixels, const DeviationTracking* tracking);

    Frame frame_;
    Tile tile_;
    RenderStats& stats_;
    ShadingStats& shading_;
    PathWaves paths_;
    RayBatch rays_;
    std::vector<int> pixel_, block_;
    std::vector<BypassRay> bypass_;
    std::vector<SampleRequest> requests_;
};

}  // namespace quaternia
