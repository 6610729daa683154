// Contouring one block of the mesh grid by marching tetrahedra (docs/methods.md, Meshes): each
// cell is cut into the 6 tetrahedra of the Freudenthal (Kuhn) triangulation, which all share
// the cell's main diagonal and cut every face along the same diagonal, so neighbouring cells
// and blocks agree and no ambiguous case can open a hole. A vertex sits on each edge whose ends
// differ in sign, found by bisection on the field; its key is the edge's, so blocks that share
// the edge make the same vertex and the mesher welds them into one.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "quaternia/fractal/fractal.h"
#include "quaternia/mesh/mesh.h"
#include "quaternia/mesh/mesh_grid.h"

namespace quaternia {

// The field contoured, f(p) = DE(p) - offset outside K_N and negative inside (only its sign is
// used): its zero set is the boundary of K_N, or the surface `offset` out from it.
class MeshField {
  public:
    MeshField(const Fractal& fractal, double offset) : fractal_(fractal), offset_(offset) {}
    bool inside(const Point3d& p) const {
        // Without an offset the sign is membership alone, cheaper than an estimate (no
        // derivative, no logarithm).
        if (offset_ <= 0) return fractal_.contains(p);
        DistanceEstimate e = fractal_.estimate(p);
        return e.inside || e.distance <= offset_;
    }
    const Fractal& fractal() const { return fractal_; }

  private:
    const Fractal& fractal_;
    double offset_;
};

// The triangles of one block, vertices numbered locally.
struct BlockMesh {
    std::vector<uint64_t> edgeKeys;  // of each vertex: the grid edge it lies on
    std::vector<Vector3f> positions;
    // Local indices fit 16 bits: a block has at most 7 (blockSize + 1)^3 edges.
    std::vector<std::array<uint16_t, 3>> triangles;
    // Bit f (faces -x, +x, -y, +y, -z, +z) is set in openFaces when face f has corners of both
    // signs: the surface goes on into the neighbour across it, which must then be contoured
    // too; and in outsideFaces when face f has an outside corner.
    uint8_t openFaces = 0, outsideFaces = 0;
    int64_t estimates = 0;
};

// Reusable per worker.
struct BlockScratch {
    std::vector<uint8_t> insideCorner;
    std::vector<int32_t> vertexOfEdge;
};

// Contours the cells [block * blockSize, block * blockSize + blockSize) (clipped to the grid).
// Corners on the grid's outer faces count as outside, so the mesh is closed even where the set
// would reach them. Triangles are ordered counter-clockwise seen from outside.
BlockMesh contourBlock(const MeshField& field, const MeshGrid& grid, const LatticeIndex& block,
                       int blockSize, BlockScratch& scratch);

// Bisection steps placing a vertex on its edge: within 2^-(steps+1) of the edge's length of
// where the sign changes.
inline constexpr int kBisectionSteps = 6;

}  // namespace quaternia
