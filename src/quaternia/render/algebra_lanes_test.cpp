// The other algebras in the SIMD lanes against the scalar reference they mirror
// (HypercomplexJuliaSet, hypercomplex_julia.cpp): bicomplex polynomials (bicomplex_lanes-inl.h)
// and octonion real forms folded onto the quaternions (octonion_fold.h). The same membership in
// K_N, estimates, escape counts and normals, in double lanes to rounding and in float lanes to
// the precision of floats; and the renders that use them.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <optional>
#include <random>
#include <string>

#include "quaternia/render/lane_test_helpers.h"
#include "quaternia/render/lanes/march_lanes.h"
#include "quaternia/render/render.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_fractal.h"

namespace quaternia {
namespace {

Scene bicomplexScene(const std::string& formula, const Quaternion& c, double bailout = 0) {
    Scene scene = defaultScene();
    scene.fractal.algebra = Algebra::kBicomplex;
    scene.fractal.formula = formula;
    scene.fractal.c = c;
    scene.fractal.maxIterations = 20;
    scene.fractal.bailout = bailout;
    scene.slice.anglesDegrees = {10, 0, 20, 0, 30, 0};  // a rotated slice: all four components
    return scene;
}

// z^2 + c (both components w^2 + c_i: their own loop) and a cubic with bicomplex coefficients
// (Horner's rule on each component's polynomial).
const char* const kFormulas[] = {"z^2 + c", "z^3 + (0.2+0.1j)*z^2 - 0.1k*z + c"};
const Quaternion kConstants[] = {Quaternion(-0.2, 0.7, 0.1, 0.05), Quaternion(-0.3, 0.4, 0.1, 0)};

using testing::randomPoints;

TEST(BicomplexLanes, TakenOnlyWhereEveryEscapeIsACertainOne) {
    const Fractal square = fractalFromScene(bicomplexScene("z^2 + c", kConstants[0]));
    EXPECT_TRUE(LaneFractal::fromBicomplex(square, Precision::Single));
    // A bailout below the components' escape radii (about 1.5 here): |q| can escape while neither
    // component is sure to; the scalar reference's Lipschitz fallback is then needed.
    EXPECT_FALSE(LaneFractal::fromBicomplex(
        fractalFromScene(bicomplexScene("z^2 + c", kConstants[0], 1.2)), Precision::Single));
    EXPECT_FALSE(LaneFractal::fromBicomplex(
        fractalFromScene(bicomplexScene("sin(z) + c", kConstants[0])), Precision::Single));
    Scene coquaternion = bicomplexScene("z^2 + c", kConstants[0]);
    coquaternion.fractal.algebra = Algebra::kCoquaternion;
    EXPECT_FALSE(LaneFractal::fromBicomplex(fractalFromScene(coquaternion), Precision::Single));
}

// The lanes of `fractal` in a precision.
using LanesOf = std::function<LaneFractal(Precision)>;

// The lanes' estimates against Fractal::estimate at random points: membership, distance, the
// trap and the smooth escape count (the colouring's), and the counts where `iterations` takes
// them from the reference.
void expectEstimatesMatch(const Fractal& fractal, const LanesOf& lanesOf, int degree,
                          int (*iterations)(const DistanceEstimate&), const std::string& label,
                          unsigned seed) {
    const PointBatch points = randomPoints(3000, 1.6, seed);
    for (Precision precision : {Precision::Double, Precision::Single}) {
        const LaneFractal lanes = lanesOf(precision);
        std::vector<PointEstimate> estimates;
        std::vector<double> distances;
        LaneCounters counters;
        estimatePoints(lanes, points, estimates, counters);
        estimateDistances(lanes, points, distances, counters);
        int mismatches = 0, inside = 0, near = 0;
        for (size_t i = 0; i < points.size(); ++i) {
            const Point3d p(points.x[i], points.y[i], points.z[i]);
            const DistanceEstimate reference = fractal.estimate(p);
            const PointEstimate& e = estimates[i];
            ASSERT_EQ(distances[i], e.distance);
            inside += reference.inside;
            near += !reference.inside && reference.distance < 0.1;
            if (e.inside != reference.inside) {
                ++mismatches;
                continue;
            }
            const double smooth = e.inside
                                      ? reference.smoothIteration
                                      : smoothEscapeCount(e.iterations, e.radiusSquared, degree);
            if (precision == Precision::Double) {
                ASSERT_NEAR(e.distance, reference.distance, 1e-9 * (1 + reference.distance))
                    << label << " at " << p;
                ASSERT_EQ(e.iterations, iterations(reference)) << label << " at " << p;
                ASSERT_NEAR(e.trap, reference.trap, 1e-9);
                ASSERT_NEAR(smooth, reference.smoothIteration, 1e-9);
            } else {
                // Float lanes continue to |w| = 100 rather than 1e4.
                ASSERT_NEAR(e.distance, reference.distance, 0.2 * reference.distance + 1e-5)
                    << label << " at " << p;
                ASSERT_NEAR(e.trap, reference.trap, 1e-4 * (1 + reference.trap));
            }
        }
        EXPECT_GT(inside, 30) << label;  // the points see the set and its surroundings
        EXPECT_GT(near, 30) << label;
        EXPECT_LE(mismatches, precision == Precision::Double ? 0 : 3) << label;
    }
}

// The lanes' normals, with each point's M from the reference and found by the lanes
// themselves, against Fractal::normal near the surface.
void expectNormalsMatch(const Fractal& fractal, const LanesOf& lanesOf, const std::string& label,
                        unsigned seed) {
    PointBatch all = randomPoints(4000, 1.6, seed), nearSet;
    std::vector<int> iterations;
    for (size_t i = 0; i < all.size(); ++i) {
        const Point3d p(all.x[i], all.y[i], all.z[i]);
        const DistanceEstimate e = fractal.estimate(p);
        if (e.inside || e.distance > 0.05) continue;
        nearSet.push(p);
        iterations.push_back(fractal.set().gradientIterations(fractal.slice().fromWorld(p)));
    }
    ASSERT_GT(nearSet.size(), 50u) << label;
    for (Precision precision : {Precision::Double, Precision::Single}) {
        std::vector<Vector3d> normals, alone;
        LaneCounters counters;
        const LaneFractal lanes = lanesOf(precision);
        potentialNormals(lanes, nearSet, iterations, normals, counters);
        potentialNormalsAlone(lanes, nearSet, alone, counters);
        int poor = 0;
        for (size_t i = 0; i < nearSet.size(); ++i) {
            const Vector3d reference =
                fractal.normal(Point3d(nearSet.x[i], nearSet.y[i], nearSet.z[i]));
            EXPECT_NEAR(length(normals[i]), 1.0, 1e-6);
            const double agreement = dot(normals[i], reference);
            if (precision == Precision::Double) {
                EXPECT_GT(agreement, 1 - 1e-9) << label;
                EXPECT_GT(dot(alone[i], reference), 1 - 1e-9) << label;
            } else {
                poor += agreement < 0.999 || dot(alone[i], reference) < 0.999;
            }
        }
        EXPECT_LE(poor, int(nearSet.size() / 100)) << label;
    }
}

// The whole picture, shaded (soft shadows, occlusion, orbit colouring): the lanes draw what the
// scalar reference draws, within the rounding of where each ray stops.
void expectRenderMatches(Scene scene, int minimumHits) {
    scene.render.width = 128;
    scene.render.height = 96;
    scene.shading.shadows = Shadows::Soft;
    scene.render.engine = RenderEngine::Scalar;
    const RenderResult reference = render(scene);
    scene.render.engine = RenderEngine::Simd;
    const RenderResult lanes = render(scene);
    EXPECT_STRNE(lanes.stats.engine, "scalar");
    ASSERT_GT(reference.stats.hits, minimumHits);
    EXPECT_NEAR(double(lanes.stats.hits), double(reference.stats.hits),
                0.003 * double(reference.stats.hits));
    double absolute = 0;
    const auto& a = lanes.image.pixels();
    const auto& b = reference.image.pixels();
    for (size_t i = 0; i < a.size(); ++i)
        absolute +=
            (std::abs(a[i].r - b[i].r) + std::abs(a[i].g - b[i].g) + std::abs(a[i].b - b[i].b)) / 3;
    EXPECT_LT(absolute / double(reference.stats.hits), 0.03);
}

int escapeIterationOf(const DistanceEstimate& e) {
    return e.escapeIteration;
}
int iterationsOf(const DistanceEstimate& e) {
    return e.iterations;
}

TEST(BicomplexLanes, EstimatesMatchTheScalarReference) {
    for (size_t f = 0; f < 2; ++f) {
        const Fractal fractal = fractalFromScene(bicomplexScene(kFormulas[f], kConstants[f]));
        expectEstimatesMatch(
            fractal, [&](Precision p) { return *LaneFractal::fromBicomplex(fractal, p); },
            fractal.setAs<HypercomplexJuliaSet>()->formula().degree(), escapeIterationOf,
            kFormulas[f], unsigned(11 + f));
    }
}

TEST(BicomplexLanes, NormalsMatchTheScalarReference) {
    for (size_t f = 0; f < 2; ++f) {
        const Fractal fractal = fractalFromScene(bicomplexScene(kFormulas[f], kConstants[f]));
        expectNormalsMatch(
            fractal, [&](Precision p) { return *LaneFractal::fromBicomplex(fractal, p); },
            kFormulas[f], unsigned(21 + f));
    }
}

TEST(BicomplexLanes, RenderMatchesTheScalarPath) {
    expectRenderMatches(bicomplexScene("z^2 + c", kConstants[0]), 1000);
}

// An octonion scene on a slice whose directions orthogonal to 1 and Im c span four dimensions
// (no isometry into H: only the fold's length takes the orbit to the quaternions), with an
// origin that is not orthogonal to the axes (the bounding sphere grows).
Scene octonionScene(const std::string& formula) {
    Scene scene = defaultScene();
    scene.fractal.algebra = Algebra::kOctonion;
    scene.fractal.formula = formula;
    scene.fractal.c = Quaternion(-0.2, 0.5, 0.1, 0.2);
    scene.fractal.cUpper = {0.15, -0.1, 0.2, 0.05};
    scene.fractal.cComponents = 8;
    scene.fractal.maxIterations = 20;
    scene.slice.origin = {0.05, 0.2, 0, 0, 0, 0.1, 0, 0};
    scene.slice.axes = {1, 0, 0, 0,   0, 0, 0, 0,  //
                        0, 1, 0, 0.2, 0, 0, 0, 0,  //
                        0, 0, 0, 0,   0, 0, 1, 0.3};
    return scene;
}

const char* const kOctonionFormulas[] = {"z^2 + c", "z^3 - 0.5*z + c", "z^2 + 0.1*z + c"};

TEST(OctonionLanes, TheFoldTakesRealFormsOnAnySlice) {
    const Scene scene = octonionScene("z^2 + c");
    const Fractal fractal = fractalFromScene(scene);
    ASSERT_FALSE(fractal.setAs<QuaternionJuliaSet>() !=
                 nullptr);  // no isometry: the fold is needed
    const std::optional<LaneFractal> lanes =
        LaneFractal::fromOctonion(scene, fractal, Precision::Single);
    ASSERT_TRUE(lanes);
    EXPECT_TRUE(lanes->folded);
    // The slice's origin has a part along the axes: the set's 3D bounding sphere is larger than
    // the bailout's.
    EXPECT_GT(lanes->boundingRadius, std::sqrt(lanes->bailoutSquared) + 0.1);
    Scene quaternionCoefficient = octonionScene("i*z^2 + c");
    EXPECT_FALSE(LaneFractal::fromOctonion(
        quaternionCoefficient, fractalFromScene(quaternionCoefficient), Precision::Single));
    const Scene bicomplex = bicomplexScene("z^2 + c", kConstants[0]);
    EXPECT_FALSE(
        LaneFractal::fromOctonion(bicomplex, fractalFromScene(bicomplex), Precision::Single));
}

TEST(OctonionLanes, EstimatesMatchTheOctonionArithmetic) {
    for (const char* formula : kOctonionFormulas) {
        const Scene scene = octonionScene(formula);
        const Fractal fractal = fractalFromScene(scene);
        expectEstimatesMatch(
            fractal, [&](Precision p) { return *LaneFractal::fromOctonion(scene, fractal, p); },
            fractal.setAs<HypercomplexJuliaSet>()->formula().degree(), iterationsOf, formula, 31);
    }
}

TEST(OctonionLanes, NormalsMatchTheOctonionArithmetic) {
    for (const char* formula : kOctonionFormulas) {
        const Scene scene = octonionScene(formula);
        const Fractal fractal = fractalFromScene(scene);
        expectNormalsMatch(
            fractal, [&](Precision p) { return *LaneFractal::fromOctonion(scene, fractal, p); },
            formula, 41);
    }
}

TEST(OctonionLanes, RenderMatchesTheScalarPath) {
    expectRenderMatches(octonionScene("z^2 + c"), 1000);
}

}  // namespace
}  // namespace quaternia
