// The mesher against analytic answers: c = 0 is the unit ball (docs/facts.md, Symmetries:
// volume 4 pi / 3, area 4 pi), a real c gives a solid of revolution about the real axis, and every
// vertex lies on the surface the renderer draws.
#include "quaternia/mesh/mesher.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <unordered_map>

#include "quaternia/fractal/fractal.h"
#include "quaternia/mesh/mesh_check.h"
#include "quaternia/mesh/mesh_grid.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/scene/test_scenes.h"

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
    // The grid spans the ball's bounding box: 128 cells across its diameter.
    EXPECT_NEAR(result.stats.grid.cellSize, 2.0 / 128, 0.02 * 2.0 / 128);
    // Sparse: most blocks of the grid are never contoured (outside the ball, or inside it).
    EXPECT_LT(result.stats.blocks, result.stats.latticeBlocks / 2);
    RecordProperty("volume_error", std::to_string(check.volume / (4 * pi / 3) - 1));
    RecordProperty("area_error", std::to_string(check.area / (4 * pi) - 1));
}

// Vertices within `radius` of a point, by a hash of cells of that size.
class VertexIndex {
  public:
    VertexIndex(const Mesh& mesh, double radius) : mesh_(mesh), radius_(radius) {
        for (uint32_t v = 0; v < mesh.positions.size(); ++v)
            cells_[key(cellOf(Point3d(mesh.positions[v])))].push_back(v);
    }
    double nearestDistance(const Point3d& p) const {
        double best = INFINITY;
        auto c = cellOf(p);
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    auto it = cells_.find(key({c[0] + dx, c[1] + dy, c[2] + dz}));
                    if (it == cells_.end()) continue;
                    for (uint32_t v : it->second)
                        best = std::min(best, length(Point3d(mesh_.positions[v]) - p));
                }
        return best;
    }

  private:
    std::array<int64_t, 3> cellOf(const Point3d& p) const {
        return {int64_t(std::floor(p.x / radius_)), int64_t(std::floor(p.y / radius_)),
                int64_t(std::floor(p.z / radius_))};
    }
    static uint64_t key(const std::array<int64_t, 3>& c) {
        return uint64_t(c[0] * 73856093) ^ uint64_t(c[1] * 19349663) ^ uint64_t(c[2] * 83492791);
    }
    const Mesh& mesh_;
    double radius_;
    std::unordered_map<uint64_t, std::vector<uint32_t>> cells_;
};

// A real c: the set is a solid of revolution about the real (x) axis, and so is its mesh:
// mirrored or turned about x, every vertex lands within a cell of a vertex of the mesh.
TEST(Mesher, RealConstantGivesSolidOfRevolution) {
    Scene scene = defaultScene();
    scene.fractal.c = Quaternion{-0.5, 0, 0, 0};
    MeshResult result = meshAt(scene, 64);
    ASSERT_TRUE(checkMesh(result.mesh).watertight());
    const double cell = result.stats.grid.cellSize;
    VertexIndex index(result.mesh, cell);
    auto turned = [](const Point3d& p, double degrees) {
        double a = degrees * std::numbers::pi / 180, c = std::cos(a), s = std::sin(a);
        return Point3d(p.x, c * p.y - s * p.z, s * p.y + c * p.z);
    };
    for (double degrees : {30.0, 90.0, 180.0}) {
        double worst = 0;
        for (const Vector3f& v : result.mesh.positions)
            worst = std::max(worst, index.nearestDistance(turned(Point3d(v), degrees)));
        EXPECT_LE(worst, cell) << "turned by " << degrees << " degrees about x";
    }
    double worstMirror = 0;
    for (const Vector3f& v : result.mesh.positions) {
        worstMirror = std::max(worstMirror, index.nearestDistance(Point3d(v.x, -v.y, v.z)));
        worstMirror = std::max(worstMirror, index.nearestDistance(Point3d(v.x, v.y, -v.z)));
    }
    EXPECT_LE(worstMirror, cell);
}

