#include "quaternia/render/proven_cones.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "quaternia/render/march.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_file.h"
#include "quaternia/scene/scene_fractal.h"

namespace quaternia {
namespace {

struct ConeCase {
    const char* name;
    std::vector<const char*> overrides;
    bool proves = true;  // whether most pixels should be proven something
};

// Rays through two points of each pixel: its centre and near a corner (samples of several per
// pixel lie anywhere in it).
constexpr double kSampleOffsets[2][2] = {{0.5, 0.5}, {0.03, 0.97}};

}  // namespace

// The cones of proof skip only samples outside K_N: through every pixel of small pictures of
// three algebras' sets, a ray started past its pixel's proven distance finds the first inside
// sample (and the one before it) of plain fixed steps; every sample it skipped is outside
// (tested one by one); a pixel proven clear all the way has no inside sample. The distances do
// not depend on the tile (blocks lie on the image's grid).
TEST(Marching, ConesOfProofKeepTheRaysSamples) {
    const std::vector<ConeCase> cases = {
        {"coquaternion", {"fractal.algebra=\"coquaternion\""}},
        // At 170 degrees a block of 16 of 40 pixels spans more than 90 degrees: its cone gives up
        // (proven_cones.cpp), and the rays march alone.
        {"coquaternion seen at 170 degrees",
         {"fractal.algebra=\"coquaternion\"", "camera.fov=170", "camera.position=[0, 0, -2.2]"},
         false},
        {"biquaternion",
         {"fractal.algebra=\"biquaternion\"", "fractal.c=[-0.2, 0.6, 0.2, 0.2, 0, 0.1, 0, 0]",
          "slice.axes=[[0,1,0,0,0,0,0,0],[0,0,0,0,0,1,0,0],[0,0,0,0,0,0,1,0]]"}},
        {"bicomplex functions",
         {"fractal.algebra=\"bicomplex\"", "fractal.formula=\"sin(z) + c\""}},
        {"octonion formula",
         {"fractal.algebra=\"octonion\"", "fractal.formula=\"z^2 + 0.2 (i z) j + c\"",
          "fractal.c=[-0.2, 0.6, 0.2, 0.2, 0.1, 0, 0.05, 0]"}},
    };
    const int width = 40, height = 24;
    for (const ConeCase& test : cases) {
        Scene scene = defaultScene();
        for (const char* assignment : test.overrides)
            applyOverride(scene, assignment);
        const Fractal fractal = fractalFromScene(scene);
        const Camera camera(scene.camera, width, height);
        MarchSettings settings;
        settings.method = MarchMethod::FixedStep;
        settings.step = 0.004;
        settings.maxSteps = 1 << 30;
        const ProvenCones cones(fractal, camera, settings.step);
        ASSERT_TRUE(cones.active()) << test.name;
        const Tile image{0, 0, width, height};
        std::vector<double> provenUntil, inTile;
        cones.clear(image, provenUntil);
        // A tile off the blocks' grid gives its pixels the same distances.
        const Tile offGrid{5, 3, 29, 21};
        cones.clear(offGrid, inTile);
        for (int py = offGrid.y0; py < offGrid.y1; ++py)
            for (int px = offGrid.x0; px < offGrid.x1; ++px)
                ASSERT_EQ(inTile[size_t((py - offGrid.y0) * (offGrid.x1 - offGrid.x0) +
                                        (px - offGrid.x0))],
                          provenUntil[size_t(py * width + px)])
                    << test.name << " pixel " << px << ", " << py;
        int64_t hits = 0, cleared = 0, provenPixels = 0;
        for (int py = 0; py < height; ++py)
            for (int px = 0; px < width; ++px) {
                const double proven = provenUntil[size_t(py * width + px)];
                cleared += proven == std::numeric_limits<double>::infinity();
                provenPixels += proven > 0;
                for (const auto& offset : kSampleOffsets) {
                    const Ray ray = camera.generateRay(px + offset[0], py + offset[1]);
                    const MarchResult plain = fixedStepMarch(fractal, ray, settings);
                    const MarchResult started =
                        proven > 0 ? fixedStepMarch(fractal, ray, settings, proven) : plain;
                    ASSERT_EQ(started.hit.has_value(), plain.hit.has_value())
                        << test.name << " pixel " << px << ", " << py;
                    if (plain.hit) {
                        ++hits;
                        EXPECT_EQ(started.hit->t, plain.hit->t) << test.name;
                        EXPECT_EQ(started.hit->tOutside, plain.hit->tOutside) << test.name;
                    }
                    // Every sample the cone skipped, tested.
                    const auto interval = intersectSphere(ray, fractal.boundingRadius());
                    if (!interval) continue;
                    for (double t = interval->tNear; t <= std::min(proven, interval->tFar);
                         t += settings.step)
                        ASSERT_FALSE(fractal.contains(ray.at(t)))
                            << test.name << " pixel " << px << ", " << py << " t " << t;
                }
            }
        // What they spare shows at full size (bench/run.sh); at this size a block is a third of
        // the picture, and the cones must still prove whole pixels clear.
        EXPECT_GT(hits, test.proves ? width * height / 10 : 10) << test.name;
        if (test.proves)
            EXPECT_GT(provenPixels, width * height / 2)
                << test.name << ", " << cleared << " cleared";
        else
            EXPECT_EQ(provenPixels, 0) << test.name;
    }
}

}  // namespace quaternia
