// Point and spot key lights (shading.light_kind) against the geometry of the unit ball, the set
// of z^2 + 0, lit by the key light alone (no ambient, fill or highlight; white; gamma 1): each
// pixel shows max(0, n . L) I / d^2 at the ball's point on its ray, in both engines. And fog
// (shading.fog_density): Beer-Lambert attenuation over each hit's distance.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "quaternia/render/camera.h"
#include "quaternia/render/render.h"
#include "quaternia/scene/test_scenes.h"

namespace quaternia {
namespace {

constexpr int kSize = 81;  // odd: the centre pixel's ray is the camera's axis

Scene litBall(RenderEngine engine, const Vector3d& light, double intensity) {
    Scene scene = testing::darkUnitBallScene(kSize, kSize);
    scene.camera.position = {0, 0, -4};
    scene.render.engine = engine;
    ShadingSettings& s = scene.shading;
    s.lightKind = LightKind::Point;
    s.lightPosition = light;
    s.lightColor = {1, 1, 1};
    s.lightIntensity = intensity;
    s.shadows = Shadows::Hard;
    return scene;
}

// Where the pixel's ray meets the unit sphere, if it does.
std::optional<Point3d> ballPoint(const Camera& camera, int px, int py) {
    const Ray ray = camera.generateRay(px + 0.5, py + 0.5);
    const double b = dot(ray.origin, ray.direction);
    const double disc = b * b - (dot(ray.origin, ray.origin) - 1);
    if (disc < 0.01) return std::nullopt;  // the outline: a hit there is a pixel's guess
    return ray.at(-b - std::sqrt(disc));
}

// The irradiance I / d^2 of a point light on the axis, on the ball's nearest point: moving the
// light from 2 to 4 units off the surface quarters it.
TEST(KeyLight, PointLightFallsWithTheInverseSquare) {
    for (RenderEngine engine : {RenderEngine::Simd, RenderEngine::Scalar}) {
        const int centre = kSize / 2;
        const double near = render(litBall(engine, {0, 0, -3}, 2)).image.at(centre, centre).r;
        const double far = render(litBall(engine, {0, 0, -5}, 2)).image.at(centre, centre).r;
        EXPECT_NEAR(near, 2.0 / (2 * 2), 0.01);
        EXPECT_NEAR(far, 2.0 / (4 * 4), 0.002);
        EXPECT_NEAR(near / far, 4, 0.04);
    }
}

// Every pixel: the cosine law and the inverse square at the ball's point, the light off the
// axis; the far side of the ball from the light is dark.
TEST(KeyLight, PointLightShadesTheBallAsOpticsDoes) {
    const Vector3d light(1.5, 1.0, -2.5);
    for (RenderEngine engine : {RenderEngine::Simd, RenderEngine::Scalar}) {
        const Scene scene = litBall(engine, light, 3);
        const RenderResult result = render(scene);
        const Camera camera(scene.camera, kSize, kSize);
        int checked = 0, dark = 0;
        double worst = 0;
        for (int py = 0; py < kSize; ++py) {
            for (int px = 0; px < kSize; ++px) {
                const std::optional<Point3d> x = ballPoint(camera, px, py);
                if (!x) continue;
                const Vector3d toLight = light - *x;
                const double d = length(toLight);
                const double cosine = dot(Vector3d(*x), toLight / d);
                const double expected = std::max(0.0, cosine) * 3 / (d * d);
                const double value = result.image.at(px, py).r;
                if (cosine < -0.05) {
                    EXPECT_EQ(value, 0) << px << ", " << py;
                    ++dark;
                } else if (cosine > 0.2) {
                    worst = std::max(worst, std::abs(value - expected) / expected);
                    ++checked;
                }
            }
        }
        EXPECT_GT(checked, 1000);
        EXPECT_GT(dark, 200);
        EXPECT_LT(worst, 0.03) << "largest relative difference from max(0, n . L) I / d^2";
    }
}

// A spot light of half-angle 12 degrees and a hard edge, aimed at the ball's centre: points
// within 11 degrees of its axis are lit as by the point light, points beyond 13 are dark.
TEST(KeyLight, SpotLightsOnlyItsCone) {
    const Vector3d light(0.5, 0.5, -3);
    for (RenderEngine engine : {RenderEngine::Simd, RenderEngine::Scalar}) {
        Scene scene = litBall(engine, light, 3);
        scene.shading.lightKind = LightKind::Spot;
        scene.shading.spotTarget = {0, 0, 0};
        scene.shading.spotAngle = 12;
        scene.shading.spotSoftness = 0;
        const RenderResult result = render(scene);
        const Camera camera(scene.camera, kSize, kSize);
        const Vector3d axis = normalize(Vector3d(0, 0, 0) - light);
        int inside = 0, outside = 0;
        for (int py = 0; py < kSize; ++py) {
            for (int px = 0; px < kSize; ++px) {
                const std::optional<Point3d> x = ballPoint(camera, px, py);
                if (!x) continue;
                const Vector3d fromLight = normalize(*x - light);
                const double angle = std::acos(std::clamp(dot(fromLight, axis), -1.0, 1.0));
                const double cosine = -dot(Vector3d(*x), fromLight);
                const double value = result.image.at(px, py).r;
                if (angle > 13 * M_PI / 180) {
                    EXPECT_EQ(value, 0) << px << ", " << py;
                    ++outside;
                } else if (angle < 11 * M_PI / 180 && cosine > 0.2) {
                    const double d = length(light - *x);
                    EXPECT_NEAR(value, cosine * 3 / (d * d), 0.03 * cosine * 3 / (d * d));
                    ++inside;
                }
            }
        }
        EXPECT_GT(inside, 200);
        EXPECT_GT(outside, 200);
    }
}

// Fog of density 0.3: each hit pixel's linear colour is the fogless one times exp(-0.3 t) plus
// the fog colour times the rest, t its distance (the passes give both); the background, at
// infinity, is the fog colour.
TEST(Fog, AttenuatesByBeerLambertOverTheDistance) {
    for (RenderEngine engine : {RenderEngine::Simd, RenderEngine::Scalar}) {
        Scene scene = litBall(engine, {1.5, 1.0, -2.5}, 3);
        scene.shading.ambient = 0.1;
        RenderOptions options;
        options.passes = true;
        const RenderResult clear = render(scene, options);
        const Color fog(0.2, 0.4, 0.6);
        scene.shading.fogDensity = 0.3;
        scene.shading.fogColor = fog;
        const RenderResult foggy = render(scene, options);
        int hits = 0;
        for (size_t i = 0; i < clear.passes.linear.size(); ++i) {
            const Rgba& a = clear.passes.linear[i];
            const Rgba& b = foggy.passes.linear[i];
            if (clear.passes.object[i] == 0) {
                EXPECT_NEAR(b.r, fog.x, 1e-6);
                EXPECT_NEAR(b.b, fog.z, 1e-6);
                continue;
            }
            ++hits;
            const double kept = std::exp(-0.3 * clear.passes.distance[i]);
            EXPECT_NEAR(b.r, a.r * kept + fog.x * (1 - kept), 1e-5) << i;
            EXPECT_NEAR(b.g, a.g * kept + fog.y * (1 - kept), 1e-5) << i;
            EXPECT_NEAR(b.b, a.b * kept + fog.z * (1 - kept), 1e-5) << i;
        }
        EXPECT_GT(hits, 1000);
    }
}

}  // namespace
}  // namespace quaternia