// Every vertex is within a cell of the surface the renderer draws: its estimate is below a
// cell (0 inside K_N).
TEST(Mesher, VerticesLieOnRenderedSurface) {
    Scene scene = testing::referenceScene("case01_sqr_A");
    MeshResult result = meshAt(scene, 96);
    Fractal fractal = fractalFromScene(scene);
    double worst = 0;
    for (const Vector3f& v : result.mesh.positions)
        worst = std::max(worst, fractal.estimate(Point3d(v)).distance);
    EXPECT_LT(worst, result.stats.grid.cellSize);
    EXPECT_GT(result.mesh.positions.size(), 1000u);
}

// The iso offset moves the surface out: more volume, still closed.
TEST(Mesher, IsoOffsetThickensAndStaysClosed) {
    Scene scene = testing::unitBallScene(32, 32);
    MeshCheck plain = checkMesh(meshAt(scene, 48).mesh);
    MeshResult thick = meshAt(scene, 48, 1.0);
    MeshCheck check = checkMesh(thick.mesh);
    EXPECT_TRUE(check.watertight());
    // DE = 0.5 (r - 1) near the unit ball, so DE = one cell lies two cells out.
    double radius = 1 + 2 * thick.stats.grid.cellSize;
    EXPECT_NEAR(check.volume / (4 * std::numbers::pi / 3 * radius * radius * radius), 1, 0.03);
    EXPECT_GT(check.volume, plain.volume);
}

TEST(Mesher, MinComponentDropsSpecks) {
    Scene scene = testing::referenceScene("case03_sqr_C");
    MeshResult all = meshAt(scene, 64);
    MeshCheck before = checkMesh(all.mesh);
    ASSERT_GT(before.components, 1) << "a dusty set is needed";
    scene.mesh.minComponent = 1e-3;
    MeshResult kept = meshAt(scene, 64);
    MeshCheck after = checkMesh(kept.mesh);
    EXPECT_LT(after.components, before.components);
    EXPECT_EQ(kept.stats.droppedComponents, before.components - after.components);
    EXPECT_TRUE(after.watertight());
}

TEST(Mesher, CancelledMeshSaysSo) {
    std::atomic<bool> cancel{true};
    MeshOptions options;
    options.cancel = &cancel;
    Scene scene = defaultScene();
    scene.mesh.resolution = 64;
    EXPECT_FALSE(meshScene(scene, options).completed);
}

TEST(Mesher, BoxSearchStopsAtItsBudgetWithTheBoundingCube) {
    // A biquaternion set whose Lipschitz bound rules out no cube (issue 41: `mesh --resolution 9`
    // took seconds, minutes under the sanitizers): the search takes its budget of estimates and
    // answers the bounding cube, which holds the set; the presets' sets take far fewer.
    Scene scene = defaultScene();
    scene.fractal.algebra = Algebra::kBiquaternion;
    scene.fractal.formula = "(0.28-0.335i+0.296k)*z^4 + c";
    scene.fractal.c = Quaternion(0.971, 0.664, -1.188, -0.561);
    scene.fractal.cUpper = {1.141, 0.733, 1.095, -0.445};
    scene.fractal.cComponents = 8;
    scene.fractal.maxIterations = 8;
    const Fractal fractal = fractalFromScene(scene);
    int64_t estimates = 0;
    const auto box = boundingBoxOfSet(fractal, kBoundingBoxDivisions, estimates);
    ASSERT_TRUE(box);
    const double r = fractal.boundingRadius();
    EXPECT_NEAR(box->lower.x, -r, 1e-12);
    EXPECT_NEAR(box->upper.z, r, 1e-12);
    EXPECT_LE(estimates, (int64_t(1) << 19) + 1);
    int64_t presetEstimates = 0;
    boundingBoxOfSet(fractalFromScene(defaultScene()), kBoundingBoxDivisions, presetEstimates);
    EXPECT_LT(presetEstimates, int64_t(1) << 17);
}

}  // namespace
}  // namespace quaternia
