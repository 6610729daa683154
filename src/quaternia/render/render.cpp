#include "quaternia/render/render.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <vector>

#include "quaternia/fractal/fractal.h"
#include "quaternia/image/png_lanes.h"
#include "quaternia/render/adaptive_driver.h"
#include "quaternia/render/adaptive_sampling.h"
#include "quaternia/render/camera.h"
#include "quaternia/render/lane_tile_renderer.h"
#include "quaternia/render/lanes/march_lanes.h"
#include "quaternia/render/march.h"
#include "quaternia/render/proven_cones.h"
#include "quaternia/render/sample_pattern.h"
#include "quaternia/render/scalar_waves.h"
#include "quaternia/render/shade.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/util/error.h"
#include "quaternia/util/parallel.h"

namespace quaternia {
namespace {

// Each thread's counters and scratch on their own cache lines, so that threads do not contend.
struct alignas(64) ThreadTotals {
    RenderStats stats;
    std::unique_ptr<LaneTileRenderer> laneTiles;  // the SIMD path's batches
    bool laneTilesBound = false;                  // to this call's frame
    std::vector<PixelSamples> pixels;
    AdaptiveScratch adaptive;         // the scalar path's adaptive sampling (adaptive_driver.h)
    std::vector<Rgba> row;            // a tile's row on its way to RenderResult::pngPixels
    std::vector<double> provenUntil;  // the scalar path's cones of proof (proven_cones.h)
};

// Where render.alpha is "opaque" and the caller asked for samples: the rows go straight to PNG
// samples (RenderOptions::opaquePngPixels) instead of the float image.
bool rendersSamples(const RenderSettings& settings, const RenderOptions& options) {
    return options.opaquePngPixels && settings.alpha == AlphaMode::Opaque;
}

// The pixels to render: RenderOptions::window, checked, or the whole image.
Tile renderWindow(const RenderSettings& settings, const RenderOptions& options) {
    if (!options.window) return Tile{0, 0, settings.width, settings.height};
    const Tile& w = *options.window;
    if (w.x0 < 0 || w.y0 < 0 || w.x1 > settings.width || w.y1 > settings.height || w.x0 >= w.x1 ||
        w.y0 >= w.y1 || w.x0 % kWindowAlignment != 0 || w.y0 % kWindowAlignment != 0)
        throw std::invalid_argument("render window outside the image or not aligned");
    return w;
}

// The result with its image (or samples) and depth pass allocated for the window, nothing
// rendered yet.
RenderResult emptyResult(const RenderSettings& settings, const RenderOptions& options,
                         const Tile& window) {
    RenderResult result;
    const int width = window.x1 - window.x0, height = window.y1 - window.y0;
    if (rendersSamples(settings, options)) {
        result.pngPixelsFormat = {width, height, settings.bitDepth, PngColorType::Rgb};
        result.pngPixels.resize(pngRowBytes(result.pngPixelsFormat) * size_t(height));
    } else {
        result.image = Image(width, height);
    }
    if (options.depth) result.depth = GrayImage(width, height);
    if (options.passes) {
        RenderPasses& p = result.passes;
        const size_t count = size_t(width) * size_t(height);
        p.width = width;
        p.height = height;
        p.linear.assign(count, Rgba{});
        p.distance.assign(count, RenderPasses::kNoHitDistance);
        p.trap.assign(count, 0.0f);
        p.normal.assign(count, {0.0f, 0.0f, 0.0f});
        p.object.assign(count, 0);
    }
    return result;
}

// Where a tile's row of display values is written, and what becomes of it once written: rows of
// the float image, or a thread's row quantised into the PNG samples. Pixels are named in the
// image's coordinates; the result holds the window from (x0, y0) on.
class RowTarget {
  public:
    RowTarget(RenderResult& result, bool toSamples, int x0, int y0)
        : result_(result), toSamples_(toSamples), x0_(x0), y0_(y0) {
        if (!toSamples) return;
        pngRowBytes_ = pngRowBytes(result.pngPixelsFormat);
        pngPixelBytes_ = pngRowBytes_ / size_t(result.pngPixelsFormat.width);
    }
    Rgba* row(ThreadTotals& thread, const Tile& tile, int py) const {
        if (!toSamples_) return &result_.image.at(tile.x0 - x0_, py - y0_);
        thread.row.resize(size_t(tile.x1 - tile.x0));
        return thread.row.data();
    }
    void done(const Tile& tile, int py, const Rgba* row) const {
        if (!toSamples_) return;
        quantisePngSamples(&row->r, size_t(tile.x1 - tile.x0), result_.pngPixelsFormat.bitDepth,
                           false,
                           result_.pngPixels.data() + size_t(py - y0_) * pngRowBytes_ +
                               size_t(tile.x0 - x0_) * pngPixelBytes_);
    }

