// The mesher against analytic answers: c = 0 is the unit ball (ORACLES: volume 4 pi / 3, area
// 4 pi), a real c gives a solid of revolution about the real axis, and every vertex lies on
// the surface the renderer draws.
#include "mesher.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fractal.h"
#include "mesh_check.h"
#include "test_scenes.h"

namespace quaternia {
namespace {

MeshResult meshAt(Scene scene, int resolution, double iso = 0) {
    scene.mesh.resolution = resolution;
    scene.mesh.iso = iso;
    return meshScene(scene);
}

TEST(Mesher, UnitBallHasBallVolumeAndArea) {
    MeshResult result = meshAt(testing::unitBallScene(32, 32), 128);
    MeshCheck check = checkMesh(result.mesh);
    const double pi = std::numbers::pi;
    EXPECT_TRUE(check.watertight());
    EXPECT_EQ(check.components, 1);
    EXPECT_NEAR(check.volume / (4 * pi / 3), 1, 0.01);
    EXPECT_NEAR(check.area / (4 * pi), 1, 0.02);
    RecordProperty("volume_error", std::to_string(check.volume / (4 * pi / 3) - 1));
    RecordProperty("area_error", std::to_string(check.area / (4 * pi) - 1));
    std::printf("ball: V %zu T %zu vol err %.5f area err %.5f blocks %lld / %lld closure %lld "
                "estimates %lld cell %.5f cells %d %d %d  %.3f s\n",
                result.mesh.positions.size(), result.mesh.triangles.size(),
                check.volume / (4 * pi / 3) - 1, check.area / (4 * pi) - 1,
                (long long)result.stats.blocks, (long long)result.stats.latticeBlocks,
                (long long)result.stats.closureBlocks, (long long)result.stats.estimates,
                result.stats.grid.cellSize, result.stats.grid.cells[0], result.stats.grid.cells[1],
                result.stats.grid.cells[2], result.stats.seconds);
}

}  // namespace
}  // namespace quaternia
