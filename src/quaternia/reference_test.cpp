// Every reference case (tests/data/reference), rendered as a Quaternia scene, against the
// brute-force silhouette: the same camera, slice, iteration and bailout must give the same
// picture up to the marcher's sub-pixel offset surface.
#include <gtest/gtest.h>

#include <cstdio>

#include "mask_compare.h"
#include "png_io.h"
#include "render.h"
#include "test_scenes.h"

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

INSTANTIATE_TEST_SUITE_P(Reference, ReferenceCase,
                         ::testing::Values("case01_sqr_A", "case03_sqr_C", "case05_sqr_E",
                                           "case06_sqr_A_tilt", "case08_cube_F"));

}  // namespace
}  // namespace quaternia
