#include "quaternia/mesh/mesher.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <utility>

#include "quaternia/fractal/fractal.h"
#include "quaternia/mesh/marching_tetrahedra.h"
#include "quaternia/mesh/mesh_check.h"
#include "quaternia/render/shade.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/util/memory_budget.h"
#include "quaternia/util/parallel.h"

namespace quaternia {
namespace {

// Fractions of the progress bar: contouring is nearly all of the work.
constexpr double kContourShare = 0.9;

// The blocks of the grid, with a flag per block (dense: one bit each, 17 MB at resolution 4096).
struct BlockLattice {
    LatticeIndex counts;
    std::size_t index(const LatticeIndex& b) const {
        return std::size_t(b[0]) +
               std::size_t(counts[0]) * (std::size_t(b[1]) + std::size_t(counts[1]) * b[2]);
    }
    bool contains(const LatticeIndex& b) const {
        return b[0] >= 0 && b[1] >= 0 && b[2] >= 0 && b[0] < counts[0] && b[1] < counts[1] &&
               b[2] < counts[2];
    }
    std::size_t size() const { return std::size_t(counts[0]) * counts[1] * counts[2]; }
};

LatticeIndex across(LatticeIndex block, int face) {
    block[face / 2] += face % 2 ? 1 : -1;
    return block;
}

// Which blocks to contour. The distance estimate rules out blocks outside the set but not
// blocks inside it (the estimate is 0 there), and contouring the inside of a solid set would
// cost as much as a dense grid. So the blocks are reached as the outside is, by flood fill:
// first the near blocks that touch a ruled-out block or the grid's edge, then, wave after wave,
// the near blocks across any face with an outside corner, and any block at all across a face
// the surface crosses (so no hole can follow from an estimate that is too large). Blocks walled
// in by inside corners are never contoured: cavities that cannot be seen from outside are
// filled, as a printer wants. Returns false if cancelled.
bool contourBlocks(const MeshField& field, const MeshGrid& grid, const BlockLattice& lattice,
                   const std::vector<LatticeIndex>& near, const MeshOptions& options,
                   MeshStats& stats, std::vector<BlockMesh>& meshes) {
    std::vector<bool> isNear(lattice.size()), done(lattice.size());
    for (const LatticeIndex& b : near)
        isNear[lattice.index(b)] = true;
    std::vector<LatticeIndex> todo;
    for (const LatticeIndex& b : near) {
        for (int face = 0; face < 6; ++face) {
            LatticeIndex n = across(b, face);
            if (!lattice.contains(n) || !isNear[lattice.index(n)]) {
                todo.push_back(b);
                done[lattice.index(b)] = true;
                break;
            }
        }
    }
    std::vector<BlockScratch> scratch(std::size_t(resolveThreadCount(options.threads)));
    while (!todo.empty()) {
        std::vector<BlockMesh> wave(todo.size());
        ParallelOptions parallel;
        parallel.threads = options.threads;
        parallel.cancel = options.cancel;
        parallel.chunkSize = 1;
        if (options.progress) {
            // Near blocks bound the work but not exactly: blocks added across open faces, and
            // interior blocks never reached, make the bar jump or stop short of the end.
            const double before = double(stats.blocks), total = double(near.size()) + 1;
            parallel.progress = [&options, before, total](int64_t finished, int64_t) {
                options.progress(kContourShare * std::min(1.0, (before + finished) / total));
            };
        }
        bool completed = parallelFor(
            int64_t(todo.size()), parallel, [&](int64_t begin, int64_t end, int thread) {
                for (int64_t b = begin; b < end; ++b)
                    wave[std::size_t(b)] =
                        contourBlock(field, grid, todo[std::size_t(b)], kMeshBlockSize,
                                     scratch[std::size_t(thread)]);
            });
        if (!completed) return false;
        stats.blocks += int64_t(todo.size());
        std::vector<LatticeIndex> next;
        for (std::size_t b = 0; b < todo.size(); ++b) {
            for (int face = 0; face < 6; ++face) {
                LatticeIndex n = across(todo[b], face);
                if (!lattice.contains(n) || done[lattice.index(n)]) continue;
                bool open = (wave[b].openFaces >> face) & 1;
                bool outside = (wave[b].outsideFaces >> face) & 1;
                if (!open && !(outside && isNear[lattice.index(n)])) continue;
                done[lattice.index(n)] = true;
                next.push_back(n);
                stats.closureBlocks += !isNear[lattice.index(n)];
            }
            stats.estimates += wave[b].estimates;
            if (!wave[b].triangles.empty()) meshes.push_back(std::move(wave[b]));
        }
        todo = std::move(next);
    }
    return true;
}

// One vertex per grid edge: the blocks' vertices sorted by edge key, duplicates (from edges
// on faces between blocks) merged, and the triangles renumbered. Block data is released as
// soon as it has been used, and every array reserved at its final size, to keep the peak low.
Mesh weld(std::vector<BlockMesh>& blocks) {
    std::vector<std::size_t> firstRecord(blocks.size() + 1, 0);
    std::size_t triangleCount = 0;
    for (std::size_t b = 0; b < blocks.size(); ++b) {
        firstRecord[b + 1] = firstRecord[b] + blocks[b].positions.size();
        triangleCount += blocks[b].triangles.size();
    }
    std::vector<std::pair<uint64_t, uint32_t>> keyed;
    keyed.reserve(firstRecord.back());
    for (std::size_t b = 0; b < blocks.size(); ++b) {
        for (std::size_t v = 0; v < blocks[b].edgeKeys.size(); ++v)
            keyed.push_back({blocks[b].edgeKeys[v], uint32_t(firstRecord[b] + v)});
        blocks[b].edgeKeys = {};
    }
    std::sort(keyed.begin(), keyed.end());

    Mesh mesh;
    std::size_t unique = 0;
    for (std::size_t r = 0; r < keyed.size(); ++r)
        unique += r == 0 || keyed[r].first != keyed[r - 1].first;
    mesh.positions.reserve(unique);
    std::vector<uint32_t> vertexOfRecord(keyed.size());
    for (std::size_t r = 0; r < keyed.size(); ++r) {
        if (r == 0 || keyed[r].first != keyed[r - 1].first) {
            std::size_t record = keyed[r].second;
            auto block =
                std::size_t(std::upper_bound(firstRecord.begin(), firstRecord.end(), record) -
                            firstRecord.begin() - 1);
            mesh.positions.push_back(blocks[block].positions[record - firstRecord[block]]);
        }
        vertexOfRecord[keyed[r].second] = uint32_t(mesh.positions.size() - 1);
    }
    keyed = {};
    for (BlockMesh& block : blocks)
        block.positions = {};
    mesh.triangles.reserve(triangleCount);
    for (std::size_t b = 0; b < blocks.size(); ++b) {
        const std::size_t first = firstRecord[b];
        for (const auto& t : blocks[b].triangles)
            mesh.triangles.push_back({vertexOfRecord[first + t[0]], vertexOfRecord[first + t[1]],
                                      vertexOfRecord[first + t[2]]});
        blocks[b] = {};
    }
    return mesh;
}

// The renderer's look at each vertex: its analytic normal and its orbit colour (shade.h).
bool addNormalsAndColors(const Scene& scene, const Fractal& fractal, Mesh& mesh,
                         const MeshOptions& options, MeshStats& stats) {
    Shader shader(scene.shading, fractal, scene.lights);
    mesh.normals.resize(mesh.positions.size());
    mesh.colors.resize(mesh.positions.size());
    ParallelOptions parallel;
    parallel.threads = options.threads;
    parallel.cancel = options.cancel;
    bool completed =
        parallelFor(int64_t(mesh.positions.size()), parallel, [&](int64_t begin, int64_t end, int) {
            for (int64_t v = begin; v < end; ++v) {
                Point3d p(mesh.positions[std::size_t(v)]);
                mesh.normals[std::size_t(v)] = Vector3f(fractal.normal(p));
                Color c = shader.toDisplay(shader.albedo(fractal.estimate(p)));
                auto byte = [](double x) { return uint8_t(std::lround(x * 255)); };
                mesh.colors[std::size_t(v)] = {byte(c.x), byte(c.y), byte(c.z)};
            }
        });
    stats.estimates += 2 * int64_t(mesh.positions.size());
    return completed;
}

// The iso surface lies where DE = iso cells, which is up to about twice as far out as iso
// cells (the estimate runs at 0.5 to 1 times the distance near the set); two cells more keep
// it off the grid's outer faces, where the mesh would be clipped.
int paddingCells(const Scene& scene) {
    return 2 + int(std::ceil(2 * scene.mesh.iso));
}

// Contours the blocks of `grid` that the surface DE = iso cells can reach into `meshes`.
// Returns false if cancelled.
bool contourGrid(const Fractal& fractal, const MeshGrid& grid, double iso,
                 const MeshOptions& options, MeshStats& stats, std::vector<BlockMesh>& meshes) {
    const double offset = iso * grid.cellSize;
    BlockLattice lattice;
    for (int axis = 0; axis < 3; ++axis)
        lattice.counts[axis] = (grid.cells[axis] + kMeshBlockSize - 1) / kMeshBlockSize;
    stats.latticeBlocks = int64_t(lattice.counts[0]) * lattice.counts[1] * lattice.counts[2];
    // Blocks that may hold a point with DE <= offset; one cell of slack for the corners that
    // a block shares with its neighbours.
    auto blocks =
        reachableCubes(fractal, grid.origin, kMeshBlockSize * grid.cellSize, lattice.counts,
                       offset + grid.cellSize, options.threads, options.cancel, stats.estimates);
    if (!blocks) return false;
    MeshField field(fractal, offset);
    stats.nearBlocks = int64_t(blocks->size());
    return contourBlocks(field, grid, lattice, *blocks, options, stats, meshes);
}

// Triangles of the scene's surface contoured at `resolution` over `box` (a pilot for the
// estimate below, whose estimates MeshStats does not count); nothing if cancelled.
std::optional<int64_t> pilotTriangles(const Scene& scene, const Fractal& fractal, const Box& box,
                                      int resolution, const MeshOptions& options) {
    MeshStats pilot;
    std::vector<BlockMesh> meshes;
    MeshOptions quiet = options;
    quiet.progress = nullptr;
    if (!contourGrid(fractal, gridOverBox(box, resolution, paddingCells(scene)), scene.mesh.iso,
                     quiet, pilot, meshes))
        return std::nullopt;
    int64_t triangles = 0;
    for (const BlockMesh& block : meshes)
        triangles += int64_t(block.triangles.size());
    return triangles;
}

// Peak bytes per triangle of a whole meshScene run (blocks, welding, normals and colours, the
// check, the writer), measured at resolutions 128 to 512 at about 55 and rounded up; dropping
// small components copies the mesh once more.
constexpr double kBytesPerTriangle = 72, kBytesPerTriangleDropped = 32;
// The surface's triangle count grows with the resolution to a power between 2 (a smooth
// surface) and 3 (a set that fills space); where only one pilot runs, this power stands in.
constexpr double kAssumedGrowth = 2.5;

// An estimate of the memory meshScene needs at scene.mesh.resolution, from pilot meshes at
// resolutions 64 and (for large requests, where it costs little beside the work) 128 over the
// same box: their triangle counts give the surface's growth with the resolution, which
// extrapolates the count. Nothing if cancelled.
std::optional<uint64_t> meshMemoryOverBox(const Scene& scene, const Fractal& fractal,
                                          const Box& box, const MeshOptions& options,
                                          MeshStats& stats) {
    const int resolution = scene.mesh.resolution;
    const int low = std::min(resolution, 64);
    auto lowCount = pilotTriangles(scene, fractal, box, low, options);
    if (!lowCount) return std::nullopt;
    double growth = kAssumedGrowth, base = double(*lowCount), from = low;
    if (resolution > 256) {
        auto highCount = pilotTriangles(scene, fractal, box, 128, options);
        if (!highCount) return std::nullopt;
        if (*lowCount > 0 && *highCount > 0)
            growth = std::clamp(std::log2(double(*highCount) / double(*lowCount)), 2.0, 3.0);
        base = double(*highCount);
        from = 128;
    }
    const double triangles = std::max(base, 1.0) * std::pow(resolution / from, growth);
    stats.estimatedTriangles = int64_t(std::min(triangles, 9e18));
    const double perTriangle =
        kBytesPerTriangle + (scene.mesh.minComponent > 0 ? kBytesPerTriangleDropped : 0);
    return uint64_t(std::min(triangles * perTriangle, 1.8e19));
}

}  // namespace

MeshResult meshScene(const Scene& scene, const MeshOptions& options) {
    auto start = std::chrono::steady_clock::now();
    validateScene(scene);
    Fractal fractal = fractalFromScene(scene);
    requireFractalMemory(scene, fractal, options.memory);  // the maps its membership tests build
    MeshResult result;
    MeshStats& stats = result.stats;
    stats.threads = resolveThreadCount(options.threads);
    stats.blockSize = kMeshBlockSize;
    auto finish = [&]() -> MeshResult {
        stats.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return std::move(result);
    };

    auto box = boundingBoxOfSet(fractal, kBoundingBoxDivisions, stats.estimates);
    if (!box) return finish();  // nothing to mesh
    if (options.memory.bytes != 0) {
        std::optional<uint64_t> bytes = meshMemoryOverBox(scene, fractal, *box, options, stats);
        if (!bytes) {
            result.completed = false;
            return finish();
        }
        requireMemory(*bytes, options.memory, "mesh.resolution",
                      "mesh.resolution = " + std::to_string(scene.mesh.resolution) +
                          " (a mesh of about " + std::to_string(stats.estimatedTriangles) +
                          " triangles)",
                      "lower mesh.resolution, or set --memory-budget");
    }
    stats.grid = gridOverBox(*box, scene.mesh.resolution, paddingCells(scene));
    std::vector<BlockMesh> meshes;
    if (!contourGrid(fractal, stats.grid, scene.mesh.iso, options, stats, meshes)) {
        result.completed = false;
        return finish();
    }
    result.mesh = weld(meshes);
    if (options.normalsAndColors &&
        !addNormalsAndColors(scene, fractal, result.mesh, options, stats)) {
        result.completed = false;
        return finish();
    }
    if (scene.mesh.minComponent > 0) {
        uint32_t before = labelComponents(result.mesh).count;
        result.mesh = dropSmallComponents(result.mesh, scene.mesh.minComponent);
        stats.droppedComponents = before - labelComponents(result.mesh).count;
    }
    if (options.progress) options.progress(1.0);
    return finish();
}

}  // namespace quaternia
