// The SIMD render path against the scalar reference renderer: silhouettes (the issue's
// accuracy bar: IoU >= 0.999 at 640x480 on the reference cases), shaded pixels, and the choice
// of path.
#include "quaternia/render/lane_tile_renderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>

#include "quaternia/image/mask_compare.h"
#include "quaternia/image/mask_test_helpers.h"
#include "quaternia/render/render.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/scene/test_scenes.h"
#include "quaternia/util/sanitized_build.h"

namespace quaternia {
namespace {

Scene silhouetteScene(const std::string& id, RenderEngine engine, Precision precision) {
    Scene scene = testing::referenceScene(id);
    scene.render.width = 640;
    scene.render.height = 480;
    scene.render.engine = engine;
    scene.render.precision = precision;
    scene.shading.shadows = Shadows::None;  // the silhouette only: no shading work
    scene.shading.ambientOcclusion = 0;
    return scene;
}

class LaneSilhouette : public ::testing::TestWithParam<const char*> {};

TEST_P(LaneSilhouette, MatchesTheScalarReferenceMarcher) {
    const std::string id = GetParam();
    RenderResult reference = render(silhouetteScene(id, RenderEngine::Scalar, Precision::Double));
    EXPECT_STREQ(reference.stats.engine, "scalar");
    Mask referenceMask = maskFromAlpha(reference.image);
    for (Precision precision : {Precision::Single, Precision::Double}) {
        RenderResult lanes = render(silhouetteScene(id, RenderEngine::Simd, precision));
        EXPECT_STRNE(lanes.stats.engine, "scalar");
        MaskComparison comparison =
            testing::compareNonEmptyMasks(maskFromAlpha(lanes.image), referenceMask, id);
        EXPECT_GE(comparison.iou, 0.999) << id << " " << describe(comparison);
        EXPECT_LE(comparison.farFromA + comparison.farFromB, 2) << id;
        std::printf("%s %s: %s\n", id.c_str(), precision == Precision::Single ? "single" : "double",
                    describe(comparison).c_str());
    }
}

INSTANTIATE_TEST_SUITE_P(ReferenceCases, LaneSilhouette,
                         ::testing::Values("case01_sqr_A", "case03_sqr_C", "case05_sqr_E",
                                           "case06_sqr_A_tilt", "case08_cube_F"));

// Formulas that are not s z^d + c run in the lanes as compiled programs (formula_program.h):
// ten of degrees 2 to 5, with real, one-sided and two-sided quaternion coefficients and several
// top-degree terms, each against the scalar reference, which iterates the expanded polynomial.
struct ProgramCase {
    const char* formula;
    Quaternion c;
};
// gtest names each case by its formula (not "40-byte object").
void PrintTo(const ProgramCase& given, std::ostream* out) {
    *out << given.formula;
}
class ProgramSilhouette : public ::testing::TestWithParam<ProgramCase> {};

TEST_P(ProgramSilhouette, MatchesTheScalarReferenceMarcher) {
    const ProgramCase& given = GetParam();
    auto scene = [&](RenderEngine engine, Precision precision) {
        Scene s = silhouetteScene("case01_sqr_A", engine, precision);
        s.render.width = 320;
        s.render.height = 240;
        s.fractal.formula = given.formula;
        s.fractal.c = given.c;
        return s;
    };
    const RenderResult reference = render(scene(RenderEngine::Scalar, Precision::Double));
    const Mask referenceMask = maskFromAlpha(reference.image);
    // A set that is not empty in view, nor the whole view.
    EXPECT_GT(reference.stats.hits, 320 * 240 / 50) << given.formula;
    EXPECT_LT(reference.stats.hits, 320 * 240 * 9 / 10) << given.formula;
    for (Precision precision : {Precision::Single, Precision::Double}) {
        const RenderResult lanes = render(scene(RenderEngine::Simd, precision));
        EXPECT_STREQ(lanes.stats.engine, laneTargetName());
        const MaskComparison comparison =
            testing::compareNonEmptyMasks(maskFromAlpha(lanes.image), referenceMask, given.formula);
        EXPECT_GE(comparison.iou, 0.999) << given.formula << " " << describe(comparison);
        // No pixel more than one pixel away from the other silhouette.
        EXPECT_EQ(comparison.farFromA + comparison.farFromB, 0) << given.formula;
        std::printf("%s %s: %s\n", given.formula,
                    precision == Precision::Single ? "single" : "double",
                    describe(comparison).c_str());
    }
}

INSTANTIATE_TEST_SUITE_P(
    TenFormulas, ProgramSilhouette,
    ::testing::Values(ProgramCase{"z^2 + 0.1*z + c", {-0.2, 0.6, 0.2, 0.2}},
                      ProgramCase{"(1+0.2i) z (1-0.1k) z + c", {-0.2, 0.6, 0.2, 0.2}},
                      ProgramCase{"z^2 + (0.1+0.2j)*z + c", {-0.2, 0.6, 0.2, 0.2}},
                      ProgramCase{"i*z*j*z + 0.3*z + c", {0.1, 0.1, 0, 0.05}},
                      ProgramCase{"z^3 + 0.2*z^2 + c", {-0.5, 0.5, 0, 0}},
                      ProgramCase{"z (0.9+0.3j) z z + c", {-0.5, 0.5, 0.1, 0}},
                      ProgramCase{"(z + 0.1i)^3 - 0.1*z + c", {-0.4, 0.5, 0, 0.1}},
                      ProgramCase{"z^4 - 0.3*z + c", {-0.6, 0.2, 0.1, 0}},
                      ProgramCase{"z^2 (1+0.1k) z^2 + 0.5*z^4 + c", {-0.5, 0.3, 0, 0}},
                      ProgramCase{"z^5 + 0.1*z^2 + c", {-0.6, 0.4, 0, 0}}));

// Fully shaded (soft shadows, occlusion, orbit-trap colour): the same picture. Not pixel for
// pixel: the cones start each ray elsewhere than the scalar marcher does, so each lands at
// another point within a fraction of a footprint of the surface, and the normal of a fractal
// surface turns fast at that scale. So the images agree in silhouette, in the mean (no bias in
// light, shadow or colour) and on average per pixel within a few percent.
TEST(LaneRender, ShadedImageMatchesTheScalarPath) {
    Scene scene = testing::referenceScene("case01_sqr_A");
    scene.render.width = 320;
    scene.render.height = 240;
    scene.shading.shadows = Shadows::Soft;
    scene.shading.ambientOcclusion = 0.8;
    scene.render.engine = RenderEngine::Scalar;
    RenderResult reference = render(scene);
    scene.render.engine = RenderEngine::Simd;
    for (Precision precision : {Precision::Single, Precision::Double}) {
        scene.render.precision = precision;
        RenderResult lanes = render(scene);
        EXPECT_NEAR(double(lanes.stats.hits), double(reference.stats.hits),
                    0.001 * double(reference.stats.hits));
        double absolute = 0, signedSum = 0;
        const auto& a = lanes.image.pixels();
        const auto& b = reference.image.pixels();
        for (size_t i = 0; i < a.size(); ++i) {
            double difference = (a[i].r - b[i].r) + (a[i].g - b[i].g) + (a[i].b - b[i].b);
            absolute += std::abs(difference) / 3;
            signedSum += difference / 3;
        }
        const double hits = double(reference.stats.hits);
        std::printf("per hit pixel: mean |difference| %.4f, mean difference %.5f\n",
                    absolute / hits, signedSum / hits);
        EXPECT_LT(absolute / hits, 0.03);
        EXPECT_LT(std::abs(signedSum / hits), 0.003);
    }
}

// Hard shadows: the shadow rays of each block are shortened to where a cylinder about them
// stopped, or left out where it cleared them whole (LaneTileRenderer::clipShadowRays). A
// cylinder only proves the set absent where the rays would have found it absent, so every
// pixel keeps its light, with fewer estimates.
TEST(LaneRender, ShadowCylindersChangeNoPixel) {
    for (const char* id : {"case01_sqr_A", "case06_sqr_A_tilt"}) {
        Scene scene = testing::referenceScene(id);
        scene.shading.shadows = Shadows::Hard;
        const Fractal fractal = fractalFromScene(scene);
        const Camera camera(scene.camera, 320, 240);
        const Shader shader(scene.shading, fractal);
        const MarchSettings march{MarchMethod::SphereTracing, 0, scene.render.epsilon,
                                  camera.pixelFootprint(1.0), scene.render.maxSteps};
        const LaneFractal lanes = LaneFractal::from(fractal, Precision::Single);
        LaneTileRenderer plain(lanes, camera, shader, march, 1, false);
        LaneTileRenderer clipped(lanes, camera, shader, march, 1, true);
        int64_t plainEstimates = 0, clippedEstimates = 0;
        int hits = 0, changed = 0;
        for (int y0 = 0; y0 < 240; y0 += 32) {
            for (int x0 = 0; x0 < 320; x0 += 32) {
                const Tile tile{x0, y0, std::min(x0 + 32, 320), std::min(y0 + 32, 240)};
                std::vector<PixelSamples> a, b;
                LaneTileStats statsA, statsB;
                plain.render(tile, a, statsA);
                clipped.render(tile, b, statsB);
                plainEstimates += statsA.shading.estimates;
                clippedEstimates += statsB.shading.estimates;
                ASSERT_EQ(a.size(), b.size());
                for (size_t i = 0; i < a.size(); ++i) {
                    ASSERT_EQ(a[i].hits, b[i].hits);
                    hits += a[i].hits;
                    changed += length(a[i].sum - b[i].sum) > 1e-6;
                }
            }
        }
        EXPECT_GT(hits, 10000) << id;
        EXPECT_LE(changed, hits / 1000) << id;
        EXPECT_LT(double(clippedEstimates), 0.95 * double(plainEstimates)) << id;
        std::printf("%s: %d of %d hit pixels changed, shading estimates %lld -> %lld\n", id,
                    changed, hits, (long long)plainEstimates, (long long)clippedEstimates);
    }
}

// The tile size (imageParallelOptions: 16, 32 or 64 pixels) changes no pixel: the cone blocks
// and shadow cylinders lie on the same 4-pixel grid in tiles of any of these sizes, and each
// ray is marched alone whatever the lanes beside it hold; adaptive sampling's decisions read
// the first samples of a border about each tile, as its neighbour tiles have them.
TEST(LaneRender, TileSizeChangesNoPixel) {
    Scene scene = testing::referenceScene("case01_sqr_A");
    scene.shading.shadows = Shadows::Hard;
    const Fractal fractal = fractalFromScene(scene);
    const int width = 200, height = 136;  // partial tiles of every size at the right and bottom
    const Camera camera(scene.camera, width, height);
    const Shader shader(scene.shading, fractal);
    const MarchSettings march{MarchMethod::SphereTracing, 0, scene.render.epsilon,
                              camera.pixelFootprint(1.0), scene.render.maxSteps};
    const LaneFractal lanes = LaneFractal::from(fractal, Precision::Single);
    // Adaptive sampling too: its decisions take the first samples of a border about the tile.
    // And with the ground, whose shadow rays of the camera's pixels are grouped by block.
    ShadingSettings softly = scene.shading;
    softly.shadows = Shadows::Soft;
    const Shader softShader(softly, fractal);
    GroundSettings ground;
    ground.enabled = true;
    ground.height = -1.1;
    ground.color = Color(0.6, 0.6, 0.6);
    for (auto [samples, withGround] :
         {std::pair{1, false}, std::pair{16, false}, std::pair{1, true}, std::pair{16, true}}) {
        SCOPED_TRACE(std::to_string(samples) + (withGround ? " samples, the ground" : " samples"));
        auto renderInTiles = [&](int size) {
            LaneTileRenderer renderer(lanes, camera, withGround ? softShader : shader, march,
                                      samples, true, true);
            if (withGround) renderer.setScenery(scene.material, ground);
            std::vector<PixelSamples> image(size_t(width * height)), tilePixels;
            for (int y0 = 0; y0 < height; y0 += size) {
                for (int x0 = 0; x0 < width; x0 += size) {
                    const Tile tile{x0, y0, std::min(x0 + size, width),
                                    std::min(y0 + size, height)};
                    LaneTileStats stats;
                    renderer.render(tile, tilePixels, stats);
                    const int tileWidth = tile.x1 - tile.x0;
                    for (int y = tile.y0; y < tile.y1; ++y) {
                        for (int x = tile.x0; x < tile.x1; ++x)
                            image[size_t(y * width + x)] =
                                tilePixels[size_t((y - tile.y0) * tileWidth + (x - tile.x0))];
                    }
                }
            }
            return image;
        };
        const std::vector<PixelSamples> reference = renderInTiles(32);
        int hits = 0, groundHits = 0;
        for (const PixelSamples& p : reference)
            hits += p.hits, groundHits += p.groundHits;
        EXPECT_GT(hits, 5000);
        if (withGround) {
            EXPECT_GT(groundHits, 5000);
        }
        for (int size : {16, 64}) {
            const std::vector<PixelSamples> image = renderInTiles(size);
            for (size_t i = 0; i < image.size(); ++i) {
                ASSERT_EQ(image[i].hits, reference[i].hits) << size << "-pixel tiles, pixel " << i;
                ASSERT_EQ(image[i].sum.x, reference[i].sum.x)
                    << size << "-pixel tiles, pixel " << i;
                ASSERT_EQ(image[i].sum.y, reference[i].sum.y)
                    << size << "-pixel tiles, pixel " << i;
                ASSERT_EQ(image[i].sum.z, reference[i].sum.z)
                    << size << "-pixel tiles, pixel " << i;
                ASSERT_EQ(image[i].depthSum, reference[i].depthSum) << size << "-pixel tiles";
                ASSERT_EQ(image[i].samples, reference[i].samples) << size << "-pixel tiles";
            }
        }
    }
}

// A single quadratic term p0 z p1 z p2 + c runs as its conjugate w = p1 z, whose radii are |p1|
// times z's; the set still lies in the ball of the bailout of z in 3D. With |p1| about 0.5 the
// lanes once took the conjugate's scaled bailout as the bounding sphere and cut the set to
// about half its pixels (IoU near 0.5). The slice of this set is a slanted one through a
// rotated quaternion Julia set (K = p1^-1 K'), rough at the pixel scale, where the marchers'
// rare over-steps differ: IoU 0.988 between the engines, ten pixels more than one pixel apart.
TEST(LaneRender, ConjugatedTermsKeepTheWholeSet) {
    auto scene = [](RenderEngine engine) {
        Scene s = silhouetteScene("case01_sqr_A", engine, Precision::Double);
        s.render.width = 128;
        s.render.height = 96;
        s.fractal.formula = "z (0.5+0.1j) z + c";
        return s;
    };
    const RenderResult reference = render(scene(RenderEngine::Scalar));
    const RenderResult lanes = render(scene(RenderEngine::Simd));
    ASSERT_GT(reference.stats.hits, 2000);
    const MaskComparison comparison = testing::compareNonEmptyMasks(
        maskFromAlpha(lanes.image), maskFromAlpha(reference.image), "conjugated term");
    EXPECT_GE(comparison.iou, 0.97) << describe(comparison);
    EXPECT_LE(comparison.farFromA + comparison.farFromB, 30) << describe(comparison);
}

// With a bailout below the escape radius (uncertainEscapeDistance, distance.h) the lanes and
// their cones draw the near surface the scalar marcher draws. The escaping estimate used to
// overshoot K_N there, and a cone stopping on it started its whole 4x4 block of rays behind
// the near surface: square blocks of a deeper layer (several hundred pixels at 192x144).
TEST(LaneRender, UncertainEscapeDrawsTheScalarPathsNearSurface) {
    auto scene = [](RenderEngine engine, Precision precision) {
        Scene s = silhouetteScene("case01_sqr_A", engine, precision);
        s.render.width = 192;
        s.render.height = 144;
        s.camera.position = Point3d(2, 3, -8);
        s.fractal.formula = "z (0.5+0.1j) z + c";
        s.fractal.c = {-0.307692, 1.076923, 0.461538, 0.615385};
        return s;
    };
    RenderOptions options;
    options.depth = true;
    const RenderResult reference = render(scene(RenderEngine::Scalar, Precision::Double), options);
    ASSERT_GT(reference.stats.hits, 2000);
    for (Precision precision : {Precision::Single, Precision::Double}) {
        const RenderResult lanes = render(scene(RenderEngine::Simd, precision), options);
        const auto& a = lanes.depth.pixels();
        const auto& b = reference.depth.pixels();
        int deeper = 0;
        for (size_t i = 0; i < a.size(); ++i)
            deeper += a[i] < 1 && b[i] < 1 && std::abs(a[i] - b[i]) > 0.02;
        EXPECT_LE(deeper, reference.stats.hits / 100) << "pixels at another depth";
    }
}

// Formulas that are not s z^d + c, and the fixed-step marcher, take the scalar path.
TEST(LaneRender, EveryFormulaTakesTheLanesAndFixedStepTheScalarPath) {
    Scene scene = testing::referenceScene("case01_sqr_A");
    scene.render.width = 16;
    scene.render.height = 12;
    scene.fractal.formula = "i*z*j*z + c";
    EXPECT_STREQ(render(scene).stats.engine, laneTargetName());
    scene.fractal.formula = "z^2 + c";
    scene.render.method = MarchMethod::FixedStep;
    EXPECT_STREQ(render(scene).stats.engine, "scalar");
    scene.render.method = MarchMethod::SphereTracing;
    RenderResult lanes = render(scene);
    EXPECT_STREQ(lanes.stats.engine, laneTargetName());
    EXPECT_GT(lanes.stats.laneSlots, 0);
    EXPECT_LE(lanes.stats.laneIterations, lanes.stats.laneSlots);
}

}  // namespace
}  // namespace quaternia