  private:
    RenderResult& result_;
    bool toSamples_;
    int x0_, y0_;
    size_t pngRowBytes_ = 0, pngPixelBytes_ = 0;
};

// The work of a lane tile, as render statistics (its hits are counted as its pixels finish).
RenderStats statsOf(const LaneTileStats& tile) {
    RenderStats stats;
    stats.rays = tile.rays;
    stats.marchSteps = tile.marchSteps;
    stats.iterations = tile.camera.laneIterations;
    stats.shadingEstimates = tile.shading.estimates;
    stats.laneIterations = tile.camera.laneIterations + tile.shading.laneIterations;
    stats.laneSlots = tile.camera.laneSlots + tile.shading.laneSlots;
    return stats;
}

// One frame of a scene: what every tile shares, and the steps that render a tile on either path
// into the result.
class FrameRenderer {
  public:
    FrameRenderer(const Scene& scene, const RenderOptions& options, const Tile& window,
                  RenderResult& result);
    // The SIMD target's name, or "scalar".
    const char* engine() const { return lanes_ ? laneTargetName() : "scalar"; }
    void renderTile(const Tile& tile, ThreadTotals& thread) const {
        if (lanes_) {
            renderTileInLanes(tile, thread);
        } else {
            renderTileScalar(tile, thread);
        }
    }

  private:
    Rgba finishPixel(int px, int py, const PixelSamples& pixel, const Color& background) const;
    // Sample k of pixel (px, py) traced and added to its sums (not counted in pixel.samples);
    // the sample's colour where it hit.
    // `provenUntil`: how far the pixel's rays are proven outside K_N (ProvenCones::clear).
    std::optional<Color> traceSample(int px, int py, int k, PixelSamples& pixel, RenderStats& stats,
                                     ShadingStats& shading, double provenUntil) const;
    // traceSample, counted in pixel.samples.
    std::optional<Color> addSample(int px, int py, int k, PixelSamples& pixel, RenderStats& stats,
                                   ShadingStats& shading, double provenUntil) const {
        ++pixel.samples;
        return traceSample(px, py, k, pixel, stats, shading, provenUntil);
    }
    // The scalar path as adaptive sampling's tracer: each sample on its own.
    class ScalarSampleTracer final : public SampleTracer {
      public:
        ScalarSampleTracer(const FrameRenderer& frame, const Tile& tile,
                           const std::vector<double>& provenUntil, RenderStats& stats,
                           ShadingStats& shading)
            : frame_(frame),
              tile_(tile),
              provenUntil_(provenUntil),
              stats_(stats),
              shading_(shading) {}
        void traceFirstSamples(const Tile&, std::span<const SampleRequest> requests,
                               std::vector<PixelSamples>& firstPass) override {
            for (const SampleRequest& r : requests)
                frame_.traceSample(r.px, r.py, r.k, firstPass[size_t(r.target)], stats_, shading_,
                                   proven(r));
        }
        void traceRound(std::span<const SampleRequest> round, std::vector<PixelSamples>& pixels,
                        const DeviationTracking* tracking, bool) override {
            for (const SampleRequest& r : round) {
                const auto colour = frame_.traceSample(r.px, r.py, r.k, pixels[size_t(r.target)],
                                                       stats_, shading_, proven(r));
                if (colour && tracking) tracking->add(r.target, *colour, frame_.shader_);
            }
        }

