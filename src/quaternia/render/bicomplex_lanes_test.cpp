// Bicomplex polynomials in the SIMD lanes (bicomplex_lanes-inl.h) against the scalar reference
// they mirror (HypercomplexJuliaSet, hypercomplex_julia.cpp): the same membership in K_N,
// estimates, escape counts and normals, in double lanes to rounding and in float lanes to the
// precision of floats; and the renders that use them.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "quaternia/render/lanes/march_lanes.h"
#include "quaternia/render/render.h"
#include "quaternia/scene/parameters.h"

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

PointBatch randomPoints(int count, double radius, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> coordinate(-radius, radius);
    PointBatch points;
    for (int i = 0; i < count; ++i)
        points.push(Point3d(coordinate(random), coordinate(random), coordinate(random)));
    return points;
}

TEST(BicomplexLanes, TakenOnlyWhereEveryEscapeIsACertainOne) {
    const Fractal square = Fractal::fromScene(bicomplexScene("z^2 + c", kConstants[0]));
    EXPECT_TRUE(LaneFractal::fromBicomplex(square, Precision::Single));
    // A bailout below the components' escape radii (about 1.5 here): |q| can escape while neither
    // component is sure to; the scalar reference's Lipschitz fallback is then needed.
    EXPECT_FALSE(LaneFractal::fromBicomplex(
        Fractal::fromScene(bicomplexScene("z^2 + c", kConstants[0], 1.2)), Precision::Single));
    EXPECT_FALSE(LaneFractal::fromBicomplex(
        Fractal::fromScene(bicomplexScene("sin(z) + c", kConstants[0])), Precision::Single));
    Scene octonion = bicomplexScene("z^2 + c", kConstants[0]);
    octonion.fractal.algebra = Algebra::kCoquaternion;
    EXPECT_FALSE(LaneFractal::fromBicomplex(Fractal::fromScene(octonion), Precision::Single));
}

TEST(BicomplexLanes, EstimatesMatchTheScalarReference) {
    for (size_t f = 0; f < 2; ++f) {
        const Fractal fractal = Fractal::fromScene(bicomplexScene(kFormulas[f], kConstants[f]));
        const PointBatch points = randomPoints(3000, 1.6, unsigned(11 + f));
        for (Precision precision : {Precision::Double, Precision::Single}) {
            const std::optional<LaneFractal> lanes = LaneFractal::fromBicomplex(fractal, precision);
            ASSERT_TRUE(lanes) << kFormulas[f];
            std::vector<PointEstimate> estimates;
            std::vector<double> distances;
            LaneCounters counters;
            estimatePoints(*lanes, points, estimates, counters);
            estimateDistances(*lanes, points, distances, counters);
            int mismatches = 0, inside = 0, outside = 0;
            for (size_t i = 0; i < points.size(); ++i) {
                const Point3d p(points.x[i], points.y[i], points.z[i]);
                const DistanceEstimate reference = fractal.estimate(p);
                const PointEstimate& e = estimates[i];
                ASSERT_EQ(distances[i], e.distance);
                inside += reference.inside;
                outside += !reference.inside && reference.distance < 0.1;
                if (e.inside != reference.inside) {
                    ++mismatches;
                    continue;
                }
                const double smooth =
                    e.inside ? fractal.hypercomplex()->set.maxIterations()
                             : smoothEscapeCount(e.iterations, e.radiusSquared,
                                                 fractal.hypercomplex()->set.formula().degree());
                if (precision == Precision::Double) {
                    ASSERT_NEAR(e.distance, reference.distance, 1e-9 * (1 + reference.distance))
                        << kFormulas[f] << " at " << p;
                    ASSERT_EQ(e.iterations, reference.escapeIteration);
                    ASSERT_NEAR(e.trap, reference.trap, 1e-9);
                    ASSERT_NEAR(smooth, reference.smoothIteration, 1e-9);
                } else {
                    // Float lanes continue to |w| = 100 rather than 1e4.
                    ASSERT_NEAR(e.distance, reference.distance, 0.2 * reference.distance + 1e-5)
                        << kFormulas[f] << " at " << p;
                    ASSERT_NEAR(e.trap, reference.trap, 1e-4 * (1 + reference.trap));
                }
            }
            EXPECT_GT(inside, 30) << kFormulas[f];
            EXPECT_GT(outside, 30) << kFormulas[f];
            EXPECT_LE(mismatches, precision == Precision::Double ? 0 : 3) << kFormulas[f];
        }
    }
}