namespace quaternia {
namespace {

// The quaternion half of the 8-component algebras (fractal.cpp, quaternionHalf): a biquaternion
// or octonion scene whose c and slice lie in H is drawn as the quaternion set, in the lanes (and
// an octonion scene in another quaternion subalgebra, octonionQuaternionSubalgebra); the
// scalar engine draws it in its own algebra (biquaternions by Algorithm 2's fixed steps, crossing
// proven empty space), and the silhouettes agree.
struct HalfCase {
    const char* name;
    Algebra algebra;
    const char* formula;
    // Moved by psi: 1, i, j, k -> 1, i, e4, e5 into the octonions' quaternion subalgebra
    // generated by i and e4 (fractal.cpp, octonionQuaternionSubalgebra): c's j and k parts as e4
    // and e5, the slice's axes 1, i, e4.
    bool otherSubalgebra = false;
};
void PrintTo(const HalfCase& given, std::ostream* out) {
    *out << given.name;
}
class QuaternionHalfSilhouette : public ::testing::TestWithParam<HalfCase> {};

TEST_P(QuaternionHalfSilhouette, MatchesTheScalarReferenceInItsAlgebra) {
    const HalfCase& given = GetParam();
    // The scalar biquaternions take seconds (fixed steps); under the sanitizers the octonion
    // case takes the same paths of the lanes (sanitized_build.h).
    if (testing::kSanitizedBuild && given.algebra == Algebra::kBiquaternion) GTEST_SKIP();
    auto scene = [&](RenderEngine engine) {
        Scene s = silhouetteScene("case01_sqr_A", engine, Precision::Double);
        s.render.width = 320;
        s.render.height = 240;
        s.render.step = 0.0005;
        // Sphere tracing takes the epsilon-offset surface for grazing rays (march.h): at the
        // default 0.25 footprints that alone moves 0.1 to 0.4% of the silhouette's pixels
        // against fixed steps, in the quaternions themselves too; at 0.05, 0.02 to 0.04%.
        s.render.epsilon = 0.05;
        s.fractal.algebra = given.algebra;
        s.fractal.formula = given.formula;
        s.fractal.cComponents = 8;
        // The quaternions' bailout where the algebra's default differs (biquaternions: 2).
        s.fractal.bailout = 2;
        if (given.otherSubalgebra) {
            s.fractal.cUpper = {s.fractal.c.y, s.fractal.c.z, 0, 0};
            s.fractal.c.y = s.fractal.c.z = 0;
            s.slice.origin.assign(8, 0.0);
            s.slice.axes.assign(24, 0.0);
            s.slice.axes[0] = s.slice.axes[8 + 1] = s.slice.axes[16 + 4] = 1;
        }
        return s;
    };
    const RenderResult reference = render(scene(RenderEngine::Scalar));
    EXPECT_STREQ(reference.stats.engine, "scalar");
    EXPECT_GT(reference.stats.hits, 320 * 240 / 50) << given.name;
    const RenderResult lanes = render(scene(RenderEngine::Simd));
    EXPECT_STREQ(lanes.stats.engine, laneTargetName()) << given.name;
    const MaskComparison comparison = testing::compareNonEmptyMasks(
        maskFromAlpha(lanes.image), maskFromAlpha(reference.image), given.name);
    EXPECT_GE(comparison.iou, 0.999) << given.name << " " << describe(comparison);
    EXPECT_EQ(comparison.farFromA + comparison.farFromB, 0) << given.name;
    std::printf("%s: %s\n", given.name, describe(comparison).c_str());
}

INSTANTIATE_TEST_SUITE_P(
    EightComponentAlgebras, QuaternionHalfSilhouette,
    ::testing::Values(
        HalfCase{"biquaternion", Algebra::kBiquaternion, "z^2 + c"},
        HalfCase{"biquaternion_two_sided", Algebra::kBiquaternion, "(1+0.2i) z (1-0.1k) z + c"},
        HalfCase{"octonion_two_sided", Algebra::kOctonion, "(i z) (z j) + c"},
        HalfCase{"octonion_subalgebra_i_e4", Algebra::kOctonion, "(i z) (z i) + c", true}),
    [](const ::testing::TestParamInfo<HalfCase>& param) { return std::string(param.param.name); });

}  // namespace
}  // namespace quaternia
