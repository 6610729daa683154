// The mesh check on meshes whose defects are known: a closed cube, then the same cube with a
// hole, a flipped triangle, a pinch and a degenerate triangle.
#include "quaternia/mesh/mesh_check.h"

#include <gtest/gtest.h>

namespace quaternia {
namespace {

// The cube [0, s]^3 + offset, 12 triangles, counter-clockwise seen from outside.
Mesh cube(double s = 1, Vector3f offset = {}) {
    Mesh mesh;
    for (int k = 0; k < 8; ++k)
        mesh.positions.push_back(
            Vector3f(float(s * (k & 1)), float(s * ((k >> 1) & 1)), float(s * ((k >> 2) & 1))) +
            offset);
    mesh.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                      {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    return mesh;
}

Mesh joined(const Mesh& a, const Mesh& b) {
    Mesh out = a;
    auto shift = uint32_t(a.positions.size());
    out.positions.insert(out.positions.end(), b.positions.begin(), b.positions.end());
    for (Triangle t : b.triangles)
        out.triangles.push_back({t[0] + shift, t[1] + shift, t[2] + shift});
    return out;
}

TEST(MeshCheck, ClosedCubeIsWatertight) {
    MeshCheck check = checkMesh(cube(2));
    EXPECT_TRUE(check.watertight());
    EXPECT_EQ(check.components, 1);
    EXPECT_DOUBLE_EQ(check.volume, 8);
    EXPECT_DOUBLE_EQ(check.area, 24);
    EXPECT_EQ(check.unusedVertices, 0);
}

TEST(MeshCheck, FindsHoleFlipAndInsideOut) {
    Mesh holed = cube();
    holed.triangles.pop_back();
    EXPECT_EQ(checkMesh(holed).boundaryEdges, 3);
    EXPECT_FALSE(checkMesh(holed).watertight());

    Mesh flipped = cube();
    std::swap(flipped.triangles[0][1], flipped.triangles[0][2]);
    EXPECT_EQ(checkMesh(flipped).misorientedEdges, 3);

    Mesh insideOut = cube();
    for (Triangle& t : insideOut.triangles)
        std::swap(t[1], t[2]);
    MeshCheck check = checkMesh(insideOut);
    EXPECT_DOUBLE_EQ(check.volume, -1);
    EXPECT_FALSE(check.watertight());
}

TEST(MeshCheck, FindsNonManifoldEdgeVertexAndDegenerate) {
    Mesh tripled = cube();
    tripled.triangles.push_back({0, 2, 1});
    EXPECT_EQ(checkMesh(tripled).nonManifoldEdges, 3);

    // Two cubes touching at one corner, welded there: closed edges, pinched vertex.
    Mesh pinched = joined(cube(), cube(1, {1, 1, 1}));
    for (Triangle& t : pinched.triangles)
        for (uint32_t& v : t)
            if (v == 8) v = 7;
    MeshCheck check = checkMesh(pinched);
    EXPECT_EQ(check.boundaryEdges, 0);
    EXPECT_EQ(check.nonManifoldVertices, 1);
    EXPECT_EQ(check.unusedVertices, 1);

    Mesh degenerate = cube();
    degenerate.positions.push_back({0.5f, 0, 0});
    degenerate.triangles.push_back({0, 1, 8});
    EXPECT_EQ(checkMesh(degenerate).degenerateTriangles, 1);
}

TEST(MeshCheck, DropsComponentsBelowVolume) {
    Mesh two = joined(cube(1), cube(0.1, {3, 0, 0}));
    EXPECT_EQ(checkMesh(two).components, 2);
    Mesh kept = dropSmallComponents(two, 0.01);
    MeshCheck check = checkMesh(kept);
    EXPECT_EQ(check.components, 1);
    EXPECT_EQ(check.vertices, 8);
    EXPECT_DOUBLE_EQ(check.volume, 1);
    EXPECT_EQ(dropSmallComponents(two, 0).triangles.size(), 24u);
}

}  // namespace
}  // namespace quaternia
