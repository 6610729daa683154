#include "quaternia/render/render.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <vector>

#include "quaternia/fractal/fractal.h"
#include "quaternia/image/png_lanes.h"
#include "quaternia/render/camera.h"
#include "quaternia/render/lane_tile_renderer.h"
#include "quaternia/render/lanes/march_lanes.h"
#include "quaternia/render/march.h"
#include "quaternia/render/shade.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/util/parallel.h"

namespace quaternia {
namespace {

// A small integer hash (Wang/Jenkins style) for reproducible jitter.
uint32_t hashPixel(uint32_t a) {
    a = (a ^ 61u) ^ (a >> 16);
    a *= 9u;
    a ^= a >> 4;
    a *= 0x27d4eb2du;
    a ^= a >> 15;
    return a;
}

double unitFromHash(uint32_t h) {
    return (h >> 8) * (1.0 / 16777216.0);
}

// Each thread's counters and scratch on their own cache lines, so that threads do not contend.
struct alignas(64) ThreadTotals {
    RenderStats stats;
    std::unique_ptr<LaneTileRenderer> laneTiles;  // the SIMD path's batches
    std::vector<PixelSamples> pixels;
    std::vector<Rgba> row;  // a tile's row on its way to RenderResult::samples
};

}  // namespace

std::array<double, 2> samplePosition(int k, int n, int px, int py) {
    if (n == 1) return {0.5, 0.5};
    int columns = int(std::ceil(std::sqrt(double(n))));
    int rows = (n + columns - 1) / columns;
    uint32_t h =
        hashPixel(uint32_t(px) * 73856093u ^ uint32_t(py) * 19349663u ^ uint32_t(k) * 83492791u);
    double jx = unitFromHash(h), jy = unitFromHash(hashPixel(h));
    return {(k % columns + jx) / columns, (k / columns + jy) / rows};
}

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

RenderResult render(const Scene& scene, const RenderOptions& options) {
    validateScene(scene);
    const Fractal fractal = Fractal::fromScene(scene);
    const RenderSettings& settings = scene.render;
    const Camera camera(scene.camera, settings.width, settings.height);
    const Shader shader(scene.shading, fractal);
    const MarchSettings marchSettings{settings.method,   settings.step,
                                      settings.epsilon,  camera.pixelFootprint(1.0),
                                      settings.maxSteps, settings.relaxation};
    const double cameraDistance = length(scene.camera.position);
    const double depthNear = std::max(0.0, cameraDistance - fractal.boundingRadius());
    const double depthRange = cameraDistance + fractal.boundingRadius() - depthNear;

    RenderResult result;
    // The rows go to the float image, or straight to PNG samples (RenderOptions::opaqueSamples).
    const bool toSamples = options.opaqueSamples && settings.alpha == AlphaMode::Opaque;
    size_t sampleRowBytes = 0, samplePixelBytes = 0;
    if (toSamples) {
        result.samplesFormat = {settings.width, settings.height, settings.bitDepth,
                                PngColorType::Rgb};
        sampleRowBytes = pngRowBytes(result.samplesFormat);
        samplePixelBytes = sampleRowBytes / size_t(settings.width);
        result.samples.resize(sampleRowBytes * size_t(settings.height));
    } else {
        result.image = Image(settings.width, settings.height);
    }
    if (options.depth) result.depth = GrayImage(settings.width, settings.height);
    // Where a tile's row of display values is written, and what becomes of it once written.
    auto rowOf = [&](ThreadTotals& thread, const Tile& tile, int py) {
        if (!toSamples) return &result.image.at(tile.x0, py);
        thread.row.resize(size_t(tile.x1 - tile.x0));
        return thread.row.data();
    };
    auto rowDone = [&](const Tile& tile, int py, const Rgba* row) {
        if (!toSamples) return;
        quantisePngSamples(&row->r, size_t(tile.x1 - tile.x0), settings.bitDepth, false,
                           result.samples.data() + size_t(py) * sampleRowBytes +
                               size_t(tile.x0) * samplePixelBytes);
    };

    const ParallelOptions parallel = imageParallelOptions(options, settings.width, settings.height);
    std::vector<ThreadTotals> totals(parallel.threads);
    const int samples = settings.samples;

    // The SIMD path where the formula and marcher allow it (march_lanes.h).
    std::optional<LaneFractal> lanes;
    if (settings.engine == RenderEngine::Simd && settings.method == MarchMethod::SphereTracing)
        lanes = LaneFractal::from(fractal, settings.precision);
    result.stats.engine = lanes ? laneTargetName() : "scalar";

    // A pixel's samples to its linear colour and alpha (and its depth): the same for both paths.
    // The background (seen through the pixel centre) is read only where some sample missed.
    const bool opaque = settings.alpha == AlphaMode::Opaque;
    auto finishPixel = [&](int px, int py, const PixelSamples& samplesOfPixel,
                           const Color& background) {
        const int hits = samplesOfPixel.hits;
        double coverage = double(hits) / samples;
        Color color;
        if (hits == samples) {
            color = samplesOfPixel.sum / double(samples);
        } else if (opaque) {
            color = samplesOfPixel.sum / double(samples) + background * (1 - coverage);
        } else {
            color = hits > 0 ? samplesOfPixel.sum / double(hits) : background;
        }
        if (opaque) coverage = 1;
        if (options.depth) {
            double depth = hits > 0 ? (samplesOfPixel.depthSum / hits - depthNear) / depthRange : 1;
            result.depth.at(px, py) = float(std::clamp(depth, 0.0, 1.0));
        }
        return Rgba{float(color.x), float(color.y), float(color.z), float(coverage)};
    };

    auto renderPixel = [&](int px, int py, RenderStats& stats) -> Rgba {
        PixelSamples pixel;
        ShadingStats shading;
        for (int k = 0; k < samples; ++k) {
            auto [sx, sy] = samplePosition(k, samples, px, py);
            Ray ray = camera.generateRay(px + sx, py + sy);
            MarchResult marched = march(fractal, ray, marchSettings);
            stats.marchSteps += marched.steps;
            stats.iterations += marched.iterations;
            if (!marched.hit) continue;
            ++pixel.hits;
            pixel.sum +=
                shader.shade(*marched.hit, ray, camera.pixelFootprint(marched.hit->t), shading);
            pixel.depthSum += marched.hit->t;
        }
        stats.shadingEstimates += shading.estimates;
        stats.rays += samples;
        stats.hits += pixel.hits;
        const Color background = pixel.hits < samples
                                     ? shader.background(camera.generateRay(px + 0.5, py + 0.5))
                                     : Color();
        Rgba linear = finishPixel(px, py, pixel, background);
        Color display = shader.toDisplay(Color(linear.r, linear.g, linear.b));
        return Rgba{float(display.x), float(display.y), float(display.z), linear.a};
    };

    // A background of one colour (its top and bottom alike), and that colour display-encoded
    // as the rows' encoding would.
    const bool uniformBackground = scene.shading.backgroundTop == scene.shading.backgroundBottom;
    // (In float, as backgroundRow gives it to finishPixel.)
    const Color backgroundColor(float(scene.shading.backgroundBottom.x),
                                float(scene.shading.backgroundBottom.y),
                                float(scene.shading.backgroundBottom.z));
    Rgba backgroundDisplay{float(backgroundColor.x), float(backgroundColor.y),
                           float(backgroundColor.z), opaque ? 1.0f : 0.0f};
    shader.toDisplay(&backgroundDisplay, 1);

    auto renderTileInLanes = [&](const Tile& tile, ThreadTotals& thread) {
        if (!thread.laneTiles) {
            thread.laneTiles =
                std::make_unique<LaneTileRenderer>(*lanes, camera, shader, marchSettings, samples);
        }
        LaneTileStats tileStats;
        thread.laneTiles->render(tile, thread.pixels, tileStats);
        RenderStats& stats = thread.stats;
        stats.marchSteps += tileStats.marchSteps;
        stats.iterations += tileStats.camera.laneIterations;
        stats.shadingEstimates += tileStats.shading.estimates;
        stats.laneIterations += tileStats.camera.laneIterations + tileStats.shading.laneIterations;
        stats.laneSlots += tileStats.camera.laneSlots + tileStats.shading.laneSlots;
        stats.rays += int64_t(samples) * int64_t(thread.pixels.size());
        const int width = tile.x1 - tile.x0;
        const PixelSamples* pixel = thread.pixels.data();
        if (uniformBackground) {
            // One colour, encoded once: the pixels without hits take it as they are, and only
            // the runs of pixels with hits are finished and encoded.
            for (int py = tile.y0; py < tile.y1; ++py) {
                Rgba* row = rowOf(thread, tile, py);
                for (int i = 0; i < width;) {
                    if (pixel[i].hits == 0) {
                        if (options.depth) finishPixel(tile.x0 + i, py, pixel[i], backgroundColor);
                        row[i++] = backgroundDisplay;
                        continue;
                    }
                    const int first = i;
                    for (; i < width && pixel[i].hits > 0; ++i) {
                        stats.hits += pixel[i].hits;
                        row[i] = finishPixel(tile.x0 + i, py, pixel[i], backgroundColor);
                    }
                    shader.toDisplay(row + first, size_t(i - first));
                }
                rowDone(tile, py, row);
                pixel += width;
            }
            return;
        }
        // Each row of the tile: the background first (float, vectorised), which is what a pixel
        // without hits shows, then the pixels with hits, then display encoding (SIMD) in place.
        for (int py = tile.y0; py < tile.y1; ++py) {
            Rgba* row = rowOf(thread, tile, py);
            const Camera::RowDirections directions = camera.rowDirections(py);
            shader.backgroundRow(directions.first, directions.step, tile.x0, width,
                                 opaque ? 1.0f : 0.0f, row);
            for (int i = 0; i < width; ++i, ++pixel) {
                if (pixel->hits == 0 && !options.depth) continue;
                stats.hits += pixel->hits;
                row[i] = finishPixel(tile.x0 + i, py, *pixel, Color(row[i].r, row[i].g, row[i].b));
            }
            // Rgba is four floats: the row's colour channels encode in place, alpha kept.
            shader.toDisplay(row, size_t(width));
            rowDone(tile, py, row);
        }
    };

    auto start = std::chrono::steady_clock::now();
    result.completed = parallelForTiles(
        settings.width, settings.height, parallel, [&](const Tile& tile, int threadIndex) {
            ThreadTotals& thread = totals[threadIndex];
            if (lanes) {
                renderTileInLanes(tile, thread);
                return;
            }
            for (int py = tile.y0; py < tile.y1; ++py) {
                Rgba* row = rowOf(thread, tile, py);
                for (int px = tile.x0; px < tile.x1; ++px)
                    row[px - tile.x0] = renderPixel(px, py, thread.stats);
                rowDone(tile, py, row);
            }
        });
    result.stats.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.stats.threads = parallel.threads;
    for (const ThreadTotals& t : totals) {
        result.stats.rays += t.stats.rays;
        result.stats.hits += t.stats.hits;
        result.stats.marchSteps += t.stats.marchSteps;
        result.stats.iterations += t.stats.iterations;
        result.stats.shadingEstimates += t.stats.shadingEstimates;
        result.stats.laneIterations += t.stats.laneIterations;
        result.stats.laneSlots += t.stats.laneSlots;
    }
    return result;
}

}  // namespace quaternia
