// A triangle mesh as the mesher makes it and the writers export it: welded vertices (each
// shared by all the triangles around it) with an optional normal and colour each, and triangles
// as vertex indices ordered counter-clockwise seen from outside, so that the right-hand normal
// points out and the signed volume is positive.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "quaternia/algebra/vecmath.h"

namespace quaternia {

using Triangle = std::array<uint32_t, 3>;
using Rgb8 = std::array<uint8_t, 3>;

struct Mesh {
    std::vector<Vector3f> positions;
    std::vector<Vector3f> normals;  // unit and outward; empty, or one per vertex
    std::vector<Rgb8> colors;       // display RGB; empty, or one per vertex
    std::vector<Triangle> triangles;
};

// (b - a) x (c - a) of triangle t: outward, twice its area long.
Vector3d triangleNormal(const Mesh& mesh, const Triangle& t);
// a . (b x c) / 6: the signed volume of the tetrahedron from the origin to triangle t.
double triangleSignedVolume(const Mesh& mesh, const Triangle& t);
// Sum of the triangles' areas.
double surfaceArea(const Mesh& mesh);
// The enclosed volume by the divergence theorem, the sum of triangleSignedVolume:
// positive for a closed, outward-oriented mesh. Meaningless for an open one.
double signedVolume(const Mesh& mesh);

// The mesh with only the triangles whose `keep` flag is set, and only the vertices they use
// (renumbered in their old order, normals and colours kept along).
Mesh keepTriangles(const Mesh& mesh, const std::vector<bool>& keep);

}  // namespace quaternia
