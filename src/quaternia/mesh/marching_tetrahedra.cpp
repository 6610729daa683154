#include "quaternia/mesh/marching_tetrahedra.h"

#include <algorithm>
#include <utility>

namespace quaternia {
namespace {

// A corner of a cell as bits (x, y, z) = (1, 2, 4); an edge of the Freudenthal triangulation
// always joins a corner to a corner with more bits, so (lower, direction) names it.
struct IntVector {
    int x, y, z;
};
constexpr IntVector cornerOffset(int bits) {
    return {bits & 1, (bits >> 1) & 1, (bits >> 2) & 1};
}

// The 6 tetrahedra of a cell: corner 0, then one axis, then a second, then corner 7, for each
// order of the three axes.
constexpr int kTetrahedra[6][4] = {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7},
                                   {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}};

class BlockContour {
  public:
    BlockContour(const MeshField& field, const MeshGrid& grid, const LatticeIndex& block,
                 int blockSize, BlockScratch& scratch)
        : field_(field), grid_(grid), scratch_(scratch) {
        for (int axis = 0; axis < 3; ++axis) {
            lower_[axis] = block[axis] * blockSize;
            cells_[axis] = std::min(blockSize, grid.cells[axis] - lower_[axis]);
        }
        std::size_t corners = std::size_t(cells_[0] + 1) * (cells_[1] + 1) * (cells_[2] + 1);
        scratch_.insideCorner.assign(corners, 0);
        scratch_.vertexOfEdge.assign(corners * 7, -1);
    }

    BlockMesh run() {
        evaluateCorners();
        for (int k = 0; k < cells_[2]; ++k)
            for (int j = 0; j < cells_[1]; ++j)
                for (int i = 0; i < cells_[0]; ++i)
                    contourCell(i, j, k);
        // Blocks are kept until all are welded: capacity left over would be a third of the
        // peak memory.
        out_.edgeKeys.shrink_to_fit();
        out_.positions.shrink_to_fit();
        out_.triangles.shrink_to_fit();
        return std::move(out_);
    }

  private:
    int localCorner(int i, int j, int k) const {
        return i + (cells_[0] + 1) * (j + (cells_[1] + 1) * k);
    }
    bool onGridBoundary(int i, int j, int k) const {
        int gi = lower_[0] + i, gj = lower_[1] + j, gk = lower_[2] + k;
        return gi == 0 || gj == 0 || gk == 0 || gi == grid_.cells[0] || gj == grid_.cells[1] ||
               gk == grid_.cells[2];
    }
    Point3d cornerPoint(int i, int j, int k) const {
        return grid_.corner(lower_[0] + i, lower_[1] + j, lower_[2] + k);
    }

    void evaluateCorners() {
        int mixed[6][2] = {};  // per face: corners outside, corners inside
        for (int k = 0; k <= cells_[2]; ++k)
            for (int j = 0; j <= cells_[1]; ++j)
                for (int i = 0; i <= cells_[0]; ++i) {
                    bool inside = false;
                    if (!onGridBoundary(i, j, k)) {
                        inside = field_.inside(cornerPoint(i, j, k));
                        ++out_.estimates;
                    }
                    scratch_.insideCorner[std::size_t(localCorner(i, j, k))] = inside;
                    int at[3] = {i, j, k};
                    for (int axis = 0; axis < 3; ++axis) {
                        if (at[axis] == 0) ++mixed[2 * axis][inside];
                        if (at[axis] == cells_[axis]) ++mixed[2 * axis + 1][inside];
                    }
                }
        for (int face = 0; face < 6; ++face) {
            if (mixed[face][0] > 0) out_.outsideFaces |= uint8_t(1 << face);
            if (mixed[face][0] > 0 && mixed[face][1] > 0) out_.openFaces |= uint8_t(1 << face);
        }
    }

    // The vertex on the edge from corner bits `from` to `to` (to has more bits) of cell (i, j, k).
    uint16_t edgeVertex(int i, int j, int k, int from, int to) {
        IntVector a = cornerOffset(from), b = cornerOffset(to);
        int ai = i + a.x, aj = j + a.y, ak = k + a.z;
        int direction = (from ^ to) - 1;
        int32_t& slot =
            scratch_
                .vertexOfEdge[std::size_t(localCorner(ai, aj, ak)) * 7 + std::size_t(direction)];
        if (slot >= 0) return uint16_t(slot);
        slot = int32_t(out_.positions.size());
        // Bisect from the lower corner always, so every block finds the same point.
        Point3d p = cornerPoint(ai, aj, ak);
        Point3d q = cornerPoint(i + b.x, j + b.y, k + b.z);
        bool pInside = scratch_.insideCorner[std::size_t(localCorner(ai, aj, ak))] != 0;
        for (int step = 0; step < kBisectionSteps; ++step) {
            Point3d middle = (p + q) * 0.5;
            (field_.inside(middle) == pInside ? p : q) = middle;
        }
        out_.estimates += kBisectionSteps;
        uint64_t corner = grid_.cornerKey(lower_[0] + ai, lower_[1] + aj, lower_[2] + ak);
        out_.edgeKeys.push_back(corner * 7 + uint64_t(direction));
        out_.positions.push_back(Vector3f((p + q) * 0.5));
        return uint16_t(slot);
    }

