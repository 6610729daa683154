// Where the mesher samples: a lattice of cells over the set's bounding box, and the sparse
// search for the cubes of a lattice that the set can reach (docs/methods.md, Meshes: a cube whose
// centre has a distance estimate greater than its half-diagonal holds no surface). Searching
// coarse-to-fine over an octree of cubes, the work grows with the surface, not the volume.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <optional>
#include <vector>

#include "quaternia/algebra/vecmath.h"
#include "quaternia/fractal/fractal.h"

namespace quaternia {

using LatticeIndex = std::array<int, 3>;

// Corner (i, j, k) lies at origin + cellSize * (i, j, k), for 0 <= i <= cells[0] and so on.
struct MeshGrid {
    Point3d origin;
    double cellSize = 0;
    LatticeIndex cells{};

    // Always computed the same way, so that the blocks sharing a corner see the same point.
    Point3d corner(int i, int j, int k) const {
        return {origin.x + cellSize * i, origin.y + cellSize * j, origin.z + cellSize * k};
    }
    // A key unique to each corner of the grid.
    uint64_t cornerKey(int i, int j, int k) const {
        return uint64_t(i) + uint64_t(cells[0] + 1) * (uint64_t(j) + uint64_t(cells[1] + 1) * k);
    }
};

struct Box {
    Point3d lower, upper;
};

// The cubes (origin + side * (index + [0, 1]^3), index in [0, counts)) that may hold points
// whose estimate is at most `reach`: those whose centre's estimate does not exceed their
// half-diagonal plus reach, tested first on blocks of 2^k cubes. In lattice order of the
// top-level blocks, then octree order; `estimates` counts the distance estimates. Returns
// nullopt if cancelled.
std::optional<std::vector<LatticeIndex>> reachableCubes(
    const Fractal& fractal, const Point3d& origin, double side, const LatticeIndex& counts,
    double reach, int threads, const std::atomic<bool>* cancel, int64_t& estimates);

// A box that holds the set: the box of the reachable cubes of a lattice of `divisions` cubes
// per side (a power of two) over the bounding ball. Empty (nullopt) when no cube is reachable.
std::optional<Box> boundingBoxOfSet(const Fractal& fractal, int divisions, int64_t& estimates);

// `resolution` cells along the box's longest side, and `padding` cells more on every side.
MeshGrid gridOverBox(const Box& box, int resolution, int padding);

}  // namespace quaternia
