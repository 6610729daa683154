#include "quaternia/render/march.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <random>
#include <vector>

#include "quaternia/render/camera.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_file.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/scene/test_scenes.h"

namespace quaternia {
namespace {

using testing::referenceScene;
using testing::unitBallScene;

TEST(IntersectSphere, FindsEntryAndExit) {
    auto interval = intersectSphere(Ray{{0, 0, -3}, {0, 0, 1}}, 1.0);
    ASSERT_TRUE(interval);
    EXPECT_DOUBLE_EQ(interval->tNear, 2);
    EXPECT_DOUBLE_EQ(interval->tFar, 4);
    EXPECT_FALSE(intersectSphere(Ray{{0, 2, -3}, {0, 0, 1}}, 1.0));
    EXPECT_FALSE(intersectSphere(Ray{{0, 0, 3}, {0, 0, 1}}, 1.0));
    auto inside = intersectSphere(Ray{{0, 0, 0}, {1, 0, 0}}, 1.0);
    ASSERT_TRUE(inside);
    EXPECT_DOUBLE_EQ(inside->tNear, 0);
}

// c = 0 is the unit ball: a ray from (0, 0, -3) towards the origin meets it at t = 2, where the
// normal is the position itself.
TEST(SphereTrace, HitsUnitBallAtTwoWithRadialNormal) {
    Fractal fractal = fractalFromScene(unitBallScene(64, 64));
    MarchSettings settings;
    settings.pixelAngle = 1e-3;
    settings.epsilon = 0.25;
    MarchResult result = sphereTrace(fractal, Ray{{0, 0, -3}, {0, 0, 1}}, settings);
    ASSERT_TRUE(result.hit);
    double epsilon = settings.epsilon * settings.pixelAngle * result.hit->t;
    EXPECT_NEAR(result.hit->t, 2.0, epsilon);
    Vector3d normal = fractal.normal(result.hit->outside);
    EXPECT_NEAR(normal.x, 0, 1e-9);
    EXPECT_NEAR(normal.y, 0, 1e-9);
    EXPECT_NEAR(normal.z, -1, 1e-9);
    // Off axis too: the normal is the hit position, normalised.
    Ray oblique{{0, 0, -3}, normalize(Vector3d(0.2, 0.1, 1))};
    MarchResult other = sphereTrace(fractal, oblique, settings);
    ASSERT_TRUE(other.hit);
    Vector3d radial = normalize(other.hit->position);
    EXPECT_NEAR(dot(fractal.normal(other.hit->outside), radial), 1, 1e-6);
    EXPECT_NEAR(length(other.hit->position), 1, 1e-3);
}

// Towards a plane met at angle theta, an estimate k times the true distance falls linearly
// along the ray: relaxed steps keep consecutive balls touching (so none is taken back), never
// pass the plane, and at shallow angles take far fewer steps than plain sphere tracing.
TEST(RelaxedMarchStep, ApproachesAPlaneWithoutCrossingIt) {
    const double plane = 10;  // where the ray meets it
    for (double degrees : {1.0, 5.0, 20.0, 45.0, 90.0}) {
        for (double k : {1.0, 0.5, 0.25}) {
            const double slope = k * std::sin(degrees * std::numbers::pi / 180);
            auto estimate = [&](double t) { return (plane - t) * slope; };
            auto stepsToReach = [&](double relaxation) {
                double t = 0, tPrevious = 0, radius = 0;
                int steps = 0;
                while (estimate(t) > 1e-3 * slope && steps < 100000) {
                    const double distance = estimate(t);
                    const double step =
                        relaxedMarchStep(relaxation, t, tPrevious, radius, distance);
                    EXPECT_LE(step, radius + distance + 1e-12 * plane)
                        << "gap after a step of " << step;
                    tPrevious = t;
                    radius = distance;
                    t += step;
                    EXPECT_LE(t, plane) << degrees << " degrees, k = " << k;
                    ++steps;
                }
                return steps;
            };
            const int plain = stepsToReach(1), relaxed = stepsToReach(kMarchRelaxation);
            EXPECT_LE(relaxed, plain);
            if (slope <= 0.1) {
                EXPECT_LT(relaxed, 0.65 * plain) << degrees << " degrees, k " << k;
            }
        }
    }
}

TEST(FixedStepMarch, HitsUnitBallAtTwo) {
    Fractal fractal = fractalFromScene(unitBallScene(64, 64));
    MarchSettings settings;
    settings.method = MarchMethod::FixedStep;
    settings.step = 0.01;
    MarchResult result = march(fractal, Ray{{0, 0, -3}, {0, 0, 1}}, settings);
    ASSERT_TRUE(result.hit);
    EXPECT_NEAR(result.hit->t, 2.0, 0.01 / 512);
    EXPECT_FALSE(fixedStepMarch(fractal, Ray{{0, 0, -3}, {0, 1, 0}}, settings).hit);
}

// The distance estimate never carries a ray past the set: along rays where fine fixed steps
// find a first member at t*, every estimate taken on the way there is at most t* - t. The
// estimate bounds the distance to K, so the iteration count is high enough that K_N is K to
// within far less than a step (distance.h).
TEST(SphereTrace, EstimateNeverOvershootsFirstMember) {
    for (const char* id : {"case01_sqr_A", "case06_sqr_A_tilt", "case08_cube_F"}) {
        Scene scene = referenceScene(id);
        scene.fractal.maxIterations = 200;
        Fractal fractal = fractalFromScene(scene);
        Camera camera(scene.camera, 320, 240);
        MarchSettings brute;
        brute.method = MarchMethod::FixedStep;
        brute.step = 0.0005;
        brute.maxSteps = 100000;
        const double epsilon = 0.25 * camera.pixelFootprint(1);
        std::mt19937 rng(5);
        std::uniform_real_distribution<double> x(0, 320), y(0, 240);
        int compared = 0;
        for (int k = 0; k < 400; ++k) {
            Ray ray = camera.generateRay(x(rng), y(rng));
            MarchResult exact = march(fractal, ray, brute);
            if (!exact.hit) continue;
            double t = intersectSphere(ray, fractal.boundingRadius())->tNear;
            for (int step = 0; step < 10000; ++step) {
                DistanceEstimate e = fractal.estimate(ray.at(t));
                if (e.inside || e.distance < epsilon * t) break;
                ASSERT_LE(e.distance, exact.hit->t - t + brute.step) << id << " ray " << k;
                t += e.distance;
            }
            ++compared;
        }
        EXPECT_GT(compared, 50) << id;
    }
}

}  // namespace
}  // namespace quaternia