TEST(BicomplexLanes, NormalsMatchTheScalarReference) {
    for (size_t f = 0; f < 2; ++f) {
        const Fractal fractal = Fractal::fromScene(bicomplexScene(kFormulas[f], kConstants[f]));
        const HypercomplexFractal& other = *fractal.hypercomplex();
        PointBatch all = randomPoints(4000, 1.6, unsigned(21 + f)), nearSet;
        std::vector<int> iterations;
        for (size_t i = 0; i < all.size(); ++i) {
            const Point3d p(all.x[i], all.y[i], all.z[i]);
            const DistanceEstimate e = fractal.estimate(p);
            if (e.inside || e.distance > 0.05) continue;
            nearSet.push(p);
            iterations.push_back(other.set.gradientIterations(other.slice.fromWorld(p)));
        }
        ASSERT_GT(nearSet.size(), 50u) << kFormulas[f];
        for (Precision precision : {Precision::Double, Precision::Single}) {
            std::vector<Vector3d> normals, alone;
            LaneCounters counters;
            const LaneFractal lanes = *LaneFractal::fromBicomplex(fractal, precision);
            potentialNormals(lanes, nearSet, iterations, normals, counters);
            potentialNormalsAlone(lanes, nearSet, alone, counters);
            int poor = 0;
            for (size_t i = 0; i < nearSet.size(); ++i) {
                const Vector3d reference =
                    fractal.normal(Point3d(nearSet.x[i], nearSet.y[i], nearSet.z[i]));
                EXPECT_NEAR(length(normals[i]), 1.0, 1e-6);
                const double agreement = dot(normals[i], reference);
                if (precision == Precision::Double) {
                    EXPECT_GT(agreement, 1 - 1e-9) << kFormulas[f];
                    EXPECT_GT(dot(alone[i], reference), 1 - 1e-9) << kFormulas[f];
                } else {
                    poor += agreement < 0.999;
                }
            }
            EXPECT_LE(poor, int(nearSet.size() / 100)) << kFormulas[f];
        }
    }
}

// The whole picture, shaded (soft shadows, occlusion, orbit colouring): the lanes draw what the
// scalar reference draws, within the rounding of where each ray stops.
TEST(BicomplexLanes, RenderMatchesTheScalarPath) {
    Scene scene = bicomplexScene("z^2 + c", kConstants[0]);
    scene.render.width = 160;
    scene.render.height = 120;
    scene.shading.shadows = Shadows::Soft;
    scene.render.engine = RenderEngine::Scalar;
    const RenderResult reference = render(scene);
    scene.render.engine = RenderEngine::Simd;
    const RenderResult lanes = render(scene);
    EXPECT_STRNE(lanes.stats.engine, "scalar");
    ASSERT_GT(reference.stats.hits, 2000);
    EXPECT_NEAR(double(lanes.stats.hits), double(reference.stats.hits),
                0.002 * double(reference.stats.hits));
    double absolute = 0;
    const auto& a = lanes.image.pixels();
    const auto& b = reference.image.pixels();
    for (size_t i = 0; i < a.size(); ++i)
        absolute +=
            (std::abs(a[i].r - b[i].r) + std::abs(a[i].g - b[i].g) + std::abs(a[i].b - b[i].b)) / 3;
    EXPECT_LT(absolute / double(reference.stats.hits), 0.03);
}

}  // namespace
}  // namespace quaternia
