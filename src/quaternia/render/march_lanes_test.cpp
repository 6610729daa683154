// The SIMD lanes against the scalar reference they mirror (distance.cpp, fractal.cpp,
// march.cpp): the same estimates, normals and march ends, in double lanes to rounding and in
// float lanes to the precision of floats.
#include "quaternia/render/lanes/march_lanes.h"

#include <gtest/gtest.h>

#include <hwy/targets.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "quaternia/algebra/formula.h"
#include "quaternia/render/camera.h"
#include "quaternia/render/lane_test_helpers.h"
#include "quaternia/render/march.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/scene/test_scenes.h"

namespace quaternia {
namespace {

Fractal tiltedFractal() {
    Scene scene = testing::referenceScene("case06_sqr_A_tilt");
    scene.slice.anglesDegrees = {10, 0, 20, 0, 30, 0};  // and a 4D rotation on top of the tilt
    return fractalFromScene(scene);
}

using testing::randomPoints;

TEST(LaneFractal, AffineMapEqualsTheSlice) {
    Fractal fractal = tiltedFractal();
    const LaneFractal lanes = LaneFractal::from(fractal, Precision::Double);
    PointBatch points = randomPoints(50, 2, 1);
    for (size_t i = 0; i < points.size(); ++i) {
        Point3d p(points.x[i], points.y[i], points.z[i]);
        Quaternion q = fractal.slice().quaternionFromWorld(p);
        for (int c = 0; c < 4; ++c) {
            double mapped = lanes.origin[c] + p.x * lanes.axes[0][c] + p.y * lanes.axes[1][c] +
                            p.z * lanes.axes[2][c];
            EXPECT_NEAR(mapped, q[c], 1e-12);
        }
    }
}

TEST(LaneFractal, ComplexConstantViewKeepsEveryOrbitRadius) {
    // docs/facts.md, Symmetries: conjugation by a unit quaternion is an automorphism, so the
    // rotated slice with the complex c' = Re c + |Im c| i has orbits of the same radii.
    Fractal fractal = tiltedFractal();
    const LaneFractal given = LaneFractal::from(fractal, Precision::Double);
    const LaneFractal rotated = given.withComplexConstant();
    const double imaginary = std::hypot(given.c[1], given.c[2], given.c[3]);
    ASSERT_GT(imaginary, 0.1);
    EXPECT_EQ(rotated.c[0], given.c[0]);
    EXPECT_NEAR(rotated.c[1], imaginary, 1e-15);
    EXPECT_EQ(rotated.c[2], 0);
    EXPECT_EQ(rotated.c[3], 0);
    auto map = [](const LaneFractal& f, const Point3d& p) {
        auto component = [&](int k) {
            return f.origin[k] + p.x * f.axes[0][k] + p.y * f.axes[1][k] + p.z * f.axes[2][k];
        };
        return Quaternion(component(0), component(1), component(2), component(3));
    };
    auto constant = [](const LaneFractal& f) { return Quaternion(f.c[0], f.c[1], f.c[2], f.c[3]); };
    PointBatch points = randomPoints(50, 1.5, 3);
    for (size_t i = 0; i < points.size(); ++i) {
        Point3d p(points.x[i], points.y[i], points.z[i]);
        Quaternion z = map(given, p), w = map(rotated, p);
        for (int n = 0; n < 6 && normSquared(z) < 16; ++n) {
            EXPECT_NEAR(normSquared(w), normSquared(z), 1e-9 * (1 + normSquared(z)))
                << "point " << i << ", iterate " << n;
            z = given.scale * z * z + constant(given);
            w = rotated.scale * w * w + constant(rotated);
        }
    }
    // A real c is complex already.
    LaneFractal real = given;
    real.c = {-0.5, 0, 0, 0};
    EXPECT_EQ(real.withComplexConstant().axes, real.axes);
}

TEST(LaneFractal, PowerFormsTakeTheirLoopsAndEveryOtherFormulaItsProgram) {
    Scene scene = testing::referenceScene("case01_sqr_A");
    EXPECT_FALSE(LaneFractal::from(fractalFromScene(scene), Precision::Single).program);
    scene.fractal.formula = "z^3 + c";
    const LaneFractal cubic = LaneFractal::from(fractalFromScene(scene), Precision::Single);
    EXPECT_FALSE(cubic.program);
    EXPECT_EQ(cubic.degree, 3);
    scene.fractal.formula = "i*z*j*z + 0.5*z + c";
    const LaneFractal general = LaneFractal::from(fractalFromScene(scene), Precision::Single);
    ASSERT_TRUE(general.program);
    EXPECT_EQ(general.degree, 2);
    // P(r) = r^2 + 0.5 r: P'(r) = 2 r + 0.5.
    EXPECT_EQ(general.derivativeBound, (std::vector<double>{0.5, 2}));
    // Its program computes the polynomial.
    const Quaternion z(0.3, -0.2, 0.5, 0.1);
    const Fractal fractal = fractalFromScene(scene);
    EXPECT_LT(norm(general.program->evaluate(z) -
                   fractal.setAs<QuaternionJuliaSet>()->polynomial().evaluate(z)),
              1e-15);
}

// Double lanes compute what QuaternionJuliaSet::estimate computes; float lanes agree on membership
// except within rounding of the boundary, and on distance within the float continuation's accuracy.
void expectEstimatesMatch(const Fractal& fractal, unsigned seed) {
    PointBatch points = randomPoints(3000, 1.6, seed);
    for (Precision precision : {Precision::Double, Precision::Single}) {
        const LaneFractal lanes = LaneFractal::from(fractal, precision);
        std::vector<PointEstimate> estimates;
        LaneCounters counters;
        estimatePoints(lanes, points, estimates, counters);
        ASSERT_EQ(estimates.size(), points.size());
        EXPECT_EQ(counters.estimates, int64_t(points.size()));
        int membershipMismatches = 0, insideCount = 0;
        for (size_t i = 0; i < points.size(); ++i) {
            DistanceEstimate reference =
                fractal.estimate(Point3d(points.x[i], points.y[i], points.z[i]));
            const PointEstimate& e = estimates[i];
            insideCount += reference.inside;
            if (e.inside != reference.inside) {
                ++membershipMismatches;
                continue;
            }
            if (precision == Precision::Double) {
                ASSERT_NEAR(e.distance, reference.distance, 1e-9 * (1 + reference.distance));
                ASSERT_EQ(e.iterations, reference.iterations);
                ASSERT_NEAR(e.trap, reference.trap, 1e-9);
            } else if (!reference.inside) {
                // The float lanes stop the continuation at |z| = 100 rather than 1e4.
                ASSERT_NEAR(e.distance, reference.distance, 0.2 * reference.distance + 1e-5);
                ASSERT_GE(e.iterations, reference.escapeIteration);
                ASSERT_LE(e.iterations, reference.iterations);
                ASSERT_NEAR(e.trap, reference.trap, 1e-4 * (1 + reference.trap));
            } else {
                ASSERT_EQ(e.iterations, reference.iterations);
                ASSERT_NEAR(e.trap, reference.trap, 1e-4 * (1 + reference.trap));
            }
        }
        EXPECT_GT(insideCount, 30);
        EXPECT_LE(membershipMismatches, precision == Precision::Double ? 0 : 3);
    }
}

// Distances alone (ambient occlusion's query) take the loop without the orbit where the bailout
// certifies escape, and the general one where it does not: both give the full estimate's
// distance exactly, 0 inside.
TEST(MarchLanes, DistancesAloneEqualTheFullEstimates) {
    Scene certified = testing::referenceScene("case01_sqr_A");
    Scene uncertified = certified;
    uncertified.fractal.bailout = 1.2;  // below the escape radius, about 1.47
    for (const Scene& scene : {certified, uncertified}) {
        const Fractal fractal = fractalFromScene(scene);
        const PointBatch points = randomPoints(2000, 1.6, 12);
        for (Precision precision : {Precision::Double, Precision::Single}) {
            const LaneFractal lanes = LaneFractal::from(fractal, precision);
            std::vector<PointEstimate> estimates;
            std::vector<double> distances;
            LaneCounters full, alone;
            estimatePoints(lanes, points, estimates, full);
            estimateDistances(lanes, points, distances, alone);
            ASSERT_EQ(distances.size(), points.size());
            EXPECT_EQ(alone.estimates, full.estimates);
            int inside = 0;
            for (size_t i = 0; i < points.size(); ++i) {
                ASSERT_EQ(distances[i], estimates[i].distance) << "point " << i;
                inside += estimates[i].inside;
            }
            EXPECT_GT(inside, 30);
        }
    }
}

TEST(MarchLanes, EstimatesMatchTheScalarReference) {
    expectEstimatesMatch(fractalFromScene(testing::referenceScene("case01_sqr_A")), 2);
    expectEstimatesMatch(fractalFromScene(testing::referenceScene("case08_cube_F")), 3);
    expectEstimatesMatch(tiltedFractal(), 4);
}

// Formulas that are not s z^d + c: a real form (float lanes: three numbers; double: the program)
// and single quadratic terms, which the lanes iterate conjugated by w = p1 z (LaneFractal::
// squareMap), |p1| near 1 and far from it, with a right factor.
Fractal formulaFractal(const char* formula) {
    Scene scene = testing::referenceScene("case01_sqr_A");
    scene.fractal.formula = formula;
    return fractalFromScene(scene);
}

TEST(MarchLanes, ProgramEstimatesMatchTheScalarReference) {
    expectEstimatesMatch(formulaFractal("z^2 + 0.1*z + c"), 5);
    expectEstimatesMatch(formulaFractal("(1+0.2i) z (1-0.1k) z + c"), 6);
    expectEstimatesMatch(formulaFractal("(0.3+0.1j) z (1.5-1i) z (1+0.2k) + c"), 7);
    expectEstimatesMatch(formulaFractal("z (0.5+0.1j) z + c"), 8);
}

// A single quadratic term's conjugate computes what the term computes: A(w^2) + c' at w = p1 z
// is p1 p(z), and the slice map is followed by z -> p1 z.
TEST(LaneFractal, SingleQuadraticTermsIterateTheirConjugate) {
    const Fractal fractal = formulaFractal("(0.3+0.1j) z (1.5-1i) z (1+0.2k) + c");
    const LaneFractal lanes = LaneFractal::from(fractal, Precision::Double);
    ASSERT_TRUE(lanes.squareMap);
    const Quaternion p1(1.5, -1, 0, 0);
    EXPECT_NEAR(lanes.normSquaredScale, 1 / normSquared(p1), 1e-15);
    EXPECT_NEAR(lanes.bailoutSquared,
                normSquared(p1) * fractal.setAs<QuaternionJuliaSet>()->bailout() *
                    fractal.setAs<QuaternionJuliaSet>()->bailout(),
                1e-12);
    for (const Quaternion& z : {Quaternion(0.3, -0.2, 0.5, 0.1), Quaternion(-1, 0.4, 0, 0.7)}) {
        const Quaternion w = p1 * z, square = w * w;
        const std::array<double, 4> s{square.w, square.x, square.y, square.z};
        Quaternion mapped;
        double* out[4] = {&mapped.w, &mapped.x, &mapped.y, &mapped.z};
        for (int row = 0; row < 4; ++row) {
            *out[row] = lanes.c[size_t(row)];
            for (int column = 0; column < 4; ++column)
                *out[row] += (*lanes.squareMap)[size_t(4 * row + column)] * s[size_t(column)];
        }
        const Quaternion expected =
            p1 * fractal.setAs<QuaternionJuliaSet>()->polynomial().evaluate(z);
        EXPECT_LT(norm(mapped - expected), 1e-14);
        EXPECT_LT(norm(lanes.program->evaluate(w) - expected), 1e-14);
    }
    const Point3d p(0.2, -0.4, 0.3);
    const Quaternion q = p1 * fractal.slice().quaternionFromWorld(p);
    const Quaternion viaLanes(
        lanes.origin[0] + p.x * lanes.axes[0][0] + p.y * lanes.axes[1][0] + p.z * lanes.axes[2][0],
        lanes.origin[1] + p.x * lanes.axes[0][1] + p.y * lanes.axes[1][1] + p.z * lanes.axes[2][1],
        lanes.origin[2] + p.x * lanes.axes[0][2] + p.y * lanes.axes[1][2] + p.z * lanes.axes[2][2],
        lanes.origin[3] + p.x * lanes.axes[0][3] + p.y * lanes.axes[1][3] + p.z * lanes.axes[2][3]);
    EXPECT_LT(norm(viaLanes - q), 1e-14);
    // Formulas of other shapes keep z.
    EXPECT_FALSE(LaneFractal::from(formulaFractal("z^2 + 0.1*z + c"), Precision::Double).squareMap);
}

// Points just outside the set (where the renderer takes normals): the lanes' analytic gradient
// points the way of Fractal::normal.
TEST(MarchLanes, NormalsMatchTheAnalyticNormal) {
    for (const char* id :
         {"case01_sqr_A", "case08_cube_F", "z^2 + 0.1*z + c", "(1+0.2i) z (1-0.1k) z + c"}) {
        const bool isFormula = std::string(id).find('z') != std::string::npos;
        Fractal fractal =
            isFormula ? formulaFractal(id) : fractalFromScene(testing::referenceScene(id));
        PointBatch all = randomPoints(4000, 1.6, 5), nearSet;
        std::vector<int> iterations;
        for (size_t i = 0; i < all.size(); ++i) {
            Point3d p(all.x[i], all.y[i], all.z[i]);
            DistanceEstimate e = fractal.estimate(p);
            if (e.inside || e.distance > 0.05) continue;
            nearSet.push(p);
            iterations.push_back(fractal.setAs<QuaternionJuliaSet>()->gradientIterations(
                fractal.slice().quaternionFromWorld(p)));
        }
        ASSERT_GT(nearSet.size(), 50u) << id;
        for (Precision precision : {Precision::Double, Precision::Single}) {
            std::vector<Vector3d> normals;
            LaneCounters counters;
            potentialNormals(LaneFractal::from(fractal, precision), nearSet, iterations, normals,
                             counters);
            int poor = 0;
            for (size_t i = 0; i < nearSet.size(); ++i) {
                Vector3d reference =
                    fractal.normal(Point3d(nearSet.x[i], nearSet.y[i], nearSet.z[i]));
                EXPECT_NEAR(length(normals[i]), 1.0, 1e-6);
                double agreement = dot(normals[i], reference);
                if (precision == Precision::Double) {
                    EXPECT_GT(agreement, 1 - 1e-9) << id;
                } else {
                    poor += agreement < 0.999;
                }
            }
            EXPECT_LE(poor, int(nearSet.size() / 100)) << id;
        }
    }
}

// Normals alone (shading without orbit colouring) find each point's M as its estimate does: the
// same normals, bit for bit, as from the estimates' counts, in the three-number lanes (float,
// z^2 + c, certified bailout) and where the counts still come from estimates (double lanes,
// z^3 + c, an uncertified bailout).
TEST(MarchLanes, NormalsAloneEqualTheNormalsOfTheEstimates) {
    Scene certified = testing::referenceScene("case01_sqr_A");
    Scene uncertified = certified;
    uncertified.fractal.bailout = 1.2;  // below the escape radius, about 1.47
    const Scene cubic = testing::referenceScene("case08_cube_F");
    for (const Scene& scene : {certified, uncertified, cubic}) {
        const Fractal fractal = fractalFromScene(scene);
        // Points near the set, where renders take normals, and some inside and far out.
        PointBatch all = randomPoints(6000, 1.6, 21), points;
        for (size_t i = 0; i < all.size(); ++i) {
            const DistanceEstimate e = fractal.estimate(Point3d(all.x[i], all.y[i], all.z[i]));
            if (e.distance < 0.05 || i % 10 == 0)
                points.push(Point3d(all.x[i], all.y[i], all.z[i]));
        }
        ASSERT_GT(points.size(), 700u);
        for (Precision precision : {Precision::Double, Precision::Single}) {
            const LaneFractal lanes = LaneFractal::from(fractal, precision);
            std::vector<PointEstimate> estimates;
            LaneCounters counters;
            estimatePoints(lanes, points, estimates, counters);
            std::vector<int> iterations;
            int inside = 0;
            for (const PointEstimate& e : estimates) {
                iterations.push_back(gradientIterationsOf(e, lanes.maxIterations));
                inside += e.inside;
            }
            EXPECT_GT(inside, 20);
            std::vector<Vector3d> fromEstimates, alone;
            potentialNormals(lanes, points, iterations, fromEstimates, counters);
            potentialNormalsAlone(lanes, points, alone, counters);
            ASSERT_EQ(alone.size(), points.size());
            for (size_t i = 0; i < points.size(); ++i) {
                ASSERT_EQ(alone[i].x, fromEstimates[i].x) << "point " << i;
                ASSERT_EQ(alone[i].y, fromEstimates[i].y) << "point " << i;
                ASSERT_EQ(alone[i].z, fromEstimates[i].z) << "point " << i;
            }
        }
    }
}

// Camera rays in double lanes end as sphereTrace's do: the same kind of end at the same t.
TEST(MarchLanes, CameraRaysEndWhereSphereTracingEnds) {
    Scene scene = testing::referenceScene("case01_sqr_A");
    Fractal fractal = fractalFromScene(scene);
    Camera camera(scene.camera, 64, 48);
    MarchSettings settings{MarchMethod::SphereTracing, 0, scene.render.epsilon,
                           camera.pixelFootprint(1.0), scene.render.maxSteps};
    RayBatch rays;
    std::vector<Ray> kept;
    for (int y = 0; y < 48; ++y) {
        for (int x = 0; x < 64; ++x) {
            Ray ray = camera.generateRay(x + 0.5, y + 0.5);
            auto interval = intersectSphere(ray, fractal.boundingRadius());
            if (!interval) continue;
            rays.push(ray, interval->tNear, interval->tFar);
            kept.push_back(ray);
        }
    }
    std::vector<TraceResult> results;
    LaneCounters counters;
    traceCameraRays(
        LaneFractal::from(fractal, Precision::Double),
        CameraMarch{settings.epsilon, settings.pixelAngle, settings.maxSteps, settings.relaxation},
        rays, results, counters);
    int hits = 0;
    for (size_t i = 0; i < kept.size(); ++i) {
        MarchResult reference = sphereTrace(fractal, kept[i], settings);
        ASSERT_EQ(results[i].end != TraceEnd::Miss, bool(reference.hit)) << i;
        EXPECT_EQ(results[i].steps, reference.steps);
        if (!reference.hit) continue;
        ++hits;
        EXPECT_NEAR(results[i].t, reference.hit->t, 1e-9);
        EXPECT_NEAR(results[i].tOutside,
                    dot(reference.hit->outside - kept[i].origin, kept[i].direction), 1e-9);
    }
    EXPECT_GT(hits, 300);
    EXPECT_GT(counters.laneSlots, 0);
    EXPECT_LE(counters.laneIterations, counters.laneSlots);
}

// Every instruction set compiled in and supported here (e.g. SSE4, AVX2, AVX-512, and the
// portable fallback) computes the same estimates: the runtime dispatch cannot pick a broken one.
TEST(MarchLanes, EveryCompiledTargetAgrees) {
    Fractal fractal = fractalFromScene(testing::referenceScene("case01_sqr_A"));
    const LaneFractal lanes = LaneFractal::from(fractal, Precision::Double);
    PointBatch points = randomPoints(500, 1.6, 6);
    std::vector<int64_t> targets = hwy::SupportedAndGeneratedTargets();
    EXPECT_GE(targets.size(), 2u);
    for (int64_t target : targets) {
        hwy::SetSupportedTargetsForTest(target);
        EXPECT_EQ(std::string(laneTargetName()), hwy::TargetName(target));
        std::vector<PointEstimate> estimates;
        LaneCounters counters;
        estimatePoints(lanes, points, estimates, counters);
        for (size_t i = 0; i < points.size(); ++i) {
            DistanceEstimate reference =
                fractal.estimate(Point3d(points.x[i], points.y[i], points.z[i]));
            ASSERT_EQ(estimates[i].inside, reference.inside) << hwy::TargetName(target);
            ASSERT_NEAR(estimates[i].distance, reference.distance, 1e-9 * (1 + reference.distance))
                << hwy::TargetName(target);
        }
    }
    hwy::SetSupportedTargetsForTest(0);  // back to what the CPU supports
}

}  // namespace
}  // namespace quaternia
