// The shading lanes (shading_lanes.h) against the scalar formulas they mirror, on every
// instruction set compiled in and supported here.
#include "quaternia/render/lanes/shading_lanes.h"

#include <gtest/gtest.h>

#include <hwy/targets.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "quaternia/fractal/fractal.h"
#include "quaternia/render/shade.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_fractal.h"

namespace quaternia {
namespace {

// Display encoding of packed RGBA pixels: colour channels as Shader::toDisplay's formula (to
// float precision), alpha untouched, on every target and for counts that leave a partial vector.
TEST(ShadingLanes, DisplayEncodingKeepsAlphaOnEveryTarget) {
    const float exposure = 1.3f, inverseGamma = 1 / 2.2f;
    std::mt19937 random(11);
    std::uniform_real_distribution<float> value(-0.5f, 1.5f), alpha(0.0f, 1.0f);
    for (int64_t target : hwy::SupportedAndGeneratedTargets()) {
        hwy::SetSupportedTargetsForTest(target);
        for (size_t pixels : {1u, 3u, 16u, 37u}) {
            std::vector<float> linear(4 * pixels);
            for (size_t i = 0; i < linear.size(); ++i)
                linear[i] = i % 4 == 3 ? alpha(random) : value(random);
            std::vector<float> encoded = linear;
            encodeDisplay(encoded.data(), pixels, exposure, inverseGamma);
            for (size_t i = 0; i < linear.size(); ++i) {
                if (i % 4 == 3) {
                    ASSERT_EQ(encoded[i], linear[i])
                        << hwy::TargetName(target) << " pixel " << i / 4;
                } else {
                    const float expected =
                        std::pow(std::clamp(linear[i] * exposure, 0.0f, 1.0f), inverseGamma);
                    ASSERT_NEAR(encoded[i], expected, 2e-6f) << hwy::TargetName(target);
                }
            }
        }
    }
    hwy::SetSupportedTargetsForTest(0);
}

// Shader::light in lanes gives the scalar lighting (to float precision) of random surface
// samples, lit and unlit, with and without a highlight, on every target and for counts that
// leave a partial vector.
TEST(ShadingLanes, LightingMatchesTheShaderOnEveryTarget) {
    Scene scene = defaultScene();
    scene.shading.shininess = 20;
    const Fractal fractal = fractalFromScene(scene);
    const Shader shader(scene.shading, fractal);
    std::mt19937 random(5);
    std::normal_distribution<double> gaussian;
    std::uniform_real_distribution<double> unit(0, 1);
    auto randomDirection = [&] {
        return normalize(Vector3d(gaussian(random), gaussian(random), gaussian(random)));
    };
    for (int64_t target : hwy::SupportedAndGeneratedTargets()) {
        hwy::SetSupportedTargetsForTest(target);
        for (size_t count : {1u, 7u, 16u, 53u}) {
            std::vector<SurfaceSample> samples(count);
            std::vector<Vector3d> directions(count);
            SurfaceBatch batch;
            batch.resize(count);
            for (size_t i = 0; i < count; ++i) {
                SurfaceSample& sample = samples[i];
                // Every fourth normal faces the key light's mirror direction: a highlight.
                directions[i] = randomDirection();
                sample.normal = i % 4 == 0 ? normalize(shader.lightDirection() - directions[i])
                                           : randomDirection();
                sample.albedo = Color(unit(random), unit(random), unit(random));
                sample.visibility = unit(random);
                sample.occlusion = unit(random);
                // A key light as a point light gives it: any unit direction and factor.
                sample.toLight = i % 4 == 0 ? shader.lightDirection() : randomDirection();
                sample.keyScale = i % 4 == 0 ? 1 : 2 * unit(random);
                batch.lx[i] = float(sample.toLight.x), batch.ly[i] = float(sample.toLight.y);
                batch.lz[i] = float(sample.toLight.z);
                batch.keyScale[i] = float(sample.keyScale);
                batch.nx[i] = float(sample.normal.x), batch.ny[i] = float(sample.normal.y);
                batch.nz[i] = float(sample.normal.z);
                batch.dx[i] = float(directions[i].x), batch.dy[i] = float(directions[i].y);
                batch.dz[i] = float(directions[i].z);
                batch.albedoR[i] = float(sample.albedo.x),
                batch.albedoG[i] = float(sample.albedo.y);
                batch.albedoB[i] = float(sample.albedo.z);
                batch.visibility[i] = float(sample.visibility);
                batch.occlusion[i] = float(sample.occlusion);
            }
            lightSurfaces(shader.lightConstants(), batch);
            for (size_t i = 0; i < count; ++i) {
                const Color expected = shader.light(samples[i], Ray{{}, directions[i]});
                ASSERT_NEAR(batch.red[i], expected.x, 1e-5) << hwy::TargetName(target) << " " << i;
                ASSERT_NEAR(batch.green[i], expected.y, 1e-5) << hwy::TargetName(target);
                ASSERT_NEAR(batch.blue[i], expected.z, 1e-5) << hwy::TargetName(target);
            }
        }
    }
    hwy::SetSupportedTargetsForTest(0);
}

}  // namespace
}  // namespace quaternia