      private:
        // Adaptive sampling also traces the first samples of neighbours in other tiles, at the
        // tile's edge: nothing is proven for them here.
        double proven(const SampleRequest& r) const {
            if (r.px < tile_.x0 || r.px >= tile_.x1 || r.py < tile_.y0 || r.py >= tile_.y1)
                return 0;
            return provenUntil_[size_t(r.py - tile_.y0) * size_t(tile_.x1 - tile_.x0) +
                                size_t(r.px - tile_.x0)];
        }
        const FrameRenderer& frame_;
        const Tile& tile_;
        const std::vector<double>& provenUntil_;
        RenderStats& stats_;
        ShadingStats& shading_;
    };
    void renderTileScalar(const Tile& tile, ThreadTotals& thread) const;
    void renderTileInLanes(const Tile& tile, ThreadTotals& thread) const;
    void finishRows(const Tile& tile, ThreadTotals& thread) const;
    void finishRowsOnUniformBackground(const Tile& tile, ThreadTotals& thread) const;
    void finishRowsOnBackgroundRows(const Tile& tile, ThreadTotals& thread) const;

    const Fractal fractal_;
    const Camera camera_;
    const Shader shader_;
    const MaterialSettings material_;
    const GroundSettings ground_;
    const bool paths_;  // the scene has reflection, refraction, the ground or the glow
    const MarchSettings march_;
    const int samples_;
    const bool adaptive_;   // adaptive sampling (adaptive_sampling.h): render.adaptive, samples > 1
    const int onlySample_;  // RenderOptions::onlySample
    const bool opaque_;     // render.alpha = "opaque"
    const bool depth_;      // RenderOptions::depth
    const bool passes_;     // RenderOptions::passes
    const double depthNear_, depthRange_;
    // The SIMD path where the formula and marcher allow it (march_lanes.h).
    std::optional<LaneFractal> lanes_;
    // The scalar fixed steps' cones of proof, where they are active.
    const ProvenCones cones_;
    // A background of one colour (its top and bottom alike), in float as backgroundRow gives it
    // to finishPixel, and that colour display-encoded as the rows' encoding would.
    bool uniformBackground_;
    Color backgroundColor_;
    Rgba backgroundDisplay_;
    const int windowX0_, windowY0_;  // the result's pixel (0, 0) in the image
    RenderResult& result_;
    RowTarget rows_;
};

FrameRenderer::FrameRenderer(const Scene& scene, const RenderOptions& options, const Tile& window,
                             RenderResult& result)
    : fractal_(fractalFromScene(scene)),
      camera_(scene.camera, scene.render.width, scene.render.height),
      shader_(scene.shading, fractal_, scene.lights, environmentOf(scene, options.memory)),
      material_(scene.material),
      ground_(scene.ground),
      paths_(PathWaves::neededFor(scene.material, scene.ground, scene.shading.glowIntensity)),
      march_{fractal_.distanceKind() == DistanceKind::kLipschitz ? MarchMethod::FixedStep
                                                                 : scene.render.method,
             scene.render.step,
             scene.render.epsilon,
             camera_.pixelFootprint(1.0),
             scene.render.maxSteps,
             scene.render.relaxation},
      samples_(scene.render.samples),
      adaptive_(scene.render.adaptive && scene.render.samples > 1 && options.onlySample < 0),
      onlySample_(options.onlySample),
      opaque_(scene.render.alpha == AlphaMode::Opaque),
      depth_(options.depth),
      passes_(options.passes),
      depthNear_(std::max(0.0, length(scene.camera.position) - fractal_.boundingRadius())),
      depthRange_(length(scene.camera.position) + fractal_.boundingRadius() - depthNear_),
      cones_(fractal_, camera_, march_.method == MarchMethod::FixedStep ? march_.step : 0),
      uniformBackground_(shader_.uniformBackground()),
      backgroundColor_(float(shader_.backgroundBottom().x), float(shader_.backgroundBottom().y),
                       float(shader_.backgroundBottom().z)),
      backgroundDisplay_{float(backgroundColor_.x), float(backgroundColor_.y),
                         float(backgroundColor_.z), opaque_ ? 1.0f : 0.0f},
      windowX0_(window.x0),
      windowY0_(window.y0),
      result_(result),
      rows_(result, rendersSamples(scene.render, options), window.x0, window.y0) {
    // The lanes take the quaternions, bicomplex polynomials and octonion real forms; the other
    // algebras run the scalar reference, by fixed steps where their distance is only a short proven
    // bound (hypercomplex_julia.h).
    lanes_ = LaneFractal::forScene(scene, fractal_);
    shader_.toDisplay(&backgroundDisplay_, 1);
}

// A pixel's samples to its linear colour and alpha (and its depth): the same for both paths.
// The background (seen through the pixel centre) is read only where some sample missed.
Rgba FrameRenderer::finishPixel(int px, int py, const PixelSamples& pixel,
                                const Color& background) const {
    // The sums are premultiplied by each sample's alpha (1 for every hit of the set).
    const int hits = pixel.hits, samples = pixel.samples;
    const double covered = hits - pixel.uncovered;
    double coverage = covered / samples;
    Color color;
    if (!pixel.showsBackground()) {
        color = pixel.sum / double(samples);
    } else if (opaque_) {
        color = pixel.sum / double(samples) + background * (1 - coverage);
    } else {
        color = covered > 0 ? pixel.sum / covered : background;
    }
    if (opaque_) coverage = 1;
    const int objectHits = hits - pixel.layerHits;  // of the set or the ground
    if (depth_) {
        double depth =
            objectHits > 0 ? (pixel.depthSum / objectHits - depthNear_) / depthRange_ : 1;
        result_.depth.at(px - windowX0_, py - windowY0_) = float(std::clamp(depth, 0.0, 1.0));
    }
    const Rgba linear{float(color.x), float(color.y), float(color.z), float(coverage)};
    if (passes_) {
        RenderPasses& p = result_.passes;
        const size_t i = size_t(py - windowY0_) * size_t(p.width) + size_t(px - windowX0_);
        p.linear[i] = linear;
        if (objectHits > 0) {
            p.distance[i] = float(pixel.depthSum / objectHits);
            p.trap[i] = float(pixel.trapSum / objectHits);
            const double n = length(pixel.normalSum);
            if (n > 0) {
                const Vector3d unit = pixel.normalSum / n;
                p.normal[i] = {float(unit.x), float(unit.y), float(unit.z)};
            }
            p.object[i] = objectHits > pixel.groundHits ? 1 : 2;  // the set, else the ground
        }
    }
    return linear;
}

// The scalar path: sample k of the pixel marched and shaded on its own, added to its sums.
std::optional<Color> FrameRenderer::traceSample(int px, int py, int k, PixelSamples& pixel,
                                                RenderStats& stats, ShadingStats& shading,
                                                double provenUntil) const {
    auto [sx, sy] = samplePosition(k, samples_, px, py);
    Ray ray = camera_.generateRay(px + sx, py + sy, lensSample(k, px, py));
    MarchResult marched = provenUntil > 0 ? fixedStepMarch(fractal_, ray, march_, provenUntil)
                                          : march(fractal_, ray, march_);
    stats.marchSteps += marched.steps;
    stats.iterations += marched.iterations;
    ++stats.rays;
    if (!marched.hit) return std::nullopt;
    ++pixel.hits;
    SurfaceSample surface;
    const Color colour = shader_.throughFog(
        shader_.shade(*marched.hit, ray, camera_.pixelFootprint(marched.hit->t), shading, &surface),
        marched.hit->t);
    pixel.sum += colour;
    pixel.depthSum += marched.hit->t;
    pixel.normalSum += surface.normal;
    pixel.trapSum += marched.hit->estimate.trap;
    return colour;
}

// The scalar path: the tile's samples traced one by one into the pixels' sums (every sample,
// or adaptively through renderAdaptively, adaptive_driver.h), then the pixels finished as the
// SIMD path finishes them.
void FrameRenderer::renderTileScalar(const Tile& tile, ThreadTotals& thread) const {
    ShadingStats shading;
    if (paths_) {
        // Reflection, refraction, the ground or the glow: the paths, in waves as the lanes
        // trace them (path_waves.h), each wave's rays one by one in double (scalar_waves.h).
        const ScalarPaths::Frame frame{fractal_,  shader_, camera_,  march_,
                                       material_, ground_, samples_, passes_};
        ScalarPaths paths(frame, tile, thread.stats, shading);
        if (adaptive_) {
            renderAdaptively(tile, camera_.width(), camera_.height(), samples_, shader_, paths,
                             thread.adaptive, thread.pixels);
        } else {
            paths.traceUniform(UniformSamples(samples_, onlySample_), thread.pixels);
        }
    } else if (adaptive_) {
        thread.stats.marchSteps += cones_.clear(tile, thread.provenUntil);
        ScalarSampleTracer tracer(*this, tile, thread.provenUntil, thread.stats, shading);
        renderAdaptively(tile, camera_.width(), camera_.height(), samples_, shader_, tracer,
                         thread.adaptive, thread.pixels);
    } else {
        const UniformSamples taken(samples_, onlySample_);
        thread.pixels.assign(size_t(tile.x1 - tile.x0) * size_t(tile.y1 - tile.y0), PixelSamples{});
        thread.stats.marchSteps += cones_.clear(tile, thread.provenUntil);
        PixelSamples* pixel = thread.pixels.data();
        for (int py = tile.y0, i = 0; py < tile.y1; ++py) {
            for (int px = tile.x0; px < tile.x1; ++px, ++pixel, ++i) {
                const double proven = thread.provenUntil[size_t(i)];
                for (int k = taken.first; k < taken.end; ++k)
                    addSample(px, py, k, *pixel, thread.stats, shading, proven);
            }
        }
    }
    thread.stats.shadingEstimates += shading.estimates;
    finishRows(tile, thread);
}

// The SIMD path: the tile's samples summed per pixel by the thread's LaneTileRenderer, then
// the pixels finished row by row.
void FrameRenderer::renderTileInLanes(const Tile& tile, ThreadTotals& thread) const {
    if (!thread.laneTiles) {
        thread.laneTiles = std::make_unique<LaneTileRenderer>(*lanes_, camera_, shader_, march_,
                                                              samples_, true, adaptive_);
        thread.laneTiles->setPasses(passes_);
        thread.laneTiles->setScenery(material_, ground_);
        thread.laneTiles->setOnlySample(onlySample_);
    } else if (!thread.laneTilesBound) {
        thread.laneTiles->rebind(*lanes_, camera_, shader_, march_, samples_, adaptive_);
        thread.laneTiles->setPasses(passes_);
        thread.laneTiles->setScenery(material_, ground_);
        thread.laneTiles->setOnlySample(onlySample_);
    }
    thread.laneTilesBound = true;
    LaneTileStats tileStats;
    thread.laneTiles->render(tile, thread.pixels, tileStats);
    thread.stats += statsOf(tileStats);
    finishRows(tile, thread);
}

// The tile's pixels from their sums (thread.pixels) to the result's rows: the same for both
// engines.
void FrameRenderer::finishRows(const Tile& tile, ThreadTotals& thread) const {
    if (uniformBackground_) {
        finishRowsOnUniformBackground(tile, thread);
    } else {
        finishRowsOnBackgroundRows(tile, thread);
    }
}

// One colour, encoded once: the pixels without hits take it as they are, and only the runs of
// pixels with hits are finished and encoded.
void FrameRenderer::finishRowsOnUniformBackground(const Tile& tile, ThreadTotals& thread) const {
    const int width = tile.x1 - tile.x0;
    const PixelSamples* pixel = thread.pixels.data();
    for (int py = tile.y0; py < tile.y1; ++py) {
        Rgba* row = rows_.row(thread, tile, py);
        for (int i = 0; i < width;) {
            if (pixel[i].hits == 0) {
                if (depth_ || passes_) finishPixel(tile.x0 + i, py, pixel[i], backgroundColor_);
                row[i++] = backgroundDisplay_;
                continue;
            }
            const int first = i;
            for (; i < width && pixel[i].hits > 0; ++i) {
                thread.stats.hits += pixel[i].hits;
                row[i] = finishPixel(tile.x0 + i, py, pixel[i], backgroundColor_);
            }
            shader_.toDisplay(row + first, size_t(i - first));
        }
        rows_.done(tile, py, row);
        pixel += width;
    }
}

// Each row of the tile: the background first (float, vectorised), which is what a pixel without
// hits shows, then the pixels with hits, then display encoding (SIMD) in place.
void FrameRenderer::finishRowsOnBackgroundRows(const Tile& tile, ThreadTotals& thread) const {
    const int width = tile.x1 - tile.x0;
    const PixelSamples* pixel = thread.pixels.data();
    for (int py = tile.y0; py < tile.y1; ++py) {
        Rgba* row = rows_.row(thread, tile, py);
        const Camera::RowDirections directions = camera_.rowDirections(py);
        const float alpha = opaque_ ? 1.0f : 0.0f;
        if (!shader_.environmentBackground()) {
            shader_.backgroundRow(directions.first, directions.step, tile.x0, width, alpha, row);
        } else {
            // A map costs more than a gradient: only the runs of pixels that show some of it
            // (finishPixel reads it nowhere else).
            for (int i = 0; i < width;) {
                if (!pixel[i].showsBackground()) {
                    ++i;
                    continue;
                }
                int end = i + 1;
                while (end < width && pixel[end].showsBackground())
                    ++end;
                shader_.backgroundRow(directions.first, directions.step, tile.x0 + i, end - i,
                                      alpha, row + i);
                i = end;
            }
        }
        for (int i = 0; i < width; ++i, ++pixel) {
            if (pixel->hits == 0 && !depth_ && !passes_) continue;
            thread.stats.hits += pixel->hits;
            row[i] = finishPixel(tile.x0 + i, py, *pixel, Color(row[i].r, row[i].g, row[i].b));
        }
        // Rgba is four floats: the row's colour channels encode in place, alpha kept.
        shader_.toDisplay(row, size_t(width));
        rows_.done(tile, py, row);
    }
}

}  // namespace

struct RenderWorkspace::Threads {
    std::vector<ThreadTotals> totals;
};

RenderWorkspace::RenderWorkspace() : threads_(std::make_unique<Threads>()) {}
RenderWorkspace::~RenderWorkspace() = default;

ParallelOptions imageParallelOptions(const WorkOptions& options, int width, int height) {
    ParallelOptions parallel;
    parallel.threads = resolveThreadCount(options.threads);
    auto tiles = [&](int size) {
        return int64_t((width + size - 1) / size) * int64_t((height + size - 1) / size);
    };
    parallel.tileSize = tiles(64) >= kMinimumHugeTiles    ? 64
                        : tiles(32) >= kMinimumLargeTiles ? 32
                                                          : 16;
    parallel.cancel = options.cancel;
    if (options.progress) {
        parallel.progress = [progress = options.progress](int64_t done, int64_t total) {
            progress(double(done) / double(total));
        };
    }
    return parallel;
}

namespace {

// The parallel-for of a render: the whole image's tiles, as imageParallelOptions gives them; in a
// window, the largest of its sizes that still gives every thread two tiles of the window (the
// pixels are the same for any of them).
ParallelOptions windowParallelOptions(const RenderOptions& options, const RenderSettings& settings,
                                      const Tile& window) {
    ParallelOptions parallel = imageParallelOptions(options, settings.width, settings.height);
    const int width = window.x1 - window.x0, height = window.y1 - window.y0;
    auto tiles = [&](int size) {
        return int64_t((width + size - 1) / size) * int64_t((height + size - 1) / size);
    };
    while (parallel.tileSize > 16 && tiles(parallel.tileSize) < 2 * int64_t(parallel.threads))
        parallel.tileSize /= 2;
    return parallel;
}

}  // namespace

RenderResult render(const Scene& scene, const RenderOptions& options) {
    validateScene(scene);
    const RenderSettings& settings = scene.render;
    const Tile window = renderWindow(settings, options);
    if (options.onlySample < -1 || options.onlySample >= settings.samples)
        throw std::invalid_argument("RenderOptions::onlySample outside the pixel's samples");
    const int width = window.x1 - window.x0, height = window.y1 - window.y0;
    RenderResult result = emptyResult(settings, options, window);
    const FrameRenderer frame(scene, options, window, result);
    result.stats.engine = frame.engine();
    const ParallelOptions parallel = windowParallelOptions(options, settings, window);
    RenderWorkspace local;
    std::vector<ThreadTotals>& totals =
        (options.workspace != nullptr ? *options.workspace : local).threads().totals;
    if (totals.size() < size_t(parallel.threads)) totals.resize(size_t(parallel.threads));
    for (ThreadTotals& thread : totals) {
        thread.stats = RenderStats();
        thread.laneTilesBound = false;
    }

    auto start = std::chrono::steady_clock::now();
    result.completed =
        parallelForTiles(width, height, parallel, [&](const Tile& tile, int threadIndex) {
            const Tile shifted{tile.x0 + window.x0, tile.y0 + window.y0, tile.x1 + window.x0,
                               tile.y1 + window.y0};
            frame.renderTile(shifted, totals[threadIndex]);
        });
    result.stats.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.stats.threads = parallel.threads;
    for (const ThreadTotals& t : totals)
        result.stats += t.stats;
    return result;
}

}  // namespace quaternia
