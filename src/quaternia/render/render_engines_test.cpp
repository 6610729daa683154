// Both engines draw every picture (issue 35): each preset and look, and one scene with every
// material feature at once, rendered by the SIMD lanes and by the double-precision reference
// (render.engine = "scalar") and held together. Not pixel for pixel: the lanes start each ray
// where its block's cone stopped, the reference at the bounding sphere, so each lands at another
// point within a fraction of a footprint of the surface, where a fractal's normal turns fast and
// a thin filament may be met by one and stepped over by the other. So, at kSamples samples a
// pixel:
// - the mean difference of each channel (lanes less reference) is at most kBias: no bias in
//   light, shadow, colour, reflection, refraction or coverage (measured: at most 0.13/255);
// - the mean absolute difference of each channel is at most kMeanAbsolute (measured: 1.40/255
//   on the dendrite, whose filaments are thinner than a pixel; at most 1.05/255 on the looks);
// - at most kFarPixels of the pixels differ by more than 16/255 in some channel: one sample of
//   16 that grazes a silhouette differently moves its pixel by up to 16/255 of the contrast
//   (measured: at most 3.0%, the dendrite; 0.4% on the looks).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "quaternia/render/render.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/presets.h"
#include "quaternia/scene/scene_file.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/util/sanitized_build.h"

namespace quaternia {
namespace {

constexpr int kSamples = 16;
constexpr double kBias = 0.5, kMeanAbsolute = 2.0, kFarPixels = 0.04;

struct EngineDifference {
    std::array<double, 4> mean{};  // per channel (red, green, blue, alpha), in 1/255
    double farPixels = 0;          // share of pixels with a channel more than 16/255 apart
    double largest = 0;            // in 1/255
    std::array<double, 4> bias{};  // mean signed difference, lanes less reference
};

// The images averaged over blocks of block x block pixels (block 1: as they are).
Image blockAverage(const Image& image, int block) {
    if (block == 1) return image;
    Image out(image.width() / block, image.height() / block);
    for (int y = 0; y < out.height(); ++y)
        for (int x = 0; x < out.width(); ++x) {
            Rgba sum{0, 0, 0, 0};
            for (int dy = 0; dy < block; ++dy)
                for (int dx = 0; dx < block; ++dx) {
                    const Rgba& p = image.at(x * block + dx, y * block + dy);
                    sum.r += p.r, sum.g += p.g, sum.b += p.b, sum.a += p.a;
                }
            const float n = float(block * block);
            out.at(x, y) = Rgba{sum.r / n, sum.g / n, sum.b / n, sum.a / n};
        }
    return out;
}

// block: the differences measured on block x block averages (the signed mean is the same):
// the looks in the built-in studio, whose soft boxes are small and 100 times brighter than the
// rest, turn the two marchers' slightly different hit points into bright sparkles of glass and
// chrome at different pixels: noise of the paths (the signed mean stays within 0.07/255), which
// averaging over blocks separates from a difference of structure.
EngineDifference compareEngines(Scene scene, int block = 1) {
    scene.render.engine = RenderEngine::Simd;
    const RenderResult lanes = render(scene);
    scene.render.engine = RenderEngine::Scalar;
    const RenderResult reference = render(scene);
    EXPECT_STREQ(reference.stats.engine, "scalar");
    EXPECT_STRNE(lanes.stats.engine, "scalar");
    // Not two empty pictures: every scene here shows the set.
    EXPECT_GT(reference.stats.hits, reference.stats.rays / 50);
    EngineDifference d;
    const Image lanesImage = blockAverage(lanes.image, block);
    const Image referenceImage = blockAverage(reference.image, block);
    const int width = lanesImage.width(), height = lanesImage.height();
    int far = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const Rgba& a = lanesImage.at(x, y);
            const Rgba& b = referenceImage.at(x, y);
            const std::array<double, 4> apart{std::abs(a.r - b.r), std::abs(a.g - b.g),
                                              std::abs(a.b - b.b), std::abs(a.a - b.a)};
            double pixel = 0;
            const std::array<double, 4> signedApart{a.r - b.r, a.g - b.g, a.b - b.b, a.a - b.a};
            for (int c = 0; c < 4; ++c) {
                d.bias[c] += 255 * signedApart[c];
                d.mean[c] += 255 * apart[c];
                pixel = std::max(pixel, 255 * apart[c]);
            }
            d.largest = std::max(d.largest, pixel);
            far += pixel > 16;
        }
    }
    for (int c = 0; c < 4; ++c) {
        d.mean[c] /= double(width) * height;
        d.bias[c] /= double(width) * height;
    }
    d.farPixels = double(far) / (double(width) * height);
    return d;
}

