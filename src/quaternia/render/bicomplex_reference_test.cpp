// The bicomplex reference cases (tests/data/reference/bicomplex, ORIGIN.md there): POV-Ray's
// hypercomplex julia_fractal, rendered by Quaternia, against the brute-force silhouette of the
// same set (fixed step 0.001, every sample tested by iteration) and against POV-Ray's own
// silhouette: Quaternia must be at least as close to the brute-force mask as POV-Ray is.
#include <gtest/gtest.h>

#include <cstdio>
#include <ostream>
#include <random>
#include <string>

#include "quaternia/fractal/hypercomplex_julia.h"
#include "quaternia/image/mask_compare.h"
#include "quaternia/image/mask_test_helpers.h"
#include "quaternia/image/png_io.h"
#include "quaternia/render/render.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/scene/test_scenes.h"
#include "quaternia/util/sanitized_build.h"

namespace quaternia {
namespace {

Scene bicomplexScene(const std::string& id) {
    return testing::referenceScene("bicomplex/" + id);
}

Mask referenceMask(const std::string& id, const std::string& kind) {
    return maskFromImage(
        readPng(testing::testDataPath("reference/bicomplex/" + id + "_" + kind + "_320x240.png")));
}

// POV-Ray's membership test for hypercomplex sqr (Iteration_HCompl in POV-Ray 3.7's hcmplx.cpp,
// restated): the point (x, y, z) of the default slice is x + y i + z j + 0 k, squared in the
// commutative algebra (i^2 = j^2 = -1, k^2 = 1, ij = k, jk = -i, ik = -j), and it escapes when
// x^2 + y^2 + z^2 + w^2 > 16 for one of z_0 .. z_{N-1}.
bool inPovRaysSet(const Point3d& p, const Quaternion& c, int iterations) {
    double x = p.x, y = p.y, z = p.z, w = 0;
    for (int n = 0; n < iterations; ++n) {
        if (x * x + y * y + z * z + w * w > 16) return false;
        const double x2 = x * x - y * y - z * z + w * w + c.w;
        const double y2 = 2 * (x * y - z * w) + c.x;
        const double z2 = 2 * (x * z - y * w) + c.y;
        const double w2 = 2 * (x * w + y * z) + c.z;
        x = x2, y = y2, z = z2, w = w2;
    }
    return true;
}

// Each case's c and max_iteration as in its POV-Ray scene (bench/scenes/<id>_mask.pov).
struct PovCase {
    const char* id;
    Quaternion c;
    int iterations;
};

void PrintTo(const PovCase& povCase, std::ostream* out) {
    *out << povCase.id;
}

class BicomplexReferenceCase : public ::testing::TestWithParam<PovCase> {};

// The scene files define the set of the masks: POV-Ray's iteration, bailout 4 and slice give
// the same answer as Quaternia's set at points around the set (a disagreement would come from a
// different norm, bailout, iteration count or slice, and would be common).
TEST_P(BicomplexReferenceCase, SceneIsPovRaysHypercomplexSet) {
    const PovCase& povCase = GetParam();
    const std::string id = povCase.id;
    const Scene scene = bicomplexScene(id);
    ASSERT_EQ(scene.fractal.algebra, Algebra::kBicomplex);
    const auto fractal = hypercomplexFractalFromScene(scene);
    std::mt19937 rng(16);
    std::uniform_real_distribution<double> u(-1.6, 1.6);
    int inside = 0, disagree = 0;
    const int count = 200000;
    for (int k = 0; k < count; ++k) {
        const Point3d p(u(rng), u(rng), u(rng));
        const bool pov = inPovRaysSet(p, povCase.c, povCase.iterations);
        inside += pov;
        disagree += pov != fractal.set().contains(fractal.slice().fromWorld(p));
    }
    EXPECT_GT(inside, 100) << id;  // enough points of the set to tell (about 270 and 4400)
    EXPECT_EQ(disagree, 0) << id;
}

// Measured (320x240, one ray per pixel; far = pixels more than one pixel from the other mask,
// both ways):
//   bicomplex01_sqr_A: Quaternia (scalar) IoU 0.9560, far 1; POV-Ray IoU 0.4150, far 1446
//   bicomplex02_sqr_C: Quaternia (scalar) IoU 0.9963, far 0; POV-Ray IoU 0.9452, far 31
//   (the SIMD lanes, float: 0.9547, far 2, and 0.9963, far 0)
// POV-Ray's hypercomplex marcher steps by at least 1/precision (0.05), and by a step from |z_n|^2
// and the normal that bounds nothing, so it skips the thin parts of the set: case A (a product
// with a Cantor dust) loses more than half of it. Quaternia misses 340 pixels of case A's dust
// (and adds 50): on 73 of those rays the estimate exceeds the distance to the first inside
// sample (it estimates the distance to K_1 x K_2, which K_N contains), on the others the dust is
// thinner along the ray than the confirmation steps (kMarchConfirmStep footprints, about 0.002).
// render.method = "fixed-step" with render.step = 0.001 draws both brute-force masks exactly.
// Both engines: the scalar reference (the scenes' engine) and the SIMD lanes
// (bicomplex_lanes-inl.h), float lanes: the same silhouette, within the rounding of floats.
TEST_P(BicomplexReferenceCase, SilhouetteIsCloserToBruteForceThanPovRays) {
    if (!testing::runsCase(std::string(GetParam().id) == "bicomplex01_sqr_A" ? 0 : 1, 2))
        GTEST_SKIP() << "checked in the Release build (util/sanitized_build.h)";
    for (RenderEngine engine : {RenderEngine::Scalar, RenderEngine::Simd}) {
        const std::string id = GetParam().id;
        Scene scene = bicomplexScene(id);
        ASSERT_EQ(scene.render.width, 320);
        ASSERT_EQ(scene.render.samples, 1);
        ASSERT_EQ(scene.render.engine, RenderEngine::Scalar);
        scene.render.engine = engine;
        const RenderResult result = render(scene);
        ASSERT_EQ(std::string(result.stats.engine) == "scalar", engine == RenderEngine::Scalar);
        const Mask rendered = maskFromAlpha(result.image);
        const Mask brute = referenceMask(id, "brute");
        const MaskComparison ours =
            testing::compareNonEmptyMasks(rendered, brute, id + " quaternia");
        const MaskComparison pov =
            testing::compareNonEmptyMasks(referenceMask(id, "pov"), brute, id + " povray");
        EXPECT_GE(ours.iou, pov.iou)
            << id << ": " << describe(ours) << "; POV-Ray " << describe(pov);
        EXPECT_LE(ours.farFromA + ours.farFromB, pov.farFromA + pov.farFromB)
            << id << ": " << describe(ours) << "; POV-Ray " << describe(pov);
        // A wrong camera, slice, iteration count or bailout costs hundreds of far pixels.
        EXPECT_LE(ours.farFromA + ours.farFromB, 5) << id << ": " << describe(ours);
        if (::testing::Test::HasFailure()) {
            const std::string base = ::testing::TempDir() + id;
            writePng(base + "_rendered.png", result.image, 8);
            writePng(base + "_difference.png", differenceImage(rendered, brute), 8);
            std::fprintf(stderr, "wrote %s_rendered.png and %s_difference.png\n", base.c_str(),
                         base.c_str());
        }
        std::printf("%s: quaternia (%s) %s; povray %s\n", id.c_str(), result.stats.engine,
                    describe(ours).c_str(), describe(pov).c_str());
    }
}

INSTANTIATE_TEST_SUITE_P(BicomplexReference, BicomplexReferenceCase,
                         ::testing::Values(PovCase{"bicomplex01_sqr_A", {-0.2, 0.6, 0.2, 0.2}, 20},
                                           PovCase{"bicomplex02_sqr_C", {-0.8, 0.156, 0, 0}, 20}),
                         [](const ::testing::TestParamInfo<PovCase>& caseInfo) {
                             return std::string(caseInfo.param.id);
                         });

}  // namespace
}  // namespace quaternia
