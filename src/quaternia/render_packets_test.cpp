// The SIMD render path against the scalar reference renderer: silhouettes (the issue's
// accuracy bar: IoU >= 0.999 at 640x480 on the reference cases), shaded pixels, and the choice
// of path.
#include "render_packets.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "mask_compare.h"
#include "render.h"
#include "test_scenes.h"

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

class PacketSilhouette : public ::testing::TestWithParam<const char*> {};

TEST_P(PacketSilhouette, MatchesTheScalarReferenceMarcher) {
    const std::string id = GetParam();
    RenderResult reference = render(silhouetteScene(id, RenderEngine::Scalar, Precision::Double));
    EXPECT_STREQ(reference.stats.engine, "scalar");
    Mask referenceMask = maskFromAlpha(reference.image);
    for (Precision precision : {Precision::Single, Precision::Double}) {
        RenderResult lanes = render(silhouetteScene(id, RenderEngine::Simd, precision));
        EXPECT_STRNE(lanes.stats.engine, "scalar");
        MaskComparison comparison = compareMasks(maskFromAlpha(lanes.image), referenceMask);
        EXPECT_GE(comparison.iou, 0.999) << id << " " << describe(comparison);
        EXPECT_LE(comparison.farFromA + comparison.farFromB, 2) << id;
        std::printf("%s %s: %s\n", id.c_str(), precision == Precision::Single ? "single" : "double",
                    describe(comparison).c_str());
    }
}

INSTANTIATE_TEST_SUITE_P(ReferenceCases, PacketSilhouette,
                         ::testing::Values("case01_sqr_A", "case03_sqr_C", "case05_sqr_E",
                                           "case06_sqr_A_tilt", "case08_cube_F"));

// Fully shaded (soft shadows, occlusion, orbit-trap colour): the same picture up to float
// rounding, in the mean and almost everywhere.
TEST(PacketRender, ShadedImageMatchesTheScalarPath) {
    Scene scene = testing::referenceScene("case01_sqr_A");
    scene.render.width = 160;
    scene.render.height = 120;
    scene.shading.shadows = Shadows::Soft;
    scene.shading.ambientOcclusion = 0.8;
    scene.render.engine = RenderEngine::Scalar;
    RenderResult reference = render(scene);
    scene.render.engine = RenderEngine::Simd;
    for (Precision precision : {Precision::Single, Precision::Double}) {
        scene.render.precision = precision;
        RenderResult lanes = render(scene);
        EXPECT_EQ(lanes.stats.hits, reference.stats.hits);
        double sum = 0;
        int different = 0;
        const auto& a = lanes.image.pixels();
        const auto& b = reference.image.pixels();
        for (size_t i = 0; i < a.size(); ++i) {
            double difference = std::max({std::abs(a[i].r - b[i].r), std::abs(a[i].g - b[i].g),
                                          std::abs(a[i].b - b[i].b), std::abs(a[i].a - b[i].a)});
            sum += difference;
            different += difference > 0.05;
        }
        EXPECT_LT(sum / double(a.size()), precision == Precision::Double ? 1e-4 : 2e-3);
        EXPECT_LE(different, int(a.size() / 200));
    }
}

TEST(PacketRender, SameImageForAnyThreadCount) {
    Scene scene = testing::referenceScene("case03_sqr_C");
    scene.render.width = 96;
    scene.render.height = 72;
    scene.render.samples = 2;
    RenderOptions one, two;
    one.threads = 1;
    two.threads = 2;
    RenderResult a = render(scene, one), b = render(scene, two);
    ASSERT_EQ(a.image.pixels().size(), b.image.pixels().size());
    for (size_t i = 0; i < a.image.pixels().size(); ++i) {
        ASSERT_EQ(a.image.pixels()[i].r, b.image.pixels()[i].r) << i;
        ASSERT_EQ(a.image.pixels()[i].a, b.image.pixels()[i].a) << i;
    }
    EXPECT_GT(a.stats.laneSlots, 0);
    EXPECT_LE(a.stats.laneIterations, a.stats.laneSlots);
}

// Formulas that are not s z^d + c, and the fixed-step marcher, take the scalar path.
TEST(PacketRender, OtherFormulasAndFixedStepUseTheScalarPath) {
    Scene scene = testing::referenceScene("case01_sqr_A");
    scene.render.width = 16;
    scene.render.height = 12;
    scene.fractal.formula = "i*z*j*z + c";
    EXPECT_STREQ(render(scene).stats.engine, "scalar");
    scene.fractal.formula = "z^2 + c";
    scene.render.method = MarchMethod::FixedStep;
    EXPECT_STREQ(render(scene).stats.engine, "scalar");
    scene.render.method = MarchMethod::SphereTracing;
    EXPECT_STREQ(render(scene).stats.engine, laneTargetName());
}

}  // namespace
}  // namespace quaternia
