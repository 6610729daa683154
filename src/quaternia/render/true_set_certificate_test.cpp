// Pictures certified against K itself (true_set_certificate.h): every certain class against the
// orbits of its ray's points in the algebra, for the reduced space (quaternions, octonions) and
// the bicomplex product; the file checked against the scene.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "quaternia/cellmap/certify_set.h"
#include "quaternia/cellmap/orbit_test_helpers.h"
#include "quaternia/fractal/hypercomplex_julia.h"
#include "quaternia/render/march.h"
#include "quaternia/render/pixel_certificate.h"
#include "quaternia/render/true_set_certificate.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/presets.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/util/error.h"
#include "quaternia/util/test_scratch_path.h"

namespace quaternia {
namespace {

Scene sceneWith(const std::vector<std::pair<std::string, ParameterValue>>& values, int width,
                int height) {
    Scene scene = defaultScene();
    for (const auto& [key, value] : values)
        setParameter(scene, key, value);
    scene.render.width = width;
    scene.render.height = height;
    scene.render.samples = 1;
    return scene;
}

using testing::staysBounded;

struct Checked {
    int64_t hits = 0, missed = 0, undecided = 0;
};

// Certifies the scene's set on `resolution` cells per axis, its picture against them, and
// checks each certain pixel: a hit's central-ray point at `farthest` stays bounded; a missed
// pixel's central-ray points across the escape ball all escape.
Checked certifyAndCheck(const Scene& scene, int resolution) {
    const SetCertification certified = certifySet(scene, resolution, {});
    EXPECT_TRUE(certified.completed);
    const Fractal fractal = hypercomplexFractalFromScene(scene);
    const Camera camera(scene.camera, scene.render.width, scene.render.height);
    const PixelCertificate certificate =
        certifyPixelsAgainstSet(fractal, certified.set, camera, scene.render.epsilon);
    const auto julia = hypercomplexJuliaSetOf(scene.fractal);
    const double radius = certified.set.escapeRadius;
    const double ball = fractal.slice().boundingRadius(radius);
    Checked checked;
    for (int y = 0; y < certificate.height; ++y)
        for (int x = 0; x < certificate.width; ++x) {
            const Ray ray = camera.generateRay(x + 0.5, y + 0.5);
            const PixelClass c = certificate.at(x, y);
            const size_t at = size_t(y) * size_t(certificate.width) + size_t(x);
            if (c == PixelClass::kHit) {
                ++checked.hits;
                const double t = certificate.farthestHit[at];
                EXPECT_LE(certificate.nearestHit[at], certificate.farthestHit[at]);
                // The float depth rounds the proven point's t outward: try it and its neighbours.
                bool bounded = false;
                for (double dt : {0.0, -1e-6, 1e-6}) {
                    const Point3d q = ray.origin + ray.direction * (double(t) + dt);
                    bounded = bounded || staysBounded(julia->formula(),
                                                      fractal.slice().fromWorld(q), radius, 20000);
                }
                EXPECT_TRUE(bounded) << "pixel " << x << "," << y << " at t = " << t;
            } else if (c == PixelClass::kMissed) {
                ++checked.missed;
                const auto interval = intersectSphere(ray, ball);
                if (!interval) continue;
                for (int n = 0; n <= 32; ++n) {
                    const double t = interval->tNear + (interval->tFar - interval->tNear) * n / 32;
                    const Point3d q = ray.origin + ray.direction * t;
                    EXPECT_FALSE(
                        staysBounded(julia->formula(), fractal.slice().fromWorld(q), radius, 20000))
                        << "pixel " << x << "," << y << " at t = " << t;
                }
            } else {
                ++checked.undecided;
            }
        }
    return checked;
}

TEST(TrueSetCertificate, QuaternionClassesHoldAlongTheRays) {
    // c in the main cardioid: K is a solid with a wide interior.
    const Scene scene = sceneWith({{"fractal.c", std::vector<double>{-0.2, 0.3, 0, 0}}}, 40, 24);
    const Checked checked = certifyAndCheck(scene, 64);
    EXPECT_GT(checked.hits, 20);
    EXPECT_GT(checked.missed, 200);
}

TEST(TrueSetCertificate, OctonionClassesHoldAlongTheRays) {
    const Scene scene =
        sceneWith({{"fractal.algebra", std::string("octonion")},
                   {"fractal.c", std::vector<double>{-0.2, 0.2, 0, 0, 0.1, 0.1, 0, 0}}},
                  32, 18);
    const Checked checked = certifyAndCheck(scene, 64);
    EXPECT_GT(checked.hits, 5);
    EXPECT_GT(checked.missed, 100);
}

TEST(TrueSetCertificate, BicomplexProductClassesHoldAlongTheRays) {
    Scene scene = defaultScene();
    applyPreset(scene, "bicomplex");
    scene.render.width = 32, scene.render.height = 18, scene.render.samples = 1;
    const Checked checked = certifyAndCheck(scene, 256);
    EXPECT_GT(checked.missed, 100);
}

TEST(TrueSetCertificate, DustHasNoHit) {
    // The default scene: K is a Cantor set (its critical orbit escapes), no cell is inside.
    const Scene scene = sceneWith({}, 32, 18);
    const Checked checked = certifyAndCheck(scene, 64);
    EXPECT_EQ(checked.hits, 0);
    EXPECT_GT(checked.missed, 100);
}

TEST(TrueSetCertificate, FileMustCertifyTheScene) {
    const std::string path = testing::scratchPath("quaternia-true-set-test.qcells").string();
    Scene scene = sceneWith({{"fractal.c", std::vector<double>{-0.2, 0.3, 0, 0}}}, 16, 9);
    {
        const SetCertification certified = certifySet(scene, 32, {});
        const std::vector<uint8_t> bytes = certified.set.encode();
        std::ofstream(path, std::ios::binary)
            .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    }
    scene.render.certified = path;
    EXPECT_NO_THROW(validateCertificate(scene));
    EXPECT_EQ(certifyPixels(scene).width, 16);
    Scene other = scene;
    setParameter(other, "fractal.c", std::vector<double>{-0.2, 0.31, 0, 0});
    try {
        validateCertificate(other);
        ADD_FAILURE() << "another c accepted";
    } catch (const UserError& e) {
        EXPECT_EQ(e.key(), "render.certified");
    }
    // A damaged file: a clear refusal, never a crash.
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out << "QUATERNIA-CELLS 1\n" << std::string(40, 'x');
    }
    try {
        validateCertificate(scene);
        ADD_FAILURE() << "damaged file accepted";
    } catch (const UserError& e) {
        EXPECT_EQ(e.key(), "render.certified");
    }
    std::filesystem::remove(path);
}

}  // namespace
}  // namespace quaternia
