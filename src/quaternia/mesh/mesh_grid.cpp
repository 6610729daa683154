#include "quaternia/mesh/mesh_grid.h"

#include <algorithm>
#include <cmath>

#include "quaternia/util/parallel.h"

namespace quaternia {
namespace {

// Top-level blocks are this many cubes on a side (a power of two); each is searched as an
// octree on one worker.
constexpr int kTopBlock = 8;

// True when the estimate at a box's centre shows that no point within `radius` of it is in the
// set. An infinite estimate says nothing: it comes from a critical point of the polynomial on
// the orbit (z = 0 for z^2 + c, where z' vanishes), such as the centre of a symmetric box.
bool ruledOut(const DistanceEstimate& e, double radius) {
    return !e.inside && std::isfinite(e.distance) && e.distance > radius;
}

struct CubeSearch {
    const Fractal& fractal;
    Point3d origin;
    double side;
    LatticeIndex counts;
    double reach;

    // The block of `size` cubes per side at `lower`, clipped to the lattice.
    void search(const LatticeIndex& lower, int size, std::vector<LatticeIndex>& out,
                int64_t& estimates) const {
        Vector3d extent;
        for (int axis = 0; axis < 3; ++axis)
            extent[axis] = side * std::min(size, counts[axis] - lower[axis]);
        Point3d centre = origin + Vector3d(lower[0], lower[1], lower[2]) * side + extent * 0.5;
        DistanceEstimate e = fractal.estimate(centre);
        ++estimates;
        if (ruledOut(e, 0.5 * length(extent) + reach)) return;
        if (size == 1) {
            out.push_back(lower);
            return;
        }
        int half = size / 2;
        for (int k = 0; k < 2; ++k)
            for (int j = 0; j < 2; ++j)
                for (int i = 0; i < 2; ++i) {
                    LatticeIndex child{lower[0] + i * half, lower[1] + j * half,
                                       lower[2] + k * half};
                    if (child[0] < counts[0] && child[1] < counts[1] && child[2] < counts[2])
                        search(child, half, out, estimates);
                }
    }
};

int blocksAlong(int cubes) {
    return (cubes + kTopBlock - 1) / kTopBlock;
}

}  // namespace

std::optional<std::vector<LatticeIndex>> reachableCubes(
    const Fractal& fractal, const Point3d& origin, double side, const LatticeIndex& counts,
    double reach, int threads, const std::atomic<bool>* cancel, int64_t& estimates) {
    CubeSearch search{fractal, origin, side, counts, reach};
    LatticeIndex blocks{blocksAlong(counts[0]), blocksAlong(counts[1]), blocksAlong(counts[2])};
    int64_t blockCount = int64_t(blocks[0]) * blocks[1] * blocks[2];
    std::vector<std::vector<LatticeIndex>> perBlock(static_cast<std::size_t>(blockCount));
    std::vector<int64_t> perThread(std::size_t(resolveThreadCount(threads)), 0);
    ParallelOptions options;
    options.threads = threads;
    options.cancel = cancel;
    bool completed = parallelFor(blockCount, options, [&](int64_t begin, int64_t end, int thread) {
        for (int64_t b = begin; b < end; ++b) {
            LatticeIndex lower{int(b % blocks[0]) * kTopBlock,
                               int(b / blocks[0] % blocks[1]) * kTopBlock,
                               int(b / blocks[0] / blocks[1]) * kTopBlock};
            search.search(lower, kTopBlock, perBlock[std::size_t(b)],
                          perThread[std::size_t(thread)]);
        }
    });
    for (int64_t n : perThread)
        estimates += n;
    if (!completed) return std::nullopt;
    std::vector<LatticeIndex> cubes;
    for (const auto& found : perBlock)
        cubes.insert(cubes.end(), found.begin(), found.end());
    return cubes;
}

namespace {

// The most estimates the box search takes: the sets whose distance bounds rule out little (the
// Lipschitz bounds of coquaternions and biquaternions, issue 41) would otherwise visit all 256^3
// cubes, minutes for a mesh of 10 cells. The presets and algebras take 2 to 260 thousand.
constexpr int64_t kBoxSearchBudget = int64_t(1) << 19;

// The box of the reachable cubes of a lattice, searched as an octree (one worker: it is small)
// that skips any block already inside the box found so far, so the inside of a solid set is
// not visited cube by cube.
struct BoxSearch {
    const Fractal& fractal;
    Point3d origin;
    double side;
    int divisions;
    std::optional<std::array<LatticeIndex, 2>> found;  // lower, upper (exclusive) cube indices
    int64_t estimates = 0;
    bool exhausted = false;  // kBoxSearchBudget ran out

    bool within(const LatticeIndex& lower, int size) const {
        if (!found) return false;
        for (int axis = 0; axis < 3; ++axis)
            if (lower[axis] < (*found)[0][axis] || lower[axis] + size > (*found)[1][axis])
                return false;
        return true;
    }
    void search(const LatticeIndex& lower, int size) {
        if (exhausted || within(lower, size)) return;
        if (estimates >= kBoxSearchBudget) {
            exhausted = true;
            return;
        }
        double h = 0.5 * size;
        Point3d centre = origin + Vector3d(lower[0] + h, lower[1] + h, lower[2] + h) * side;
        DistanceEstimate e = fractal.estimate(centre);
        ++estimates;
        if (ruledOut(e, 0.5 * std::sqrt(3.0) * side * size)) return;
        if (size == 1) {
            if (!found) found = {{lower, lower}};
            for (int axis = 0; axis < 3; ++axis) {
                (*found)[0][axis] = std::min((*found)[0][axis], lower[axis]);
                (*found)[1][axis] = std::max((*found)[1][axis], lower[axis] + 1);
            }
            return;
        }
        int half = size / 2;
        for (int k = 0; k < 2; ++k)
            for (int j = 0; j < 2; ++j)
                for (int i = 0; i < 2; ++i)
                    search({lower[0] + i * half, lower[1] + j * half, lower[2] + k * half}, half);
    }
};

}  // namespace

std::optional<Box> boundingBoxOfSet(const Fractal& fractal, int divisions, int64_t& estimates) {
    double radius = fractal.boundingRadius();
    double side = 2 * radius / divisions;
    BoxSearch search{fractal, Point3d(-radius, -radius, -radius), side, divisions, {}, 0};
    search.search({0, 0, 0}, divisions);
    estimates += search.estimates;
    if (search.exhausted)  // the bounding cube: it holds the set
        return Box{search.origin, search.origin + Vector3d(1, 1, 1) * (side * divisions)};
    if (!search.found) return std::nullopt;
    const auto& [lower, upper] = *search.found;
    return Box{search.origin + Vector3d(lower[0], lower[1], lower[2]) * side,
               search.origin + Vector3d(upper[0], upper[1], upper[2]) * side};
}

MeshGrid gridOverBox(const Box& box, int resolution, int padding) {
    Vector3d size = box.upper - box.lower;
    double longest = std::max({size.x, size.y, size.z});
    MeshGrid grid;
    grid.cellSize = longest / resolution;
    Point3d centre = (box.lower + box.upper) * 0.5;
    Vector3d half;
    for (int axis = 0; axis < 3; ++axis) {
        int cells = std::max(1, int(std::ceil(size[axis] / grid.cellSize - 1e-9)));
        grid.cells[axis] = cells + 2 * padding;
        half[axis] = 0.5 * grid.cellSize * grid.cells[axis];
    }
    // Centred on the box, so that a set symmetric about a plane through the box's centre gets
    // a grid symmetric about it too.
    grid.origin = centre - half;
    return grid;
}

}  // namespace quaternia
