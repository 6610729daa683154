// The environment in pictures (issue 39), physics on the unit ball (c = 0), in both engines: a
// mirror ball shows the map in the mirrored direction r = d - 2 (d . n) n, and turns with it; a
// white diffuse ball under a constant map sends back L times its albedo at every pixel (a convex
// body hides none of the sky from itself); the ground under the ball is darker than the ground
// far from it, by occlusion alone.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "quaternia/image/hdr_image.h"
#include "quaternia/render/camera.h"
#include "quaternia/render/environment.h"
#include "quaternia/render/render.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/presets.h"
#include "quaternia/scene/test_scenes.h"
#include "quaternia/util/atomic_file.h"

namespace quaternia {
namespace {

constexpr int kSize = 81;

std::string writeMap(const std::string& name, const HdrImage& map) {
    const std::string path = ::testing::TempDir() + "/" + name;
    AtomicFile file(path);
    file.write(encodeRadianceHdr(map));
    file.commit();
    return path;
}

// A smooth map of three unlike colour waves, so that each direction reads as itself (within
// [0, 1]: the image is the display's, clamped).
std::string wavesMap() {
    HdrImage map{256, 128, {}};
    for (int y = 0; y < map.height; ++y)
        for (int x = 0; x < map.width; ++x) {
            const double u = (x + 0.5) / map.width, v = (y + 0.5) / map.height;
            map.rgb.push_back(float(0.5 + 0.3 * std::sin(2 * M_PI * u)));
            map.rgb.push_back(float(0.5 + 0.3 * std::cos(M_PI * v)));
            map.rgb.push_back(float(0.5 + 0.25 * std::cos(2 * M_PI * u) * std::sin(M_PI * v)));
        }
    return writeMap("waves.hdr", map);
}

std::string constantMapFile(float value) {
    return writeMap("constant.hdr", HdrImage{64, 32, std::vector<float>(64 * 32 * 3, value)});
}

Scene ballUnder(const std::string& map, RenderEngine engine) {
    Scene scene = testing::darkUnitBallScene(kSize, kSize);
    scene.camera.position = {0, 0, -4};
    scene.render.engine = engine;
    scene.environment.enabled = true;
    scene.environment.map = map;
    return scene;
}

std::optional<Point3d> ballPoint(const Camera& camera, int px, int py) {
    const Ray ray = camera.generateRay(px + 0.5, py + 0.5);
    const double b = dot(ray.origin, ray.direction);
    const double disc = b * b - (dot(ray.origin, ray.origin) - 1);
    if (disc < 0.3) return std::nullopt;  // near the outline the mirror turns fast
    return ray.at(-b - std::sqrt(disc));
}

TEST(EnvironmentLight, MirrorBallShowsTheMapInTheMirroredDirection) {
    const std::string map = wavesMap();
    for (RenderEngine engine : {RenderEngine::Simd, RenderEngine::Scalar}) {
        for (double rotation : {0.0, 90.0}) {
            Scene scene = ballUnder(map, engine);
            scene.material.reflectivity = 1;
            scene.material.maxDepth = 1;
            scene.environment.lighting = false;
            scene.environment.rotation = rotation;
            const RenderResult result = render(scene);
            const auto environment = environmentOf(scene);
            const Camera camera(scene.camera, kSize, kSize);
            int checked = 0;
            double worst = 0, unturned = 0;
            for (int py = 0; py < kSize; ++py)
                for (int px = 0; px < kSize; ++px) {
                    const std::optional<Point3d> x = ballPoint(camera, px, py);
                    if (!x) continue;
                    const Vector3d d = camera.generateRay(px + 0.5, py + 0.5).direction;
                    const Vector3d n = *x;
                    const Vector3d r = d - n * (2 * dot(d, n));
                    const Color expected = environment->radiance(r);
                    const Rgba& got = result.image.at(px, py);
                    const double apart =
                        std::max({std::abs(got.r - expected.x), std::abs(got.g - expected.y),
                                  std::abs(got.b - expected.z)});
                    worst = std::max(worst, apart);
                    // The same direction read from the map unturned differs where turned.
                    Scene plain = scene;
                    plain.environment.rotation = 0;
                    if (rotation != 0 && checked % 50 == 0)
                        unturned = std::max(unturned,
                                            std::abs(got.r - environmentOf(plain)->radiance(r).x));
                    ++checked;
                }
            EXPECT_GT(checked, 1200);
            // Radiances of 0.2 to 0.8: a hundredth is the map's bilinear filtering where the
            // mirror spreads a pixel over several texels.
            EXPECT_LT(worst, 0.02) << int(engine) << " " << rotation;
            if (rotation != 0) {
                EXPECT_GT(unturned, 0.15);
            }
        }
    }
}

TEST(EnvironmentLight, WhiteBallUnderConstantMapSendsBackLTimesAlbedo) {
    const std::string map = constantMapFile(0.5f);
    for (RenderEngine engine : {RenderEngine::Simd, RenderEngine::Scalar}) {
        Scene scene = ballUnder(map, engine);
        scene.shading.baseColor = {0.8, 0.6, 0.4};
        scene.environment.background = false;
        scene.environment.samples = 4;
        const RenderResult result = render(scene);
        const Color radiance = environmentOf(scene)->diffuse({0, 1, 0});
        ASSERT_NEAR(radiance.x, 0.5, 0.01);  // RGBE's rounding
        const Camera camera(scene.camera, kSize, kSize);
        int checked = 0;
        for (int py = 0; py < kSize; ++py)
            for (int px = 0; px < kSize; ++px) {
                if (!ballPoint(camera, px, py)) continue;
                const Rgba& got = result.image.at(px, py);
                EXPECT_NEAR(got.r, 0.8 * radiance.x, 1e-4) << px << ", " << py;
                EXPECT_NEAR(got.g, 0.6 * radiance.y, 1e-4);
                EXPECT_NEAR(got.b, 0.4 * radiance.z, 1e-4);
                ++checked;
            }
        EXPECT_GT(checked, 1200);
    }
}

// The ground at y = -1 (touching the ball) lit by a constant map: its points 0.5 to 1 from the
// ball's foot lose much of the sky to the ball; points more than 3 away lose almost none. With
// no shadow rays (samples 0) both get the whole sky.
TEST(EnvironmentLight, GroundUnderTheBallIsDarkerByOcclusion) {
    const std::string map = constantMapFile(0.5f);
    for (RenderEngine engine : {RenderEngine::Simd, RenderEngine::Scalar}) {
        for (int samples : {0, 8}) {
            Scene scene = ballUnder(map, engine);
            scene.camera.position = {0, 4, -4};
            scene.camera.lookAt = {0, -1, 0};
            scene.render.width = 120;
            scene.render.samples = 4;
            scene.ground.enabled = true;
            scene.ground.height = -1;
            scene.ground.color = {0.5, 0.5, 0.5};
            scene.environment.background = false;
            scene.environment.samples = samples;
            const RenderResult result = render(scene);
            const Camera camera(scene.camera, scene.render.width, scene.render.height);
            double near = 0, far = 0;
            int nearCount = 0, farCount = 0;
            for (int py = 0; py < scene.render.height; ++py)
                for (int px = 0; px < scene.render.width; ++px) {
                    const Ray ray = camera.generateRay(px + 0.5, py + 0.5);
                    if (!(ray.direction.y < 0)) continue;
                    const double t = (-1 - ray.origin.y) / ray.direction.y;
                    const Point3d g = ray.at(t);
                    const double b = dot(ray.origin, ray.direction);
                    if (b * b - (dot(ray.origin, ray.origin) - 1.05 * 1.05) > 0) continue;
                    const double rho = std::hypot(g.x, g.z);
                    const double value = result.image.at(px, py).g;
                    if (rho < 1 && rho > 0.5) near += value, ++nearCount;
                    if (rho > 3) far += value, ++farCount;
                }
            ASSERT_GT(nearCount, 20);
            ASSERT_GT(farCount, 100);
            near /= nearCount, far /= farCount;
            EXPECT_NEAR(far, 0.25, samples == 0 ? 1e-3 : 0.02) << samples;
            if (samples == 0) {
                EXPECT_NEAR(near, far, 1e-3);
            } else {
                EXPECT_LT(near, 0.8 * far) << int(engine);
            }
        }
    }
}

// The environment's shadow rays are seeded by where each hit is: a window of the image (a
// poster's, quaternia-mpi) has the whole image's pixels there, and so do other thread counts.
TEST(EnvironmentLight, WindowAndThreadsLeaveThePixelsAlone) {
    Scene scene = defaultScene();
    applyPreset(scene, "sunset");
    scene.render.width = 150;
    scene.render.height = 100;
    scene.material.reflectivity = 0.3;
    scene.material.roughness = 0.2;
    const RenderResult whole = render(scene);
    RenderOptions options;
    options.window = Tile{64, 64, 150, 100};
    options.threads = 1;
    const RenderResult part = render(scene, options);
    for (int y = 64; y < 100; ++y)
        for (int x = 64; x < 150; ++x) {
            const Rgba a = part.image.at(x - 64, y - 64), b = whole.image.at(x, y);
            ASSERT_TRUE(a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a) << x << "," << y;
        }
}

}  // namespace
}  // namespace quaternia
