// Symmetries of quaternion Julia sets (docs/facts.md, Symmetries) seen in whole renders.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "quaternia/image/mask_compare.h"
#include "quaternia/image/mask_test_helpers.h"
#include "quaternia/render/render.h"
#include "quaternia/scene/test_scenes.h"

namespace quaternia {
namespace {

Scene complexScene() {
    Scene scene = testing::referenceScene("case03_sqr_C");  // c = -0.8 + 0.156 i
    scene.render.width = 160;
    scene.render.height = 120;
    return scene;
}

void expectSameSilhouette(const Scene& a, const Scene& b) {
    MaskComparison comparison = testing::compareNonEmptyMasks(maskFromAlpha(render(a).image),
                                                              maskFromAlpha(render(b).image));
    EXPECT_GE(comparison.iou, 0.999);
    EXPECT_EQ(comparison.farFromA, 0);
    EXPECT_EQ(comparison.farFromB, 0);
}

// For c in span{1, i}, turning the slice in the (j, k) plane leaves the picture unchanged.
TEST(Symmetry, HiddenDimensionRotationLeavesRenderUnchanged) {
    Scene rotated = complexScene();
    rotated.slice.anglesDegrees = {0, 0, 0, 0, 0, 37};
    expectSameSilhouette(complexScene(), rotated);
}

// left = u, right = conj(u) with u = exp(i theta/2) is conjugation by u, which fixes c in
// span{1, i}: again the same picture.
TEST(Symmetry, ConjugationFixingCLeavesRenderUnchanged) {
    Scene rotated = complexScene();
    const double half = 0.61;
    rotated.slice.left = Quaternion(std::cos(half), std::sin(half), 0, 0);
    rotated.slice.right = conj(rotated.slice.left);
    expectSameSilhouette(complexScene(), rotated);
}

// K = -K for z^2 + c. A camera at -P with sky -up has forward -f, the same right vector and
// up -u, so its ray through image point (-x, y) is the point reflection of the first camera's
// ray through (x, y): it sees the same silhouette mirrored left to right.
TEST(Symmetry, CentralSymmetryGivesMirroredViewFromOppositeCamera) {
    Scene scene = testing::referenceScene("case01_sqr_A");
    scene.render.width = 160;
    scene.render.height = 120;
    Scene opposite = scene;
    opposite.camera.position = -scene.camera.position;
    opposite.camera.up = -scene.camera.up;
    Mask a = maskFromAlpha(render(scene).image);
    Mask b = maskFromAlpha(render(opposite).image);
    Mask mirrored = b;
    for (int y = 0; y < b.height; ++y) {
        for (int x = 0; x < b.width; ++x) {
            mirrored.inside[y * b.width + x] = b.inside[y * b.width + (b.width - 1 - x)];
        }
    }
    MaskComparison comparison = testing::compareNonEmptyMasks(a, mirrored);
    EXPECT_GE(comparison.iou, 0.995);
    EXPECT_GT(comparison.countA, 1000);
}

}  // namespace
}  // namespace quaternia
