// Meshing a scene's set: marching tetrahedra (marching_tetrahedra.h) over the blocks of a grid
// that the set can reach (mesh_grid.h), the blocks' vertices welded by their grid edges, each
// vertex given the renderer's analytic normal and orbit colour. The result is closed,
// manifold and outward-oriented by construction; mesh_check.h verifies it.
//
// Sparse blocks are found by the distance estimate and a flood fill of the outside (see
// contourBlocks in mesher.cpp), so work and memory grow with the surface, not the volume.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>

#include "quaternia/mesh/mesh.h"
#include "quaternia/mesh/mesh_grid.h"
#include "quaternia/scene/scene.h"
#include "quaternia/util/memory_budget.h"
#include "quaternia/util/parallel.h"

namespace quaternia {

struct MeshOptions : WorkOptions {
    bool normalsAndColors = true;  // false: positions and triangles only (for checks)
    // With a limit, meshScene estimates the mesh's memory before contouring (from pilot meshes
    // at lower resolutions) and throws UserError naming mesh.resolution if it exceeds it.
    MemoryBudget memory = {};
};

struct MeshStats {
    MeshGrid grid;
    int blockSize = 0;          // cells per block side
    int64_t latticeBlocks = 0;  // blocks of the whole grid (what a dense method would visit)
    int64_t nearBlocks = 0;     // blocks the distance estimate could not rule out
    int64_t blocks = 0;         // blocks contoured
    int64_t closureBlocks = 0;  // of them, ruled out but crossed by the surface at a face
    int64_t estimates = 0;      // distance estimates, all stages
    int64_t droppedComponents = 0;
    int64_t estimatedTriangles = 0;  // the memory check's estimate (0: none made)
    int threads = 0;
    double seconds = 0;
};

struct MeshResult {
    Mesh mesh;
    MeshStats stats;
    bool completed = true;  // false if cancelled
};

// Meshes scene.fractal through scene.slice with scene.mesh's resolution, iso offset and
// smallest component. Validates the scene first (throws UserError naming the bad key).
MeshResult meshScene(const Scene& scene, const MeshOptions& options = {});

// Cells per block side; blocks are the unit of sparseness and of parallel work.
inline constexpr int kMeshBlockSize = 8;
// Cubes per side of the lattice over the bounding ball that finds the set's bounding box.
inline constexpr int kBoundingBoxDivisions = 256;

}  // namespace quaternia
