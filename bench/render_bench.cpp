// Benchmarks with stable names: the distance estimate and whole frames of fixed scenes.
// Counters explain the speed: rays/s, estimates and iterations per ray.
#include <benchmark/benchmark.h>

#include <hwy/targets.h>

#include <cmath>
#include <random>
#include <string>

#include "quaternia/fractal/fractal.h"
#include "quaternia/image/png_io.h"
#include "quaternia/mesh/mesher.h"
#include "quaternia/render/lanes/march_lanes.h"
#include "quaternia/render/render.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_fractal.h"

namespace quaternia {
namespace {

// The default scene's fractal, queried at points spread through its bounding ball.
void BM_DistanceEstimate(benchmark::State& state) {
    Scene scene = defaultScene();
    Fractal fractal = fractalFromScene(scene);
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> coordinate(-fractal.boundingRadius(),
                                                      fractal.boundingRadius());
    std::vector<Point3d> points(4096);
    for (Point3d& p : points)
        p = {coordinate(rng), coordinate(rng), coordinate(rng)};
    int64_t iterations = 0;
    size_t k = 0;
    for (auto _ : state) {
        DistanceEstimate e = fractal.estimate(points[k++ & 4095]);
        iterations += e.iterations;
        benchmark::DoNotOptimize(e);
    }
    state.counters["estimates/s"] =
        benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["iterations/s"] =
        benchmark::Counter(double(iterations), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_DistanceEstimate);

// The same points through the SIMD lanes (march_lanes.h), 4096 per call; the argument is
// the precision (0 single, 1 double). Lane-iterations/s is the throughput of the hot loop.
void BM_DistanceEstimateLanes(benchmark::State& state) {
    Scene scene = defaultScene();
    Fractal fractal = fractalFromScene(scene);
    const LaneFractal lanes =
        LaneFractal::from(fractal, state.range(0) ? Precision::Double : Precision::Single);
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> coordinate(-fractal.boundingRadius(),
                                                      fractal.boundingRadius());
    PointBatch points;
    for (int i = 0; i < 4096; ++i)
        points.push(Point3d(coordinate(rng), coordinate(rng), coordinate(rng)));
    std::vector<PointEstimate> estimates;
    LaneCounters counters;
    for (auto _ : state) {
        estimatePoints(lanes, points, estimates, counters);
        benchmark::DoNotOptimize(estimates.data());
    }
    state.SetLabel(laneTargetName());
    state.counters["estimates/s"] =
        benchmark::Counter(double(counters.estimates), benchmark::Counter::kIsRate);
    state.counters["lane_iterations/s"] =
        benchmark::Counter(double(counters.laneIterations), benchmark::Counter::kIsRate);
    state.counters["lane_utilisation"] =
        double(counters.laneIterations) / double(counters.laneSlots);
}
BENCHMARK(BM_DistanceEstimateLanes)->Arg(0)->Arg(1);

// A whole frame: arguments are width, height, samples, threads (0 = all cores) and the path
// (0 SIMD single, 1 SIMD double, 2 scalar reference, 3 SIMD single with AVX-512 switched off:
// what a machine with AVX2 as its widest SIMD would run, comparable across machines).
// What explains a frame's speed: lane use, rays/s, steps and iterations per ray, shading work.
void reportRenderCounters(benchmark::State& state, const RenderStats& last) {
    state.counters["lane_utilisation"] =
        last.laneSlots ? double(last.laneIterations) / double(last.laneSlots) : 0.0;
    state.counters["rays/s"] =
        benchmark::Counter(double(last.rays) * state.iterations(), benchmark::Counter::kIsRate);
    state.counters["steps/ray"] = double(last.marchSteps) / double(last.rays);
    state.counters["iterations/ray"] = double(last.iterations) / double(last.rays);
    state.counters["shading_estimates/hit"] =
        last.hits ? double(last.shadingEstimates) / double(last.hits) : 0.0;
}

void BM_RenderDefaultScene(benchmark::State& state) {
    Scene scene = defaultScene();
    scene.render.width = int(state.range(0));
    scene.render.height = int(state.range(1));
    scene.render.samples = int(state.range(2));
    RenderOptions options;
    options.threads = int(state.range(3));
    scene.render.precision = state.range(4) == 1 ? Precision::Double : Precision::Single;
    scene.render.engine = state.range(4) == 2 ? RenderEngine::Scalar : RenderEngine::Simd;
    if (state.range(4) == 3) hwy::DisableTargets(HWY_AVX3 | HWY_AVX3_DL);
    RenderStats last;
    for (auto _ : state)
        last = render(scene, options).stats;
    hwy::DisableTargets(0);
    state.SetLabel(last.engine);
    reportRenderCounters(state, last);
}
BENCHMARK(BM_RenderDefaultScene)
    ->Args({640, 360, 1, 0, 0})
    ->Args({640, 360, 1, 1, 0})
    ->Args({640, 360, 1, 0, 1})
    ->Args({640, 360, 1, 0, 2})
    ->Args({640, 360, 1, 0, 3})
    ->Args({1920, 1080, 1, 0, 0})
    ->Args({1920, 1080, 1, 1, 0})
    ->Args({1920, 1080, 1, 0, 3})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Issue 17's formulas at 1920x1080, 1 sample, 2 threads, the default scene otherwise: the first
// argument picks the formula (0 z^2 + c, 1 z^2 + 0.1 z + c, 2 (1+0.2i) z (1-0.1k) z + c, both
// compiled programs, 3 z^3 + c with c = -0.5 + 0.5i), the second the instruction set (0 the
// best the CPU has, 1 AVX-512 switched off: what an AVX2 machine runs).
void BM_RenderFormula(benchmark::State& state) {
    struct Case {
        const char* formula;
        Quaternion c;
    };
    const Case cases[] = {{"z^2 + c", defaultScene().fractal.c},
                          {"z^2 + 0.1*z + c", defaultScene().fractal.c},
                          {"(1+0.2i) z (1-0.1k) z + c", defaultScene().fractal.c},
                          {"z^3 + c", Quaternion(-0.5, 0.5, 0, 0)}};
    const Case& given = cases[state.range(0)];
    Scene scene = defaultScene();
    scene.render.width = 1920;
    scene.render.height = 1080;
    scene.render.samples = 1;
    scene.fractal.formula = given.formula;
    scene.fractal.c = given.c;
    RenderOptions options;
    options.threads = 2;
    if (state.range(1) == 1) hwy::DisableTargets(HWY_AVX3 | HWY_AVX3_DL);
    RenderStats last;
    for (auto _ : state)
        last = render(scene, options).stats;
    hwy::DisableTargets(0);
    state.SetLabel(std::string(given.formula) + " " + last.engine);
    reportRenderCounters(state, last);
}
BENCHMARK(BM_RenderFormula)
    ->ArgsProduct({{0, 1, 2, 3}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Encoding a rendered 1920x1080 frame as an 8-bit PNG: the argument is the alpha mode (0
// coverage, as the default scene renders, 1 opaque). The frame is rendered once, outside the
// timing, with 1 sample per pixel; "bytes" is the size of the file.
void BM_EncodePng(benchmark::State& state) {
    Scene scene = defaultScene();
    scene.render.width = 1920;
    scene.render.height = 1080;
    scene.render.samples = 1;
    scene.render.alpha = state.range(0) == 1 ? AlphaMode::Opaque : AlphaMode::Coverage;
    const Image image = render(scene).image;
    size_t bytes = 0;
    for (auto _ : state) {
        std::vector<uint8_t> png = encodePng(image, 8);
        bytes = png.size();
        benchmark::DoNotOptimize(png.data());
    }
    state.counters["bytes"] = double(bytes);
    state.counters["pixels/s"] = benchmark::Counter(
        double(image.pixels().size()) * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_EncodePng)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

// The default scene's mesh: the argument is mesh.resolution.
void BM_MeshDefaultScene(benchmark::State& state) {
    Scene scene = defaultScene();
    scene.mesh.resolution = int(state.range(0));
    MeshResult last;
    for (auto _ : state)
        last = meshScene(scene);
    state.counters["triangles"] = double(last.mesh.triangles.size());
    state.counters["blocks"] = double(last.stats.blocks);
    state.counters["estimates/triangle"] =
        double(last.stats.estimates) / double(last.mesh.triangles.size());
    state.counters["triangles/s"] = benchmark::Counter(
        double(last.mesh.triangles.size()) * state.iterations(), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_MeshDefaultScene)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond)->UseRealTime();

// What each explorer query pays before it renders: the scene's fractal, for a formula whose
// top degree has two terms (its escape radius needs the branch and bound of the top-degree part's
// minimum, kept across queries that change only c) while c moves as a slider moves it.
void BM_FractalFromScene(benchmark::State& state) {
    Scene scene = defaultScene();
    scene.fractal.formula = "z i z + 0.5 z^2 + c";
    double x = 0;
    for (auto _ : state) {
        scene.fractal.c.w = -0.2 + 0.01 * std::sin(x += 0.1);
        const Fractal fractal = fractalFromScene(scene);
        benchmark::DoNotOptimize(fractal.set().escapeRadius());
    }
}
BENCHMARK(BM_FractalFromScene)->Unit(benchmark::kMicrosecond)->UseRealTime();

}  // namespace
}  // namespace quaternia

BENCHMARK_MAIN();
