#include "quaternia/render/render.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstring>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "quaternia/image/mask_compare.h"
#include "quaternia/image/mask_test_helpers.h"
#include "quaternia/image/png_io.h"
#include "quaternia/render/sample_pattern.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_file.h"
#include "quaternia/scene/test_scenes.h"
#include "quaternia/util/error.h"
#include "quaternia/util/sanitized_build.h"

namespace quaternia {
namespace {

using testing::referenceScene;
using testing::unitBallScene;

// With one sample a pixel is hit or not: alpha is exactly 0 or 1 (0 or 255 in the PNG).
// Tiles: 64 or 32 pixels where the image has enough of them, 16 for small images (explorer
// previews), whatever the thread count, so the picture does not depend on it.
TEST(Render, TileSizeFollowsTheImageNotTheThreads) {
    for (int threads : {1, 2, 64}) {
        WorkOptions work;
        work.threads = threads;
        EXPECT_EQ(imageParallelOptions(work, 3840, 2160).tileSize, 64);
        EXPECT_EQ(imageParallelOptions(work, 1920, 1080).tileSize, 64);
        EXPECT_EQ(imageParallelOptions(work, 1280, 720).tileSize, 32);
        EXPECT_EQ(imageParallelOptions(work, 640, 360).tileSize, 32);
        EXPECT_EQ(imageParallelOptions(work, 160, 90).tileSize, 16);
        EXPECT_EQ(imageParallelOptions(work, 1, 2000).tileSize, 16);
        EXPECT_EQ(imageParallelOptions(work, 640, 360).threads, threads);
    }
}

// A window of the image renders the very pixels the whole image has there, on both engines and
// into either result (float image, or PNG samples with the depth pass): quaternia-mpi renders
// posters window by window.
TEST(Render, WindowHasTheWholeImagesPixels) {
    // Adaptive sampling decides from the first samples of each pixel's neighbours, which lie
    // in other tiles at the window's edge.
    for (RenderEngine engine : {RenderEngine::Simd, RenderEngine::Scalar}) {
        for (auto [n, adaptive, samples] :
             {std::tuple{2, false, false}, std::tuple{2, false, true}, std::tuple{16, true, false},
              std::tuple{16, true, true}, std::tuple{16, false, false}}) {
            if (engine == RenderEngine::Scalar && n == 16 && !adaptive) continue;  // slow
            Scene scene = defaultScene();
            scene.render.width = 150;
            scene.render.height = 139;
            scene.render.samples = n;
            scene.render.adaptive = adaptive;
            scene.render.engine = engine;
            scene.render.alpha = samples ? AlphaMode::Opaque : AlphaMode::Coverage;
            RenderOptions options;
            options.depth = true;
            options.opaquePngPixels = samples;
            const RenderResult whole = render(scene, options);
            options.window = Tile{64, 64, 150, 139};
            const RenderResult part = render(scene, options);
            ASSERT_EQ(part.depth.width(), 86);
            ASSERT_EQ(part.depth.height(), 75);
            int hits = 0;
            for (int y = 64; y < 139; ++y) {
                for (int x = 64; x < 150; ++x) {
                    ASSERT_EQ(part.depth.at(x - 64, y - 64), whole.depth.at(x, y));
                    hits += whole.depth.at(x, y) < 1;
                    if (samples) continue;
                    const Rgba a = part.image.at(x - 64, y - 64), b = whole.image.at(x, y);
                    ASSERT_TRUE(a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a)
                        << x << "," << y;
                }
            }
            EXPECT_GT(hits, 0);  // the window shows some of the set
            if (!samples) continue;
            const size_t row = pngRowBytes(whole.pngPixelsFormat);
            const size_t partRow = pngRowBytes(part.pngPixelsFormat);
            for (int y = 64; y < 139; ++y)
                ASSERT_EQ(0,
                          std::memcmp(part.pngPixels.data() + size_t(y - 64) * partRow,
                                      whole.pngPixels.data() + size_t(y) * row + 64 * 3, partRow));
        }
    }
}

// The same for the scalar fixed steps' cones of proof (proven_cones.h), which hold distances for
// the tile's own pixels: adaptive sampling's neighbours in other tiles march on their own.
TEST(Render, WindowHasTheWholeImagesPixelsThroughConesOfProof) {
    Scene scene = defaultScene();
    applyOverride(scene, "fractal.algebra=\"coquaternion\"");
    scene.render.width = 128;
    scene.render.height = 100;
    scene.render.samples = 4;
    scene.render.adaptive = true;
    scene.render.step = 0.004;
    RenderOptions options;
    options.depth = true;
    const RenderResult whole = render(scene, options);
    options.window = Tile{64, 64, 128, 100};
    const RenderResult part = render(scene, options);
    int hits = 0;
    for (int y = 64; y < 100; ++y)
        for (int x = 64; x < 128; ++x) {
            ASSERT_EQ(part.depth.at(x - 64, y - 64), whole.depth.at(x, y)) << x << "," << y;
            hits += whole.depth.at(x, y) < 1;
        }
    EXPECT_GT(hits, 0);
}

TEST(Render, WindowMustBeAlignedAndInside) {
    Scene scene = unitBallScene(100, 100);
    RenderOptions options;
    options.window = Tile{32, 0, 100, 100};
    EXPECT_THROW(render(scene, options), std::invalid_argument);
    options.window = Tile{64, 0, 101, 100};
    EXPECT_THROW(render(scene, options), std::invalid_argument);
}

TEST(Render, SingleSampleAlphaIsBinary) {
    RenderResult result = render(unitBallScene(48, 36));
    int covered = 0;
    for (const Rgba& pixel : result.image.pixels()) {
        ASSERT_TRUE(pixel.a == 0.0f || pixel.a == 1.0f);
        covered += pixel.a == 1.0f;
    }
    EXPECT_GT(covered, 100);
    EXPECT_EQ(result.stats.rays, 48 * 36);
    EXPECT_EQ(result.stats.hits, covered);
}

// With n samples alpha is the covered fraction k / n, and edges show fractions.
TEST(Render, AlphaIsCoverage) {
    Scene scene = unitBallScene(40, 30);
    scene.render.samples = 4;
    RenderResult result = render(scene);
    std::set<float> seen;
    for (const Rgba& pixel : result.image.pixels()) {
        float quarters = pixel.a * 4;
        ASSERT_FLOAT_EQ(quarters, std::round(quarters));
        seen.insert(pixel.a);
    }
    EXPECT_TRUE(seen.count(0.0f) && seen.count(1.0f));
    EXPECT_GE(seen.size(), 3u);  // some edge pixel is partly covered
}

// The unit ball seen from (0, 0, -3): its silhouette is the disc of angular radius asin(1/3).
TEST(Render, UnitBallSilhouetteIsTheAnalyticDisc) {
    Scene scene = unitBallScene(101, 101);
    scene.camera.fovDegrees = 45;
    RenderResult result = render(scene);
    Mask rendered = maskFromAlpha(result.image);
    Mask analytic{101, 101, std::vector<uint8_t>(101 * 101)};
    const double halfWidth = std::tan(45.0 * M_PI / 360.0);
    const double tanRadius = std::tan(std::asin(1.0 / 3.0));
    for (int y = 0; y < 101; ++y) {
        for (int x = 0; x < 101; ++x) {
            double u = ((x + 0.5) / 101 - 0.5) * 2 * halfWidth;
            double v = (0.5 - (y + 0.5) / 101) * 2 * halfWidth;
            analytic.inside[y * 101 + x] = u * u + v * v < tanRadius * tanRadius;
        }
    }
    MaskComparison comparison = testing::compareNonEmptyMasks(rendered, analytic);
    EXPECT_GT(comparison.iou, 0.98);
    EXPECT_EQ(comparison.farFromA, 0);
    EXPECT_EQ(comparison.farFromB, 0);
}

TEST(Render, DepthPassIsZeroAtNearestPointOfUnitBall) {
    Scene scene = unitBallScene(21, 21);
    RenderOptions options;
    options.depth = true;
    RenderResult result = render(scene, options);
    // Camera at distance 3, bounding radius 1: depth 0 at t = 2, the front of the ball.
    EXPECT_NEAR(result.depth.at(10, 10), 0.0, 5e-3);
    EXPECT_EQ(result.depth.at(0, 0), 1.0f);
    EXPECT_GT(result.depth.at(10, 6), result.depth.at(10, 10));
}

TEST(Render, CancelStopsEarly) {
    std::atomic<bool> cancel{true};
    RenderOptions options;
    options.cancel = &cancel;
    RenderResult result = render(unitBallScene(64, 64), options);
    EXPECT_FALSE(result.completed);
    EXPECT_LT(result.stats.rays, 64 * 64);
}

TEST(Render, ProgressReachesOne) {
    RenderOptions options;
    double last = -1;
    bool monotonic = true;
    options.progress = [&](double fraction) {
        monotonic = monotonic && fraction >= last;
        last = fraction;
    };
    render(unitBallScene(64, 48), options);
    EXPECT_TRUE(monotonic);
    EXPECT_DOUBLE_EQ(last, 1.0);
}

TEST(Render, SameImageWithAnyThreadCount) {
    Scene scene = referenceScene("case01_sqr_A");
    scene.render.width = 64;
    scene.render.height = 48;
    scene.render.samples = 2;
    RenderOptions one, three;
    one.threads = 1;
    three.threads = 3;
    RenderResult a = render(scene, one), b = render(scene, three);
    for (size_t k = 0; k < a.image.pixels().size(); ++k) {
        ASSERT_EQ(a.image.pixels()[k].r, b.image.pixels()[k].r);
        ASSERT_EQ(a.image.pixels()[k].a, b.image.pixels()[k].a);
    }
}

// Pixels equal to the last bit, colour and alpha.
void expectSameImage(const Image& a, const Image& b) {
    ASSERT_EQ(a.pixels().size(), b.pixels().size());
    for (size_t k = 0; k < a.pixels().size(); ++k) {
        const Rgba &p = a.pixels()[k], &q = b.pixels()[k];
        ASSERT_TRUE(p.r == q.r && p.g == q.g && p.b == q.b && p.a == q.a) << "pixel " << k;
    }
}

// A film renders its frames with one workspace: the lane renderers of the frame before, rebound,
// draw what new ones draw.
TEST(Render, AWorkspaceKeepsNothingOfThePicture) {
    Scene before = defaultScene(), frame = defaultScene();
    before.render.width = 72;
    before.render.height = 40;
    before.render.samples = 2;
    frame.render.width = 48;
    frame.render.height = 30;
    frame.render.samples = 3;
    frame.fractal.c = Quaternion(-0.3, 0.5, 0.1, 0.3);
    frame.camera.position = Point3d(0.5, 0.4, 3.2);
    RenderWorkspace workspace;
    RenderOptions options;
    options.threads = 2;
    options.workspace = &workspace;
    render(before, options);
    RenderResult reused = render(frame, options);
    options.workspace = nullptr;
    RenderResult alone = render(frame, options);
    EXPECT_STRNE(alone.stats.engine, "scalar") << "the SIMD path, whose renderers are kept";
    EXPECT_EQ(std::string(reused.stats.engine), std::string(alone.stats.engine));
    EXPECT_EQ(reused.stats.rays, alone.stats.rays);
    expectSameImage(reused.image, alone.image);
}

// Sample positions are a function of the pixel and the sample's index alone (no state, no
// frame, no thread), so the still parts of a film do not flicker from frame to frame.
TEST(Render, SamplePositionsDependOnlyOnPixelAndIndex) {
    std::vector<std::array<double, 2>> first;
    for (int py = 0; py < 4; ++py)
        for (int px = 0; px < 4; ++px)
            for (int k = 0; k < 4; ++k)
                first.push_back(samplePosition(k, 4, px, py));
    render(unitBallScene(16, 12));
    size_t at = first.size();
    for (int py = 3; py >= 0; --py)
        for (int px = 3; px >= 0; --px)
            for (int k = 3; k >= 0; --k) {
                std::array<double, 2> position = samplePosition(k, 4, px, py);
                EXPECT_EQ(position, first[--at]);
                // In the sample's stratum of the 2x2 grid.
                EXPECT_GE(position[0], 0.5 * (k % 2));
                EXPECT_LT(position[0], 0.5 * (k % 2 + 1));
                EXPECT_GE(position[1], 0.5 * (k / 2));
                EXPECT_LT(position[1], 0.5 * (k / 2 + 1));
            }
    EXPECT_NE(samplePosition(0, 4, 0, 0), samplePosition(0, 4, 1, 0)) << "jittered per pixel";
}

// The counters of work add up; the description of the whole render stays.
TEST(Render, StatsAddTheirCounters) {
    RenderStats total{1, 2, 3, 4, 5, 6, 7, "AVX2", 8, 0.5};
    total += RenderStats{10, 20, 30, 40, 50, 60, 70, "scalar", 80, 9.0};
    EXPECT_EQ(total.rays, 11);
    EXPECT_EQ(total.hits, 22);
    EXPECT_EQ(total.marchSteps, 33);
    EXPECT_EQ(total.iterations, 44);
    EXPECT_EQ(total.shadingEstimates, 55);
    EXPECT_EQ(total.laneIterations, 66);
    EXPECT_EQ(total.laneSlots, 77);
    EXPECT_STREQ(total.engine, "AVX2");
    EXPECT_EQ(total.threads, 8);
    EXPECT_EQ(total.seconds, 0.5);
}

// Each thread counts its own tiles: the sums are the same for any number of threads, on both
// engines.
TEST(Render, StatsDoNotDependOnTheThreads) {
    Scene scene = referenceScene("case01_sqr_A");
    scene.render.width = 64;
    scene.render.height = 48;
    for (RenderEngine engine : {RenderEngine::Scalar, RenderEngine::Simd}) {
        scene.render.engine = engine;
        RenderOptions one, three;
        one.threads = 1;
        three.threads = 3;
        const RenderStats a = render(scene, one).stats, b = render(scene, three).stats;
        EXPECT_EQ(a.rays, 64 * 48);
        EXPECT_GT(a.hits, 0);
        EXPECT_GT(a.marchSteps, a.rays);
        EXPECT_GT(a.shadingEstimates, 0);
        EXPECT_EQ(a.hits, b.hits);
        EXPECT_EQ(a.marchSteps, b.marchSteps);
        EXPECT_EQ(a.iterations, b.iterations);
        EXPECT_EQ(a.shadingEstimates, b.shadingEstimates);
        EXPECT_EQ(a.laneIterations, b.laneIterations);
        EXPECT_EQ(a.laneSlots, b.laneSlots);
        EXPECT_EQ(a.laneSlots > 0, engine == RenderEngine::Simd);
    }
}

// Opaque frames rendered straight to PNG samples (RenderOptions::opaquePngPixels) encode to the
// very bytes of the float image's PNG, on both engines, at both bit depths, with a background of
// one colour and a gradient; frames with coverage alpha still come as the image.
TEST(Render, OpaqueSamplesAreTheImagesPngSamples) {
    Scene scene = referenceScene("case01_sqr_A");
    scene.render.width = 70;  // tiles of 16 that do not divide the image
    scene.render.height = 45;
    scene.render.alpha = AlphaMode::Opaque;
    RenderOptions asSamples;
    asSamples.opaquePngPixels = true;
    for (RenderEngine engine : {RenderEngine::Simd, RenderEngine::Scalar}) {
        for (int bitDepth : {8, 16}) {
            for (bool uniform : {true, false}) {
                scene.render.engine = engine;
                scene.render.bitDepth = bitDepth;
                scene.shading.backgroundTop =
                    uniform ? scene.shading.backgroundBottom : Color(0.9, 0.2, 0.1);
                const RenderResult image = render(scene, RenderOptions{});
                const RenderResult samples = render(scene, asSamples);
                EXPECT_EQ(samples.image.width(), 0);
                ASSERT_EQ(samples.pngPixelsFormat.colorType, PngColorType::Rgb);
                EXPECT_EQ(writePngBytes(samples.pngPixelsFormat, samples.pngPixels),
                          encodePng(image.image, bitDepth, true))
                    << bitDepth << " bits, uniform background " << uniform;
            }
        }
    }
    scene.render.alpha = AlphaMode::Coverage;
    const RenderResult coverage = render(scene, asSamples);
    EXPECT_TRUE(coverage.pngPixels.empty());
    EXPECT_EQ(coverage.image.width(), scene.render.width);
}

// RenderOptions::onlySample: each pixel's samples rendered one at a time are the uniform
// render's, which is their mean (opaque: composited over the background), on both engines, and
// a sample outside the pixel's is refused before work (bench/adaptive_study relies on both).
TEST(Render, SamplesOneAtATimeAverageToTheUniformRender) {
    for (RenderEngine engine : {RenderEngine::Simd, RenderEngine::Scalar}) {
        Scene scene = defaultScene();
        scene.render.width = 40;
        scene.render.height = 30;
        scene.render.samples = 4;
        scene.render.adaptive = true;  // ignored where one sample is asked for
        scene.render.engine = engine;
        scene.render.alpha = AlphaMode::Opaque;
        RenderOptions options;
        options.passes = true;
        scene.render.adaptive = false;
        const std::vector<Rgba> uniform = render(scene, options).passes.linear;
        scene.render.adaptive = true;
        std::vector<Rgba> sum(uniform.size());
        std::vector<Rgba> first;
        int differing = 0;  // pixels whose samples differ: they are not one sample four times
        for (int k = 0; k < 4; ++k) {
            options.onlySample = k;
            const std::vector<Rgba> one = render(scene, options).passes.linear;
            ASSERT_EQ(one.size(), uniform.size());
            for (size_t p = 0; p < one.size(); ++p) {
                sum[p].r += one[p].r, sum[p].g += one[p].g, sum[p].b += one[p].b;
                if (k > 0) differing += !(one[p] == first[p]);
            }
            if (k == 0) first = one;
        }
        EXPECT_GT(differing, 20);
        double largest = 0;
        for (size_t p = 0; p < uniform.size(); ++p) {
            largest = std::max({largest, double(std::abs(sum[p].r / 4 - uniform[p].r)),
                                double(std::abs(sum[p].g / 4 - uniform[p].g)),
                                double(std::abs(sum[p].b / 4 - uniform[p].b))});
        }
        EXPECT_LT(largest, 1e-5) << (engine == RenderEngine::Simd ? "simd" : "scalar");
        options.onlySample = 4;
        EXPECT_THROW(render(scene, options), std::invalid_argument);
    }
}

TEST(Render, RejectsBadFormulaBeforeWork) {
    Scene scene = unitBallScene(8, 8);
    scene.fractal.formula = "z^2 + x";
    try {
        render(scene);
        FAIL() << "expected a UserError";
    } catch (const UserError& e) {
        EXPECT_EQ(e.key(), "fractal.formula");
        EXPECT_NE(std::string(e.what()).find("column 7"), std::string::npos) << e.what();
    }
}

// Algorithm 2 (fixed steps, membership by iteration) and sphere tracing find the same surface.
TEST(Render, FixedStepAndSphereTracingSilhouettesAgree) {
    int index = 0;
    for (const char* id : {"case01_sqr_A", "case03_sqr_C", "case05_sqr_E", "case08_cube_F"}) {
        if (!testing::runsCase(index++, 4)) continue;
        Scene scene = referenceScene(id);
        scene.render.width = 200;
        scene.render.height = 150;
        RenderResult traced = render(scene);
        scene.render.method = MarchMethod::FixedStep;
        scene.render.step = 0.001;
        RenderResult stepped = render(scene);
        MaskComparison comparison = testing::compareNonEmptyMasks(maskFromAlpha(traced.image),
                                                                  maskFromAlpha(stepped.image), id);
        EXPECT_GE(comparison.iou, 0.99) << id;
        std::printf("%s fixed-step vs sphere: %s\n", id, describe(comparison).c_str());
    }
}

}  // namespace
}  // namespace quaternia
