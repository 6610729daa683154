// Every reference case (tests/data/reference), rendered as a Quaternia scene, against the
// brute-force silhouette: the same camera, slice, iteration and bailout must give the same
// picture up to the marcher's sub-pixel offset surface.
#include <gtest/gtest.h>

#include <cstdio>

#include "quaternia/image/mask_compare.h"
#include "quaternia/image/png_io.h"
#include "quaternia/render/render.h"
#include "quaternia/scene/test_scenes.h"

namespace quaternia {
namespace {

class ReferenceCase : public ::testing::TestWithParam<const char*> {};

TEST_P(ReferenceCase, SilhouetteMatchesBruteForceMask) {
    const std::string id = GetParam();
    Scene scene = testing::referenceScene(id);
    ASSERT_EQ(scene.render.width, 320);
    ASSERT_EQ(scene.render.samples, 1);
    RenderResult result = render(scene);
    Mask rendered = maskFromAlpha(result.image);
    Mask brute = maskFromImage(
        readPng(testing::testDataPath("reference/masks/" + id + "_brute_320x240.png")));
    MaskComparison comparison = compareMasks(rendered, brute);
    const double allowed = 0.002 * double(comparison.countB);
    EXPECT_GE(comparison.iou, 0.97) << id;
    EXPECT_LE(double(comparison.farFromB), allowed) << id << ": rendered pixels far from mask";
    EXPECT_LE(double(comparison.farFromA), allowed) << id << ": mask pixels far from render";
    if (::testing::Test::HasFailure()) {
        std::string base = ::testing::TempDir() + id;
        writePng(base + "_rendered.png", result.image, 8);
        writePng(base + "_difference.png", differenceImage(rendered, brute), 8);
        std::fprintf(stderr, "wrote %s_rendered.png and %s_difference.png\n", base.c_str(),
                     base.c_str());
    }
    std::printf("%s: %s\n", id.c_str(), describe(comparison).c_str());
    RecordProperty("iou", std::to_string(comparison.iou));
}

// Over-relaxed sphere tracing (render.relaxation, the default) against plain steps: it draws
// the same silhouette or one closer to the brute-force mask, never anything far from the plain
// one, in far fewer steps. (It can draw fewer grazing pixels: its longer steps in confirmation
// leave the set's neighbourhood before the confirmation budget ends on an offset surface.)
TEST_P(ReferenceCase, RelaxedMarchIsAsCloseToTheMaskAsPlainSteps) {
    const std::string id = GetParam();
    Scene scene = testing::referenceScene(id);
    Mask brute = maskFromImage(
        readPng(testing::testDataPath("reference/masks/" + id + "_brute_320x240.png")));
    scene.render.relaxation = 1;
    RenderResult plain = render(scene);
    scene.render.relaxation = 1.8;
    RenderResult relaxed = render(scene);
    const MaskComparison plainToMask = compareMasks(maskFromAlpha(plain.image), brute);
    const MaskComparison relaxedToMask = compareMasks(maskFromAlpha(relaxed.image), brute);
    const MaskComparison relaxedToPlain =
        compareMasks(maskFromAlpha(relaxed.image), maskFromAlpha(plain.image));
    EXPECT_GE(relaxedToMask.iou, plainToMask.iou - 0.0005) << id;
    EXPECT_LE(relaxedToMask.farFromA + relaxedToMask.farFromB,
              plainToMask.farFromA + plainToMask.farFromB)
        << id;
    EXPECT_GE(relaxedToPlain.iou, 0.99) << id;
    EXPECT_EQ(relaxedToPlain.farFromA + relaxedToPlain.farFromB, 0) << id;
    EXPECT_LT(double(relaxed.stats.marchSteps), 0.85 * double(plain.stats.marchSteps)) << id;
    std::printf("%s: relaxed %s; plain %s; steps %lld vs %lld\n", id.c_str(),
                describe(relaxedToMask).c_str(), describe(plainToMask).c_str(),
                (long long)relaxed.stats.marchSteps, (long long)plain.stats.marchSteps);
}

INSTANTIATE_TEST_SUITE_P(Reference, ReferenceCase,
                         ::testing::Values("case01_sqr_A", "case03_sqr_C", "case05_sqr_E",
                                           "case06_sqr_A_tilt", "case08_cube_F"));

}  // namespace
}  // namespace quaternia
