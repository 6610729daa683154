#include "quaternia/render/point_queries.h"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "quaternia/algebra/hypercomplex.h"
#include "quaternia/fractal/algebra_rules.h"
#include "quaternia/render/lanes/march_lanes.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

// Points per chunk of the parallel-for: many lane batches each, few enough for a cancel to
// be seen within milliseconds.
constexpr int64_t kChunk = 4096;

// The fractal whose membership the points ask about: the renderer's for 3D points; for points
// of the algebra, the quaternions' own set, or the set in its own algebra (never folded).
Fractal fractalFor(const Scene& scene, bool world) {
    if (world || algebraRules(scene.fractal.algebra).quaternionSet) return fractalFromScene(scene);
    return hypercomplexFractalFromScene(scene);
}

}  // namespace

bool queryPoints(const Scene& scene, const double* points, std::size_t count, int components,
                 uint8_t* inside, double* distance, const WorkOptions& options) {
    validateScene(scene);
    const int dimension = algebraDimension(scene.fractal.algebra);
    if (components != 3 && components != dimension) {
        throw UserError("fractal.algebra",
                        "points of " + std::to_string(components) +
                            " components: fractal.algebra = \"" +
                            std::string(algebraName(scene.fractal.algebra)) + "\" takes " +
                            std::to_string(dimension) +
                            " (points of the algebra) or 3 (points of the 3D slice)");
    }
    const bool world = components == 3;
    const Fractal fractal = fractalFor(scene, world);
    const std::optional<LaneFractal> lanes = LaneFractal::forScene(
        scene, fractal, world ? LaneCoordinates::World : LaneCoordinates::Algebra);
    ParallelOptions parallel;
    parallel.threads = options.threads;
    parallel.cancel = options.cancel;
    parallel.chunkSize = kChunk;
    if (options.progress)
        parallel.progress = [&](int64_t done, int64_t total) {
            options.progress(total > 0 ? double(done) / double(total) : 1.0);
        };
    const std::size_t stride = std::size_t(components);
    return parallelFor(int64_t(count), parallel, [&](int64_t begin, int64_t end, int) {
        if (lanes) {
            PointBatch batch;
            for (int64_t i = begin; i < end; ++i) {
                const double* p = points + std::size_t(i) * stride;
                batch.x.push_back(p[0]), batch.y.push_back(p[1]), batch.z.push_back(p[2]);
                if (!world) batch.w.push_back(p[3]);
            }
            LaneCounters counters;
            std::vector<PointEstimate> estimates;
            estimatePoints(*lanes, batch, estimates, counters);
            for (int64_t i = begin; i < end; ++i) {
                const PointEstimate& e = estimates[std::size_t(i - begin)];
                if (inside) inside[i] = e.inside ? 1 : 0;
                if (distance) distance[i] = e.inside ? 0.0 : e.distance;
            }
            return;
        }
        for (int64_t i = begin; i < end; ++i) {
            const double* p = points + std::size_t(i) * stride;
            DistanceEstimate e;
            if (world) {
                e = fractal.estimate(Point3d(p[0], p[1], p[2]));
            } else {
                Hypercomplex z{};
                std::copy(p, p + stride, z.begin());
                e = fractal.set().estimate(z);
            }
            if (inside) inside[i] = e.inside ? 1 : 0;
            if (distance) distance[i] = e.inside ? 0.0 : e.distance;
        }
    });
}

}  // namespace quaternia
