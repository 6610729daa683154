// The scene's set certified (certify_set.h): the classes of points of the algebra against their
// orbits in the algebra itself (the reduced space against quaternion and octonion arithmetic,
// the product against bicomplex arithmetic), and the refusals.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "quaternia/cellmap/certify_set.h"
#include "quaternia/cellmap/orbit_test_helpers.h"
#include "quaternia/fractal/hypercomplex_julia.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/presets.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

Scene sceneWith(const std::vector<std::pair<std::string, ParameterValue>>& values) {
    Scene scene = defaultScene();
    for (const auto& [key, value] : values)
        setParameter(scene, key, value);
    return scene;
}

using testing::staysBounded;

struct Counts {
    int outside = 0, inside = 0, undecided = 0;
};

// Random points of the escape ball: each outside point's orbit escapes, each inside point's
// stays bounded (10^5 iterates; 10^6 for the first 50 inside points).
Counts expectPointsAgreeWithOrbits(const Scene& scene, int resolution, int points) {
    const SetCertification certified = certifySet(scene, resolution, {});
    EXPECT_TRUE(certified.completed);
    const auto julia = hypercomplexJuliaSetOf(scene.fractal);
    const int dimension = algebraDimension(scene.fractal.algebra);
    const double radius = certified.set.escapeRadius;
    std::mt19937_64 random(42);
    std::uniform_real_distribution<double> coordinate(-radius, radius);
    Counts counts;
    for (int n = 0; n < points; ++n) {
        Hypercomplex z{};
        for (int k = 0; k < dimension; ++k)
            z[k] = coordinate(random);
        switch (certified.set.classOfPoint(z, dimension)) {
            case CellClass::kOutside:
                ++counts.outside;
                EXPECT_FALSE(staysBounded(julia->formula(), z, radius, 100000)) << n;
                break;
            case CellClass::kInside:
                ++counts.inside;
                EXPECT_TRUE(staysBounded(julia->formula(), z, radius,
                                         counts.inside <= 50 ? 1000000 : 100000))
                    << n;
                break;
            default:
                ++counts.undecided;
        }
    }
    return counts;
}

TEST(CertifySet, QuaternionPointsAgreeWithOrbits) {
    // c in the main cardioid (a solid K), at 64 cells per axis of the reduced space.
    const Counts counts = expectPointsAgreeWithOrbits(
        sceneWith({{"fractal.c", std::vector<double>{-0.2, 0.3, 0.1, 0}}}), 64, 4000);
    EXPECT_GT(counts.inside, 20);
    EXPECT_GT(counts.outside, 3000);
}

TEST(CertifySet, CubicAndOctonionPointsAgreeWithOrbits) {
    Counts counts =
        expectPointsAgreeWithOrbits(sceneWith({{"fractal.formula", std::string("z^3 - 0.5 z + c")},
                                               {"fractal.c", std::vector<double>{0.1, 0.2, 0, 0}}}),
                                    64, 2000);
    EXPECT_GT(counts.inside, 5);
    counts = expectPointsAgreeWithOrbits(
        sceneWith({{"fractal.algebra", std::string("octonion")},
                   {"fractal.c", std::vector<double>{-0.2, 0.2, 0, 0, 0.1, 0.1, 0, 0}}}),
        64, 2000);
    EXPECT_GT(counts.inside, 0);
    EXPECT_GT(counts.outside, 1500);
}

TEST(CertifySet, BicomplexProductPointsAgreeWithOrbits) {
    Scene scene = defaultScene();
    applyPreset(scene, "bicomplex");
    const Counts counts = expectPointsAgreeWithOrbits(scene, 256, 4000);
    EXPECT_GT(counts.outside, 3000);
}

TEST(CertifySet, DustHasNoInside) {
    // The default scene: its critical orbit escapes, K is a Cantor set.
    const SetCertification certified = certifySet(defaultScene(), 64, {});
    EXPECT_EQ(certified.census[0].inside, 0);
    EXPECT_GT(certified.census[0].outside, 0);
}

TEST(CertifySet, RefusesWhatHasNoReduction) {
    auto keyOf = [](const Scene& scene) {
        try {
            validateSetCertification(scene);
        } catch (const UserError& e) {
            return e.key();
        }
        return std::string();
    };
    EXPECT_EQ(keyOf(sceneWith({{"fractal.formula", std::string("i z^2 j + c")}})),
              "fractal.formula");
    EXPECT_EQ(keyOf(sceneWith({{"fractal.formula", std::string("c z^2 + 0.1")}})),
              "fractal.formula");
    EXPECT_EQ(keyOf(sceneWith({{"fractal.algebra", std::string("coquaternion")}})),
              "fractal.algebra");
    Scene bicomplex = sceneWith({{"fractal.algebra", std::string("bicomplex")},
                                 {"fractal.formula", std::string("sin(z) + c")}});
    EXPECT_EQ(keyOf(bicomplex), "fractal.formula");
    EXPECT_EQ(keyOf(sceneWith({})), "");
}

}  // namespace
}  // namespace quaternia
