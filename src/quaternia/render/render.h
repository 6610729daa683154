// Rendering a scene to an image: one camera ray per sample, marched (march.h), shaded
// (shade.h), averaged per pixel, tiles spread over all cores by the one parallel-for.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>

#include "quaternia/image/image.h"
#include "quaternia/image/png_writer.h"
#include "quaternia/scene/scene.h"
#include "quaternia/util/memory_budget.h"
#include "quaternia/util/parallel.h"

namespace quaternia {

// What render() keeps from one call to the next when the caller hands it one: each thread's
// scratch, the SIMD path's lane renderer with its batches among it, so that a film allocates
// them once. It holds nothing of the picture: a render draws the same bytes with a workspace,
// a used one or none. One render at a time may use a workspace.
class RenderWorkspace {
  public:
    RenderWorkspace();
    ~RenderWorkspace();
    RenderWorkspace(const RenderWorkspace&) = delete;
    RenderWorkspace& operator=(const RenderWorkspace&) = delete;

    struct Threads;  // render.cpp's
    Threads& threads() { return *threads_; }

  private:
    std::unique_ptr<Threads> threads_;
};

// How any image is computed (3D renders, plane images): threads, cancellation, progress.
struct RenderOptions : WorkOptions {
    RenderWorkspace* workspace = nullptr;  // none: render() makes its scratch for the call
    bool depth = false;                    // also fill RenderResult::depth
    bool passes = false;                   // also fill RenderResult::passes (for EXR)
    // Where render.alpha is "opaque": fill RenderResult::pngPixels instead of the image, each
    // row quantised as soon as its tile has it (while it is in cache), as encodePng would.
    bool opaquePngPixels = false;
    // Only this rectangle of the image (in the image's pixels; none: all of it). The result's
    // image, PNG pixels and depth then hold the window alone, with the same values as the whole
    // image's render has there, provided x0 and y0 are multiples of kWindowAlignment (the
    // tiles and cone blocks then fall on the same pixels). quaternia-mpi renders a poster
    // window by window on many machines.
    std::optional<Tile> window;
    // Each pixel as uniform sampling's sample k (0 <= k < render.samples) alone, in place of
    // all of them (or adaptive sampling): bench/adaptive_study renders the samples one by one
    // to measure what an adaptive sampler could save. -1: every sample.
    int onlySample = -1;
    // What the environment map may take (environment.map, read before the work).
    MemoryBudget memory = {};
};

// What RenderOptions::window's corner must be a multiple of: the largest tile side.
inline constexpr int kWindowAlignment = 64;

struct RenderStats {
    int64_t rays = 0;  // camera rays (pixels x samples)
    int64_t hits = 0;
    int64_t marchSteps = 0;        // distance estimates or membership tests of camera rays
    int64_t iterations = 0;        // polynomial evaluations of camera rays
    int64_t shadingEstimates = 0;  // shadow and occlusion estimates
    // The SIMD path's lanes (camera and shading): polynomial evaluations in live lanes and lane
    // slots; utilisation = laneIterations / laneSlots. 0 on the scalar path.
    int64_t laneIterations = 0;
    int64_t laneSlots = 0;
    const char* engine = "";  // the SIMD target (e.g. "AVX2") or "scalar"
    int threads = 0;
    double seconds = 0;

    // Adds the counters above (rays to laneSlots) of other work; engine, threads and seconds
    // describe the whole render and are left as they are.
    RenderStats& operator+=(const RenderStats& other) {
        rays += other.rays;
        hits += other.hits;
        marchSteps += other.marchSteps;
        iterations += other.iterations;
        shadingEstimates += other.shadingEstimates;
        laneIterations += other.laneIterations;
        laneSlots += other.laneSlots;
        return *this;
    }
};

// Passes for compositing (RenderOptions::passes), each width x height, row-major. linear: the
// colour before exposure and gamma with alpha as RenderResult::image has it (straight); of the
// hit samples, distance: the mean distance from the camera along the ray (kNoHitDistance where
// none hit, as Blender writes its Z pass), normal: the mean world normal made unit (0 where none
// hit), trap: the mean orbit trap min |z_n| (0 where none hit); object: 1 where a sample hit the
// set, 0 else.
struct RenderPasses {
    static constexpr float kNoHitDistance = 1e10f;
    int width = 0, height = 0;
    std::vector<Rgba> linear;
    std::vector<float> distance, trap;
    std::vector<std::array<float, 3>> normal;
    std::vector<uint32_t> object;
};

struct RenderResult {
    // Display values (exposure and gamma applied). With render.alpha = "coverage", alpha is the
    // fraction of a pixel's samples that hit and colour the mean of the hit samples (straight
    // alpha), or the background where nothing was hit; with "opaque", the samples are
    // composited over the background and alpha is 1.
    Image image;
    // Depth pass when asked for: the mean hit distance scaled so that 0 is the near side of the
    // bounding sphere and 1 its far side; 1 where nothing was hit.
    GrayImage depth;
    RenderPasses passes;  // with RenderOptions::passes
    // With RenderOptions::opaquePngPixels and render.alpha = "opaque", in place of `image` (which
    // stays empty): its RGB pixels at the scene's bit depth, as PNG stores them (png_writer.h),
    // the very bytes that encodePng(image, bitDepth, true) deflates. A quarter of the memory
    // of the float image at 8 bits, and no second pass over it.
    PngFormat pngPixelsFormat;
    std::vector<uint8_t, ZeroedAllocator<uint8_t>> pngPixels;
    RenderStats stats;
    bool completed = true;  // false if cancelled
};

// Validates the scene (throws UserError naming the bad key) before any work starts.
RenderResult render(const Scene& scene, const RenderOptions& options = {});

// The parallel-for settings of a width x height image: the options' threads resolved, their
// cancel flag, their progress (if set) called with the fraction of tiles done, and square tiles
// of 64 pixels where the image has at least kMinimumHugeTiles of them, else of 32 pixels where
// it has at least kMinimumLargeTiles, else 16. Large tiles make long batches for the SIMD path
// (each batch ends with lanes idling while its last rays finish, so fewer, longer batches idle
// less); small images need the small tiles to keep every thread busy, and
// kMinimumHugeTiles still gives 64 cores about 8 tiles each. The size depends on the image
// alone, so the picture is the same for any number of threads (it is the same for any of these
// sizes too: they are multiples of the cone blocks, lane_tile_renderer.h).
inline constexpr int64_t kMinimumLargeTiles = 128;
inline constexpr int64_t kMinimumHugeTiles = 480;
ParallelOptions imageParallelOptions(const WorkOptions& options, int width, int height);

}  // namespace quaternia
