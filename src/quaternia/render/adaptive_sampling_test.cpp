// Adaptive sampling (render.adaptive) against uniform sampling of the same samples: the same
// picture within the bound, from far fewer rays, the same on both engines' terms.
#include "quaternia/render/adaptive_sampling.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "quaternia/render/render.h"
#include "quaternia/scene/parameters.h"

namespace quaternia {
namespace {

struct Difference {
    double mean = 0, max = 0;  // per channel (alpha among them), in display values
};

Difference compareImages(const Image& a, const Image& b) {
    Difference d;
    const auto& p = a.pixels();
    const auto& q = b.pixels();
    for (size_t i = 0; i < p.size(); ++i) {
        for (double e : {p[i].r - q[i].r, p[i].g - q[i].g, p[i].b - q[i].b, p[i].a - q[i].a}) {
            d.mean += std::abs(e);
            d.max = std::max(d.max, std::abs(e));
        }
    }
    d.mean /= 4.0 * double(p.size());
    return d;
}

TEST(AdaptiveSampling, SixteenSamplesWithinTheBoundOfUniformFromFewerRays) {
    Scene scene = defaultScene();
    scene.render.width = 320;
    scene.render.height = 180;
    scene.render.samples = 16;
    scene.render.adaptive = false;
    const RenderResult uniform = render(scene);
    scene.render.adaptive = true;
    const RenderResult adaptive = render(scene);
    const Difference d = compareImages(adaptive.image, uniform.image);
    std::printf("mean %.3f/255, max %.1f/255, rays %lld against %lld\n", d.mean * 255, d.max * 255,
                (long long)adaptive.stats.rays, (long long)uniform.stats.rays);
    EXPECT_LE(d.mean, 1.0 / 255);
    EXPECT_LE(d.max, 24.0 / 255);
    EXPECT_GT(d.max, 0);  // adaptive: some pixels keep fewer samples
    EXPECT_EQ(uniform.stats.rays, 16 * 320 * 180);
    EXPECT_LT(double(adaptive.stats.rays), 0.5 * double(uniform.stats.rays));
    EXPECT_NEAR(double(adaptive.stats.hits) / double(adaptive.stats.rays),
                double(uniform.stats.hits) / double(uniform.stats.rays), 0.5);
}

// The scalar engine makes the same decisions from its own samples.
TEST(AdaptiveSampling, ScalarEngineWithinTheBoundOfUniform) {
    Scene scene = defaultScene();
    scene.render.width = 96;
    scene.render.height = 54;
    scene.render.samples = 16;
    scene.render.engine = RenderEngine::Scalar;
    scene.render.adaptive = false;
    const RenderResult uniform = render(scene);
    scene.render.adaptive = true;
    const RenderResult adaptive = render(scene);
    const Difference d = compareImages(adaptive.image, uniform.image);
    EXPECT_LE(d.mean, 1.0 / 255);
    EXPECT_LE(d.max, 24.0 / 255);
    EXPECT_LT(adaptive.stats.rays, uniform.stats.rays);
}

// One sample, or adaptive off: every pixel takes all its samples.
TEST(AdaptiveSampling, OneSampleOrUniformTakesEverySample) {
    Scene scene = defaultScene();
    scene.render.width = 40;
    scene.render.height = 30;
    scene.render.samples = 1;
    EXPECT_EQ(render(scene).stats.rays, 40 * 30);
    scene.render.samples = 4;
    scene.render.adaptive = false;
    EXPECT_EQ(render(scene).stats.rays, 4 * 40 * 30);
}

// The order is a permutation of the strata whose first four lie in different rows and
// columns of the grid, the centre stratum first.
TEST(AdaptiveSampling, OrderSpreadsTheFirstSamples) {
    for (int n : {2, 4, 5, 9, 16, 64}) {
        const AdaptiveSampling order(n);
        ASSERT_EQ(order.samples(), n);
        std::set<int> seen;
        for (int j = 0; j < n; ++j)
            seen.insert(order.index(j, 0, 0));
        EXPECT_EQ(int(seen.size()), n);
        EXPECT_EQ(*seen.rbegin(), n - 1);
        EXPECT_EQ(order.second(), std::min(n, 4));
    }
    const AdaptiveSampling order(16);
    EXPECT_EQ(order.index(0, 3, 7), 2 * 4 + 2);
    std::set<int> columns, rows;
    for (int j = 0; j < 4; ++j) {
        columns.insert(order.index(j, 0, 0) % 4);
        rows.insert(order.index(j, 0, 0) / 4);
    }
    EXPECT_EQ(columns.size(), 4u);
    EXPECT_EQ(rows.size(), 4u);
}

}  // namespace
}  // namespace quaternia