    void contourCell(int i, int j, int k) {
        int insideBits = 0;
        for (int bits = 0; bits < 8; ++bits) {
            IntVector o = cornerOffset(bits);
            if (scratch_.insideCorner[std::size_t(localCorner(i + o.x, j + o.y, k + o.z))])
                insideBits |= 1 << bits;
        }
        if (insideBits == 0 || insideBits == 0xff) return;
        for (const auto& tetrahedron : kTetrahedra)
            contourTetrahedron(i, j, k, tetrahedron, insideBits);
    }

    void contourTetrahedron(int i, int j, int k, const int (&corners)[4], int insideBits) {
        int in[4], out[4], inCount = 0, outCount = 0;
        for (int c : corners)
            ((insideBits >> c) & 1 ? in[inCount++] : out[outCount++]) = c;
        if (inCount == 0 || outCount == 0) return;
        auto vertex = [&](int u, int v) {
            return EdgePoint{u, v, edgeVertex(i, j, k, std::min(u, v), std::max(u, v))};
        };
        if (inCount == 1 || outCount == 1) {
            // One corner alone: the triangle cuts its three edges.
            int alone = inCount == 1 ? in[0] : out[0];
            const int* others = inCount == 1 ? out : in;
            emit(vertex(alone, others[0]), vertex(alone, others[1]), vertex(alone, others[2]),
                 in[0], out[0]);
            return;
        }
        // Two and two: a quadrilateral ac, ad, bd, bc, cut along its shorter diagonal.
        EdgePoint ac = vertex(in[0], out[0]), ad = vertex(in[0], out[1]);
        EdgePoint bd = vertex(in[1], out[1]), bc = vertex(in[1], out[0]);
        if (distanceSquared(ac, bd) <= distanceSquared(ad, bc)) {
            emit(ac, ad, bd, in[0], out[0]);
            emit(ac, bd, bc, in[0], out[0]);
        } else {
            emit(ad, bd, bc, in[0], out[0]);
            emit(ad, bc, ac, in[0], out[0]);
        }
    }

    struct EdgePoint {
        int u, v;  // corner bits of the edge's ends
        uint16_t index;
    };
    float distanceSquared(const EdgePoint& a, const EdgePoint& b) const {
        Vector3f d = out_.positions[a.index] - out_.positions[b.index];
        return dot(d, d);
    }

    // Orientation is decided on the combinatorial surface with every vertex at its edge's
    // midpoint: the zero set of the piecewise-linear field that is -1 at inside corners and +1
    // at outside ones. Its normal points from `insideCorner` to `outsideCorner` (any such pair
    // of the tetrahedron), the test is exact in integers, and it is the same orientation the
    // neighbouring tetrahedra give, so the mesh is consistently oriented outward.
    void emit(const EdgePoint& a, const EdgePoint& b, const EdgePoint& c, int insideCorner,
              int outsideCorner) {
        auto midpoint2 = [](const EdgePoint& e) {
            IntVector u = cornerOffset(e.u), v = cornerOffset(e.v);
            return IntVector{u.x + v.x, u.y + v.y, u.z + v.z};
        };
        IntVector pa = midpoint2(a), pb = midpoint2(b), pc = midpoint2(c);
        IntVector ab{pb.x - pa.x, pb.y - pa.y, pb.z - pa.z};
        IntVector ac{pc.x - pa.x, pc.y - pa.y, pc.z - pa.z};
        IntVector n{ab.y * ac.z - ab.z * ac.y, ab.z * ac.x - ab.x * ac.z,
                    ab.x * ac.y - ab.y * ac.x};
        IntVector in = cornerOffset(insideCorner), out = cornerOffset(outsideCorner);
        int facing = n.x * (out.x - in.x) + n.y * (out.y - in.y) + n.z * (out.z - in.z);
        if (facing > 0)
            out_.triangles.push_back({a.index, b.index, c.index});
        else
            out_.triangles.push_back({a.index, c.index, b.index});
    }

    const MeshField& field_;
    const MeshGrid& grid_;
    BlockScratch& scratch_;
    LatticeIndex lower_{}, cells_{};
    BlockMesh out_;
};

}  // namespace

BlockMesh contourBlock(const MeshField& field, const MeshGrid& grid, const LatticeIndex& block,
                       int blockSize, BlockScratch& scratch) {
    return BlockContour(field, grid, block, blockSize, scratch).run();
}

}  // namespace quaternia
