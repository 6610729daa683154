// Every reference case (tests/data/reference), rendered as a Quaternia scene, against the
// brute-force silhouette: the same camera, slice, iteration and bailout must give the same
// picture up to the marcher's sub-pixel offset surface.
#include <gtest/gtest.h>

#include <cstdio>

#include <hwy/targets.h>

#include "quaternia/image/mask_compare.h"
#include "quaternia/image/mask_test_helpers.h"
#include "quaternia/image/png_io.h"
#include "quaternia/render/render.h"
#include "quaternia/scene/test_scenes.h"

namespace quaternia {
namespace {

class ReferenceCase : public ::testing::TestWithParam<const char*> {};

Mask bruteForceMask(const std::string& id) {
    return maskFromImage(
        readPng(testing::testDataPath("reference/masks/" + id + "_brute_320x240.png")));
}

// The bounds near what every engine achieves (IoU 0.9977 at worst, case01, and no pixel more
// than one pixel off): a wrong camera, slice, iteration count or bailout costs hundreds of far
// pixels.
void expectCloseToBruteForce(const std::string& id, const std::string& engine,
                             const RenderResult& result, const Mask& brute) {
    const Mask rendered = maskFromAlpha(result.image);
    const MaskComparison comparison =
        testing::compareNonEmptyMasks(rendered, brute, id + " " + engine);
    EXPECT_GE(comparison.iou, 0.995) << id << " " << engine << ": " << describe(comparison);
    EXPECT_LE(comparison.farFromA + comparison.farFromB, 5)
        << id << " " << engine << ": " << describe(comparison);
    if (::testing::Test::HasFailure()) {
        std::string base = ::testing::TempDir() + id + "_" + engine;
        writePng(base + "_rendered.png", result.image, 8);
        writePng(base + "_difference.png", differenceImage(rendered, brute), 8);
        std::fprintf(stderr, "wrote %s_rendered.png and %s_difference.png\n", base.c_str(),
                     base.c_str());
    }
    std::printf("%s %s: %s\n", id.c_str(), engine.c_str(), describe(comparison).c_str());
}

// Every engine the machine can run: the scalar reference marcher, and the lanes in float and
// in double on each SIMD target Highway compiled that this CPU supports (not only the one it
// would choose).
TEST_P(ReferenceCase, SilhouetteMatchesBruteForceMaskOnEveryEngine) {
    const std::string id = GetParam();
    Scene scene = testing::referenceScene(id);
    ASSERT_EQ(scene.render.width, 320);
    ASSERT_EQ(scene.render.samples, 1);
    const Mask brute = bruteForceMask(id);
    scene.render.engine = RenderEngine::Scalar;
    RenderResult scalar = render(scene);
    ASSERT_STREQ(scalar.stats.engine, "scalar");
    expectCloseToBruteForce(id, "scalar", scalar, brute);
    scene.render.engine = RenderEngine::Simd;
    int targets = 0;
    for (int64_t target : hwy::SupportedAndGeneratedTargets()) {
        hwy::SetSupportedTargetsForTest(target);
        for (Precision precision : {Precision::Single, Precision::Double}) {
            scene.render.precision = precision;
            RenderResult lanes = render(scene);
            EXPECT_STREQ(lanes.stats.engine, hwy::TargetName(target));
            expectCloseToBruteForce(id,
                                    std::string(hwy::TargetName(target)) +
                                        (precision == Precision::Single ? " float" : " double"),
                                    lanes, brute);
        }
        ++targets;
    }
    hwy::SetSupportedTargetsForTest(0);
    EXPECT_GE(targets, 1);
}

// Over-relaxed sphere tracing (render.relaxation, the default) against plain steps: it draws
// the same silhouette or one closer to the brute-force mask, never anything far from the plain
// one, in far fewer steps. (It can draw fewer grazing pixels: its longer steps in confirmation
// leave the set's neighbourhood before the confirmation budget ends on an offset surface.)
TEST_P(ReferenceCase, RelaxedMarchIsAsCloseToTheMaskAsPlainSteps) {
    const std::string id = GetParam();
    Scene scene = testing::referenceScene(id);
    const Mask brute = bruteForceMask(id);
    scene.render.relaxation = 1;
    RenderResult plain = render(scene);
    scene.render.relaxation = 1.8;
    RenderResult relaxed = render(scene);
    const MaskComparison plainToMask =
        testing::compareNonEmptyMasks(maskFromAlpha(plain.image), brute, id + " plain");
    const MaskComparison relaxedToMask =
        testing::compareNonEmptyMasks(maskFromAlpha(relaxed.image), brute, id + " relaxed");
    const MaskComparison relaxedToPlain =
        testing::compareNonEmptyMasks(maskFromAlpha(relaxed.image), maskFromAlpha(plain.image), id);
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
