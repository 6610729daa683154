// The scene around the set against optics, on the unit ball (the set of z^2 + 0): Fresnel and
// Snell at a surface, a mirror ball that shows the ground where ray optics puts it, a glass
// ball that inverts the background as a ball lens does, white materials in a white world that
// stay white, the ground as a shadow catcher, extra lights, glow: on both engines.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <optional>
#include <random>

#include "quaternia/render/camera.h"
#include "quaternia/render/lane_tile_renderer.h"
#include "quaternia/render/optics.h"
#include "quaternia/render/render.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/scene/test_scenes.h"

namespace quaternia {
namespace {

constexpr int kSize = 81;

// Both engines draw the scene around the set (path_waves.h): the tests below hold each to optics.
constexpr std::array kEngines{RenderEngine::Simd, RenderEngine::Scalar};
const char* nameOf(RenderEngine engine) {
    return engine == RenderEngine::Simd ? "simd" : "scalar";
}
Scene on(Scene scene, RenderEngine engine) {
    scene.render.engine = engine;
    return scene;
}

// The unit ball seen from `eye`, lit by nothing (its own colour black), gamma 1, opaque.
Scene darkBall(const Vector3d& eye) {
    Scene scene = testing::darkUnitBallScene(kSize, kSize);
    scene.camera.position = eye;
    return scene;
}

struct BallHit {
    Point3d point;
    Ray ray;
};
// Where the centre ray of pixel (px, py) meets the unit sphere, away from its outline.
std::optional<BallHit> ballHit(const Camera& camera, int px, int py, double margin = 0.02) {
    const Ray ray = camera.generateRay(px + 0.5, py + 0.5);
    const double b = dot(ray.origin, ray.direction);
    const double disc = b * b - (dot(ray.origin, ray.origin) - 1);
    if (disc < margin) return std::nullopt;
    return BallHit{ray.at(-b - std::sqrt(disc)), ray};
}

TEST(Optics, FresnelMatchesTheFormulaAtNormalAndGrazingIncidence) {
    // Normal incidence: ((n1 - n2) / (n1 + n2))^2, from either side.
    EXPECT_NEAR(fresnelDielectric(1, 1, 1.5), 0.04, 1e-12);
    EXPECT_NEAR(fresnelDielectric(1, 1.5, 1), 0.04, 1e-12);
    EXPECT_NEAR(fresnelDielectric(1, 1, 2.42), std::pow(1.42 / 3.42, 2), 1e-12);
    // Grazing incidence reflects everything.
    EXPECT_NEAR(fresnelDielectric(0, 1, 1.5), 1, 1e-12);
    // Beyond the critical angle asin(1 / 1.5) = 41.8 degrees inside glass: total reflection.
    EXPECT_EQ(fresnelDielectric(std::cos(45 * M_PI / 180), 1.5, 1), 1);
    // At Brewster's angle atan(1.5) the p wave vanishes: R = Rs / 2.
    const double brewster = std::atan(1.5), transmitted = M_PI / 2 - brewster;
    const double rs = std::sin(brewster - transmitted) / std::sin(brewster + transmitted);
    EXPECT_NEAR(fresnelDielectric(std::cos(brewster), 1, 1.5), 0.5 * rs * rs, 1e-12);
    // Schlick: r0 at normal incidence, 1 at grazing, r0 + (1 - r0) (1 - cos)^5 between.
    EXPECT_DOUBLE_EQ(fresnelSchlick(1, 0.3), 0.3);
    EXPECT_DOUBLE_EQ(fresnelSchlick(0, 0.3), 1);
    EXPECT_NEAR(fresnelSchlick(0.5, 0.3), 0.3 + 0.7 / 32, 1e-15);
}

TEST(Optics, RefractionObeysSnellsLaw) {
    std::mt19937 random(7);
    std::normal_distribution<double> normal;
    for (int i = 0; i < 1000; ++i) {
        const Vector3d n = normalize(Vector3d(normal(random), normal(random), normal(random)));
        Vector3d d = normalize(Vector3d(normal(random), normal(random), normal(random)));
        if (dot(d, n) > 0) d = -d;  // towards the surface
        const double n1 = 1 + 0.5 * (i % 3), n2 = 1 + 0.5 * ((i / 3) % 3);
        const double sinI = length(cross(d, n));
        auto t = refract(d, n, n1, n2);
        if (n1 * sinI > n2) {
            EXPECT_FALSE(t) << "total internal reflection";
            continue;
        }
        ASSERT_TRUE(t);
        EXPECT_NEAR(length(*t), 1, 1e-12);
        EXPECT_NEAR(n1 * sinI, n2 * length(cross(*t, n)), 1e-9);  // Snell
        EXPECT_LT(dot(*t, n), 0);                                 // goes on through
        EXPECT_NEAR(dot(cross(d, n), *t), 0, 1e-9);               // in the plane of incidence
    }
    const Vector3d r = reflect(normalize(Vector3d(1, -1, 0)), Vector3d(0, 1, 0));
    EXPECT_NEAR(r.x, std::sqrt(0.5), 1e-15);
    EXPECT_NEAR(r.y, std::sqrt(0.5), 1e-15);
}

// A mirror ball over a red floor under a blue sky: every pixel of the ball shows red where its
// reflected ray meets the plane y = -1.5 and blue where it goes up, in exactly those colours.
TEST(Mirror, BallReflectsTheGroundWhereRayOpticsPutsIt) {
    for (RenderEngine engine : kEngines) {
        SCOPED_TRACE(nameOf(engine));
        Scene scene = darkBall({0, 0.8, -4});
        scene.material.reflectivity = 1;  // Schlick's reflectance is then 1 at every angle
        scene.material.maxDepth = 2;
        scene.ground.enabled = true;
        scene.ground.height = -1.5;
        scene.ground.color = {1, 0, 0};
        scene.shading.ambient = 1;  // the floor's colour, evenly lit
        scene.shading.backgroundTop = scene.shading.backgroundBottom = {0, 0, 1};
        const RenderResult result = render(on(scene, engine));
        const Camera camera(scene.camera, kSize, kSize);
        int checked = 0, red = 0, wrong = 0;
        for (int py = 0; py < kSize; ++py) {
            for (int px = 0; px < kSize; ++px) {
                auto hit = ballHit(camera, px, py);
                if (!hit) continue;
                const Vector3d r = reflect(hit->ray.direction, Vector3d(hit->point));
                if (std::abs(r.y) < 0.03) continue;  // the horizon: a pixel's guess
                const bool floor = r.y < 0;
                const Rgba& c = result.image.at(px, py);
                const bool ok = floor ? (std::abs(c.r - 1) < 2e-3 && c.b < 2e-3)
                                      : (std::abs(c.b - 1) < 2e-3 && c.r < 2e-3);
                ++checked;
                red += floor;
                wrong += !ok;
            }
        }
        EXPECT_GT(checked, 1500);
        EXPECT_GT(red, 500);
        EXPECT_GT(checked - red, 500);
        EXPECT_LE(wrong, checked / 500) << wrong << " of " << checked;
    }
}

// A glass ball (index 1.5) against a sky that brightens upwards, 0.5 + 0.5 y of the direction:
// a ball lens turns the rays through it over, so what lies above the axis is seen below it.
// Each pixel shows the sky along the ray's analytic exit (two refractions), give or take the
// few percent of Fresnel reflection.
TEST(Glass, BallLensInvertsTheBackground) {
    for (RenderEngine engine : kEngines) {
        SCOPED_TRACE(nameOf(engine));
        Scene scene = darkBall({0, 0, -4});
        scene.material.transparency = 1;
        scene.material.ior = 1.5;
        scene.shading.backgroundTop = {1, 1, 1};
        scene.shading.backgroundBottom = {0, 0, 0};
        const RenderResult result = render(on(scene, engine));
        const Camera camera(scene.camera, kSize, kSize);
        int checked = 0, inverted = 0, far = 0;
        for (int py = 0; py < kSize; ++py) {
            for (int px = 0; px < kSize; ++px) {
                auto hit = ballHit(camera, px, py, 0.3);  // the centre, where Fresnel is small
                if (!hit) continue;
                const Vector3d n(hit->point);
                const Vector3d inside = *refract(hit->ray.direction, n, 1, 1.5);
                // The chord of the unit sphere from the entry point along `inside`.
                const Point3d exit = hit->point + inside * (-2 * dot(hit->point, inside));
                auto out = refract(inside, -Vector3d(exit), 1.5, 1);
                ASSERT_TRUE(out);
                // The sky along the way out, and what the Fresnel reflections at entry and exit
                // may add: the entry's reflection of the sky, the exit's internal reflection of
                // anything between black and white.
                auto sky = [](const Vector3d& v) { return 0.5 + 0.5 * v.y; };
                const double entry = fresnelDielectric(-dot(hit->ray.direction, n), 1, 1.5);
                const double exitReflectance =
                    fresnelDielectric(dot(inside, Vector3d(exit)), 1.5, 1);
                const double least = entry * sky(reflect(hit->ray.direction, n)) +
                                     (1 - entry) * (1 - exitReflectance) * sky(*out);
                const double most = least + (1 - entry) * exitReflectance;
                const double seen = result.image.at(px, py).g;
                ++checked;
                far += seen < least - 0.01 || seen > most + 0.01;
                // Inverted: the exit turns to the other side of the axis than the entry.
                if (std::abs(hit->ray.direction.y) > 0.02)
                    inverted += (out->y > 0) != (hit->ray.direction.y > 0);
            }
        }
        EXPECT_GT(checked, 1000);
        EXPECT_LE(far, checked / 100) << far << " of " << checked;
        EXPECT_GT(inverted, checked / 2);
    }
}

// Clear of refraction (index 1: no Fresnel reflection, no bending), a ball that absorbs
// passes exp(-absorption x L) of the white background per channel, L the chord of its pixel's
// ray: Beer-Lambert over the way inside, found by the fixed steps and the bisection.
TEST(Glass, AbsorbsByBeerLambertAlongTheChord) {
    for (RenderEngine engine : kEngines) {
        SCOPED_TRACE(nameOf(engine));
        Scene scene = darkBall({0, 0, -4});
        scene.material.transparency = 1;
        scene.material.ior = 1;
        scene.material.absorption = {0.5, 1, 2};
        scene.shading.backgroundTop = scene.shading.backgroundBottom = {1, 1, 1};
        const RenderResult result = render(on(scene, engine));
        const Camera camera(scene.camera, kSize, kSize);
        int checked = 0;
        double worst = 0;
        for (int py = 0; py < kSize; ++py) {
            for (int px = 0; px < kSize; ++px) {
                auto hit = ballHit(camera, px, py, 0.05);
                if (!hit) continue;
                const double chord = -2 * dot(hit->point, hit->ray.direction);
                const Rgba& c = result.image.at(px, py);
                worst = std::max({worst, std::abs(c.r - std::exp(-0.5 * chord)),
                                  std::abs(c.g - std::exp(-1 * chord)),
                                  std::abs(c.b - std::exp(-2 * chord))});
                ++checked;
            }
        }
        EXPECT_GT(checked, 1000);
        EXPECT_LT(worst, 0.01);
    }
}

// A white furnace: a lossless mirror and clear glass in a white world are white all over.
TEST(Furnace, LosslessMaterialsInAWhiteWorldStayWhite) {
    for (RenderEngine engine : kEngines) {
        SCOPED_TRACE(nameOf(engine));
        for (bool glass : {false, true}) {
            Scene scene = darkBall({0, 0.5, -4});
            (glass ? scene.material.transparency : scene.material.reflectivity) = 1;
            scene.shading.backgroundTop = scene.shading.backgroundBottom = {1, 1, 1};
            const RenderResult result = render(on(scene, engine));
            double worst = 0;
            for (int py = 0; py < kSize; ++py) {
                for (int px = 0; px < kSize; ++px) {
                    const Rgba& c = result.image.at(px, py);
                    worst = std::max(
                        {worst, std::abs(c.r - 1.0), std::abs(c.g - 1.0), std::abs(c.b - 1.0)});
                }
            }
            EXPECT_LT(worst, 2e-3) << (glass ? "glass" : "mirror");
        }
    }
}

// The ground as a shadow catcher under a light straight above: black with alpha 1 in the
// ball's shadow (the disc x^2 + z^2 < 1 of the floor) and nothing elsewhere; id 2 in the passes.
TEST(Ground, ShadowCatcherIsTheShadowAlone) {
    for (RenderEngine engine : kEngines) {
        SCOPED_TRACE(nameOf(engine));
        Scene scene = darkBall({0, 2, -4});
        scene.render.alpha = AlphaMode::Coverage;
        scene.shading.lightDirection = {0, 1, 0};
        scene.shading.lightIntensity = 1;
        scene.shading.shadows = Shadows::Hard;
        scene.ground.enabled = true;
        scene.ground.height = -1.2;
        scene.ground.shadowCatcher = true;
        RenderOptions options;
        options.passes = true;
        const RenderResult result = render(on(scene, engine), options);
        const Camera camera(scene.camera, kSize, kSize);
        int shadowed = 0, open = 0, wrong = 0;
        for (int py = 0; py < kSize; ++py) {
            for (int px = 0; px < kSize; ++px) {
                const Ray ray = camera.generateRay(px + 0.5, py + 0.5);
                const size_t i = size_t(py) * kSize + size_t(px);
                if (ballHit(camera, px, py, -0.05)) {  // the ball, and its outline
                    if (ballHit(camera, px, py, 0.05)) {
                        EXPECT_EQ(result.passes.object[i], 1u);
                    }
                    continue;
                }
                if (!(ray.direction.y < 0)) continue;
                const Point3d floor = ray.at((-1.2 - ray.origin.y) / ray.direction.y);
                const double r2 = floor.x * floor.x + floor.z * floor.z;
                if (std::abs(r2 - 1) < 0.15) continue;  // the shadow's edge
                const Rgba& c = result.image.at(px, py);
                if (r2 < 1) {
                    ++shadowed;
                    wrong += !(c.a > 0.999 && c.r < 1e-3 && result.passes.object[i] == 2u);
                } else {
                    ++open;
                    wrong += !(c.a < 1e-3);
                }
            }
        }
        EXPECT_GT(shadowed, 200);
        EXPECT_GT(open, 1000);
        EXPECT_EQ(wrong, 0);
    }
}

// Camera rays that see the ground and nothing else end there without the paths' bookkeeping
// (LaneTileRenderer::shadeCameraGround) where the ground reflects nothing: every pixel as the
// paths make it, with fog, soft shadows and a point light, and as a shadow catcher.
TEST(Ground, CameraRaysThatEndOnItChangeNoPixel) {
    for (const bool catcher : {false, true}) {
        Scene scene = defaultScene();
        scene.ground.enabled = true;
        scene.ground.shadowCatcher = catcher;
        scene.shading.fogDensity = 0.05;
        scene.lights[0].enabled = true;
        scene.lights[0].kind = LightKind::Point;
        scene.lights[0].position = {2, 3, -2};
        scene.lights[0].color = Color(1, 0.9, 0.8);
        scene.lights[0].intensity = 8;
        scene.lights[0].radius = 0.3;
        const Fractal fractal = fractalFromScene(scene);
        const Camera camera(scene.camera, 160, 90);
        const Shader shader(scene.shading, fractal, scene.lights);
        const MarchSettings march{MarchMethod::SphereTracing, 0, scene.render.epsilon,
                                  camera.pixelFootprint(1.0), scene.render.maxSteps};
        const LaneFractal lanes = LaneFractal::from(fractal, Precision::Single);
        LaneTileRenderer shortcut(lanes, camera, shader, march, 1);
        LaneTileRenderer paths(lanes, camera, shader, march, 1);
        shortcut.setScenery(scene.material, scene.ground);
        paths.setScenery(scene.material, scene.ground);
        paths.setGroundShortcut(false);
        int ground = 0, changed = 0;
        for (int y0 = 0; y0 < 90; y0 += 32) {
            for (int x0 = 0; x0 < 160; x0 += 32) {
                const Tile tile{x0, y0, std::min(x0 + 32, 160), std::min(y0 + 32, 90)};
                std::vector<PixelSamples> a, b;
                LaneTileStats statsA, statsB;
                shortcut.render(tile, a, statsA);
                paths.render(tile, b, statsB);
                ASSERT_EQ(a.size(), b.size());
                for (size_t i = 0; i < a.size(); ++i) {
                    ASSERT_EQ(a[i].hits, b[i].hits);
                    ASSERT_EQ(a[i].groundHits, b[i].groundHits);
                    ground += a[i].groundHits;
                    changed += length(a[i].sum - b[i].sum) > 1e-12 ||
                               std::abs(a[i].uncovered - b[i].uncovered) > 1e-12 ||
                               std::abs(a[i].depthSum - b[i].depthSum) > 1e-12;
                }
            }
        }
        EXPECT_GT(ground, 5000) << "the ground should fill most of the frame";
        EXPECT_EQ(changed, 0) << (catcher ? "shadow catcher" : "ground");
    }
}

// A light's size makes its shadow's penumbra: under a directional light straight above, the
// ball's shadow on a shadow catcher has a soft rim (partial alpha) that widens with the light's
// angular radius, and none with hard shadows.
TEST(Lights, PenumbraWidensWithTheLightsSize) {
    auto rim = [](Shadows shadows, double degrees) {
        Scene scene = darkBall({0, 3, -3});
        scene.render.alpha = AlphaMode::Coverage;
        scene.shading.lightDirection = {0, 1, 0};
        scene.shading.lightIntensity = 1;
        scene.shading.shadows = shadows;
        scene.shading.lightAngularRadius = degrees;
        scene.ground.enabled = true;
        scene.ground.height = -1.5;
        scene.ground.shadowCatcher = true;
        const Image image = render(scene).image;
        int partial = 0;
        for (int py = 0; py < kSize; ++py)
            for (int px = 0; px < kSize; ++px)
                partial += image.at(px, py).a > 0.05 && image.at(px, py).a < 0.95;
        return partial;
    };
    const int hard = rim(Shadows::Hard, 0), narrow = rim(Shadows::Soft, 2),
              wide = rim(Shadows::Soft, 10);
    EXPECT_LT(hard, 40);  // the ball's own outline, anti-aliased by nothing: only its edge
    EXPECT_GT(narrow, hard + 20);
    EXPECT_GT(wide, 2 * narrow);
}

// A second light ([light1]) on the axis adds I / d^2 at the ball's nearest point, as the key
// light does, in both engines.
TEST(Lights, ExtraPointLightFallsWithTheInverseSquare) {
    for (RenderEngine engine : {RenderEngine::Simd, RenderEngine::Scalar}) {
        for (double distance : {2.0, 4.0}) {
            Scene scene = darkBall({0, 0, -4});
            scene.render.engine = engine;
            LightSettings& light = scene.lights[0];
            light.enabled = true;
            light.kind = LightKind::Point;
            light.position = {0, 0, -1 - distance};
            light.color = {1, 1, 1};
            light.intensity = 2;
            light.shadows = Shadows::Hard;
            const double centre = render(scene).image.at(kSize / 2, kSize / 2).r;
            EXPECT_NEAR(centre, 2 / (distance * distance), 0.01 / distance);
        }
    }
}

// The glow colours the background about the set and fades with the distance from it.
TEST(Glow, HaloAboutTheSilhouetteFadesOutwards) {
    for (RenderEngine engine : kEngines) {
        SCOPED_TRACE(nameOf(engine));
        Scene scene = darkBall({0, 0, -4});
        scene.shading.glowIntensity = 1;
        scene.shading.glowColor = {0, 1, 0};
        const Image image = render(on(scene, engine)).image;
        const int centre = kSize / 2;
        // Along the middle row, outwards from the ball's edge.
        const Camera camera(scene.camera, kSize, kSize);
        int x = centre;
        while (x < kSize && ballHit(camera, x, centre, 0.0))
            ++x;
        ASSERT_LT(x + 6, kSize);
        EXPECT_GT(image.at(x, centre).g, image.at(x + 5, centre).g);
        EXPECT_GT(image.at(x, centre).g, 0.05);
        EXPECT_EQ(image.at(x, centre).r, 0);
        EXPECT_EQ(image.at(0, 0).g, 0);  // the corner: the ray misses the bounding sphere
    }
}

}  // namespace
}  // namespace quaternia