void expectEnginesAgree(const Scene& scene, const std::string& name, int block = 1) {
    const EngineDifference d = compareEngines(scene, block);
    std::printf(
        "%-14s mean |difference| %.3f %.3f %.3f %.3f, mean difference %.3f %.3f %.3f "
        "%.3f (1/255), %.2f%% of pixels over 16/255\n",
        name.c_str(), d.mean[0], d.mean[1], d.mean[2], d.mean[3], d.bias[0], d.bias[1], d.bias[2],
        d.bias[3], 100 * d.farPixels);
    for (int c = 0; c < 4; ++c) {
        EXPECT_LE(std::abs(d.bias[c]), kBias) << name << ": channel " << c;
        EXPECT_LE(d.mean[c], kMeanAbsolute) << name << ": channel " << c;
    }
    EXPECT_LE(d.farPixels, kFarPixels) << name << " (largest " << d.largest << "/255)";
}

Scene small(Scene scene) {
    scene.render.width = 128;
    scene.render.height = 72;
    scene.render.samples = kSamples;
    return scene;
}

TEST(RenderEngines, EveryPresetAndLookAgrees) {
    int index = 0;
    for (const Preset& preset : scenePresets()) {
        if (!testing::runsCase(index++, 2)) continue;
        Scene scene = defaultScene();
        applyPreset(scene, preset.name);
        // The fixed-step algebras' presets (coquaternion, biquaternion) have no lanes yet: the
        // scalar engine draws them in both (Marching.ProvenRunsFindThePlainStepsSample holds
        // their march to plain fixed steps).
        if (fractalFromScene(scene).distanceKind() == DistanceKind::kLipschitz) continue;
        const bool studio =
            scene.environment.enabled && scene.environment.builtin == EnvironmentBuiltin::Studio;
        expectEnginesAgree(small(scene), preset.name, studio ? 4 : 1);
    }
}

// Every material feature in one picture: a glossy, partly reflecting, partly transparent set
// that absorbs, over a reflecting ground, in fog and glow, through a thin lens, lit by the key
// light and a coloured point light with soft shadows; and the same adaptively sampled.
TEST(RenderEngines, EveryMaterialFeatureAtOnceAgrees) {
    Scene scene = small(defaultScene());
    for (const char* assignment :
         {"material.reflectivity=0.3", "material.roughness=0.05", "material.transparency=0.5",
          "material.ior=1.4", "material.absorption=[0.5, 0.2, 0.1]", "ground.enabled=true",
          "ground.reflectivity=0.3", "shading.fog_density=0.05", "shading.glow_intensity=0.4",
          "camera.aperture=0.05", "light1.enabled=true", "light1.kind=point",
          "light1.position=[3, 3, 4]", "light1.color=[0.6, 0.75, 1.0]", "light1.intensity=12",
          "light1.radius=0.3"})
        applyOverride(scene, assignment);
    expectEnginesAgree(scene, "every feature");
    scene.render.adaptive = true;
    expectEnginesAgree(scene, "adaptive");
}

// The environment (issue 39): the built-in studio seen by glossy reflections and the background,
// its light on the set and the ground shadowed by 4 rays a hit; the built-in sky with its sun.
TEST(RenderEngines, EnvironmentLightAgrees) {
    Scene scene = small(defaultScene());
    for (const char* assignment :
         {"environment.enabled=true", "environment.builtin=studio", "environment.samples=4",
          "environment.rotation=40", "material.reflectivity=0.3", "material.roughness=0.2",
          "ground.enabled=true", "shading.light_intensity=0.3", "shading.ambient=0"})
        applyOverride(scene, assignment);
    expectEnginesAgree(scene, "studio", 4);
    if (!testing::runsCase(1, 2)) return;  // under the sanitizers, the studio alone
    applyOverride(scene, "environment.builtin=sky");
    applyOverride(scene, "environment.background=false");
    expectEnginesAgree(scene, "sky");
}

}  // namespace
}  // namespace quaternia
