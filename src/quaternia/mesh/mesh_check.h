// Checking that a mesh bounds a solid (docs/methods.md, Meshes: check closedness yourself, and
// with admesh): every edge used by exactly two triangles in opposite directions, the triangles
// around each vertex forming one disc, no degenerate triangles; and the measures a printer or
// a user wants: volume, surface area, connected components.
#pragma once

#include <cstdint>
#include <vector>

#include "quaternia/mesh/mesh.h"

namespace quaternia {

struct MeshCheck {
    int64_t vertices = 0, triangles = 0;
    int64_t boundaryEdges = 0;        // used by one triangle: a hole's rim
    int64_t nonManifoldEdges = 0;     // used by three triangles or more
    int64_t misorientedEdges = 0;     // used twice in the same direction
    int64_t nonManifoldVertices = 0;  // triangles around it form several fans (pinched)
    int64_t degenerateTriangles = 0;  // a repeated vertex, or zero area in float
    int64_t unusedVertices = 0;
    int64_t components = 0;  // connected by shared vertices
    double volume = 0;       // signedVolume
    double area = 0;

    // Closed, manifold and consistently oriented outward, with no degenerate triangles.
    bool watertight() const {
        return boundaryEdges == 0 && nonManifoldEdges == 0 && misorientedEdges == 0 &&
               nonManifoldVertices == 0 && degenerateTriangles == 0 && volume > 0;
    }
};

// Linear in the mesh size; `threads` as ParallelOptions::threads.
MeshCheck checkMesh(const Mesh& mesh, int threads = 0);

struct MeshComponents {
    std::vector<uint32_t> ofTriangle;  // component of each triangle, in [0, count)
    uint32_t count = 0;                // numbered in the order of their first triangle
};
// Triangles sharing a vertex are in one component (union-find over the vertices).
MeshComponents labelComponents(const Mesh& mesh);

// The mesh without the components whose |signed volume| is below minimumVolume (world units
// cubed): the floating specks of dusty sets. minimumVolume <= 0 keeps everything.
Mesh dropSmallComponents(const Mesh& mesh, double minimumVolume);

}  // namespace quaternia