namespace quaternia {
namespace {

struct ProvenCase {
    const char* name;
    std::vector<const char*> overrides;
};

// Runs crossed by proof (and the bicomplex functions' clearance, duplex_escape_map.h) skip only
// samples outside K_N: along random rays through every algebra's set (formulas with one- and
// two-sided constants, 8-component slices), the first inside sample and the sample before it are
// those of plain fixed steps, which follow every sample's orbit; and the proofs spare most of the
// samples.
TEST(Marching, ProvenRunsFindThePlainStepsSample) {
    const std::vector<ProvenCase> cases = {
        {"coquaternion", {"fractal.algebra=\"coquaternion\""}},
        {"coquaternion two-sided",
         {"fractal.algebra=\"coquaternion\"", "fractal.formula=\"i z^2 j + 0.3 z^3 + c\"",
          "slice.angles=[0, 0, 0, 0, 90, 0]"}},
        {"biquaternion",
         {"fractal.algebra=\"biquaternion\"", "fractal.c=[-0.2, 0.6, 0.2, 0.2, 0, 0.1, 0, 0]",
          "slice.axes=[[0,1,0,0,0,0,0,0],[0,0,0,0,0,1,0,0],[0,0,0,0,0,0,1,0]]"}},
        {"octonion formula",
         {"fractal.algebra=\"octonion\"", "fractal.formula=\"z^2 + 0.2 (i z) j + c\"",
          "fractal.c=[-0.2, 0.6, 0.2, 0.2, 0.1, 0, 0.05, 0]"}},
        {"bicomplex",
         {"fractal.algebra=\"bicomplex\"", "fractal.c=[-0.5613, 0.3724, 0.3724, -0.4387]"}},
        {"bicomplex functions",
         {"fractal.algebra=\"bicomplex\"", "fractal.formula=\"sin(z) + 0.2 exp(z) + c\""}},
        {"bicomplex exp", {"fractal.algebra=\"bicomplex\"", "fractal.formula=\"exp(z) + c\""}},
    };
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> u(-1, 1);
    for (const ProvenCase& test : cases) {
        Scene scene = defaultScene();
        for (const char* assignment : test.overrides)
            applyOverride(scene, assignment);
        const Fractal fractal = fractalFromScene(scene);
        ASSERT_TRUE(fractal.provesEmptySegments()) << test.name;
        const double step = 0.004;
        int64_t proven = 0, plain = 0, hits = 0;
        for (int r = 0; r < 60; ++r) {
            const Point3d origin(3 * u(rng), 3 * u(rng), -4);
            const Ray ray{origin, normalize(Vector3d(0.3 * u(rng), 0.3 * u(rng), 0) - origin)};
            const auto interval = intersectSphere(ray, fractal.boundingRadius());
            if (!interval) continue;
            const SampleCrossing crossing =
                firstSampleInside(fractal, ray, interval->tNear, interval->tFar, step, 1 << 30);
            // Every sample, one by one.
            std::optional<double> tInside;
            double tOutside = interval->tNear;
            int64_t samples = 0;
            for (int64_t k = 0; interval->tNear + double(k) * step <= interval->tFar; ++k) {
                const double t = interval->tNear + double(k) * step;
                ++samples;
                if (fractal.containsByOrbit(ray.at(t))) {
                    tInside = t;
                    break;
                }
                tOutside = t;
            }
            ASSERT_EQ(crossing.tInside.has_value(), tInside.has_value())
                << test.name << " ray " << r;
            if (tInside) {
                ++hits;
                EXPECT_EQ(*crossing.tInside, *tInside) << test.name << " ray " << r;
                EXPECT_EQ(crossing.tOutside, tOutside) << test.name << " ray " << r;
            }
            proven += crossing.steps;
            plain += samples;
        }
        EXPECT_GT(hits, 5) << test.name;
        EXPECT_LT(proven * 4, plain)
            << test.name << ": " << proven << " tests, " << plain << " samples";
    }
}

}  // namespace
}  // namespace quaternia
