#include "quaternia/render/camera_rays.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "quaternia/render/march.h"
#include "quaternia/render/sample_pattern.h"

namespace quaternia {

void CameraRays::bind(const Camera& camera, double boundingRadius, const CameraMarch& march,
                      int samples, bool glow) {
    camera_ = &camera;
    boundingRadius_ = boundingRadius;
    march_ = march;
    samples_ = samples;
    glow_ = glow;
    coneRatio_ = coneRatio(camera);
}

double CameraRays::coneRatio(const Camera& camera) {
    // The cone about a block's central ray holds every ray through the block: points at the same
    // t lie within t |d - d_centre| of each other, largest at the block's corners. Through a
    // pinhole, a block subtends the widest angle at the image centre (its angular size falls as
    // cos^2 of the angle off the axis radially, as cos tangentially); the blocks at the centre
    // and the four image corners are measured, and the widest, with a margin, serves all.
    const double width = camera.width(), height = camera.height();
    const double block = kConeBlock;
    double ratio = 0;
    for (auto [cx, cy] :
         {std::pair{0.5 * width, 0.5 * height}, std::pair{0.5 * block, 0.5 * block},
          std::pair{width - 0.5 * block, 0.5 * block}, std::pair{0.5 * block, height - 0.5 * block},
          std::pair{width - 0.5 * block, height - 0.5 * block}}) {
        const Vector3d centre = camera.generateRay(cx, cy).direction;
        for (double dx : {-0.5 * block, 0.5 * block}) {
            for (double dy : {-0.5 * block, 0.5 * block})
                ratio = std::max(ratio,
                                 length(camera.generateRay(cx + dx, cy + dy).direction - centre));
        }
    }
    return ratio * 1.01 + 1e-12;
}

void CameraRays::sampleRays(const Tile& tile, int k, const CameraRayBatch& out) {
    const int width = tile.x1 - tile.x0;
    const int blocksAcross = (width + kConeBlock - 1) / kConeBlock;
    for (int py = tile.y0; py < tile.y1; ++py) {
        const double* blockRow =
            blockStart_.data() + size_t((py - tile.y0) / kConeBlock * blocksAcross);
        // A row whose blocks' cones all missed has no ray to march (but its rays may see the
        // ground).
        if (out.bypass == nullptr &&
            std::all_of(blockRow, blockRow + blocksAcross, [](double start) {
                return start == std::numeric_limits<double>::infinity();
            })) {
            continue;
        }
        if (samples_ == 1 && !camera_->thinLens()) {
            rowRays(tile, py, blockRow, out.bypass != nullptr);
        } else {
            sampleRowRays(tile, py, k);
        }
        pushRowRays(tile, py, blockRow, out);
    }
}

void CameraRays::sampleRowRays(const Tile& tile, int py, int k) {
    rowRays_.resize(size_t(tile.x1 - tile.x0));
    for (int px = tile.x0; px < tile.x1; ++px) {
        auto [sx, sy] = samplePosition(k, samples_, px, py);
        const Ray ray = camera_->generateRay(px + sx, py + sy, lensSample(k, px, py));
        RowRay& r = rowRays_[size_t(px - tile.x0)];
        r.origin = ray.origin;
        r.direction = ray.direction;
        auto interval = intersectSphere(ray, boundingRadius_);
        r.tNear = interval ? interval->tNear : 1;
        r.tFar = interval ? interval->tFar : -1;  // none: tNear > tFar
    }
}

void CameraRays::pushRowRays(const Tile& tile, int py, const double* blockStart,
                             const CameraRayBatch& out) {
    const int width = tile.x1 - tile.x0;
    const int rowBlock = (py - tile.y0) / kConeBlock * ((width + kConeBlock - 1) / kConeBlock);
    for (int px = tile.x0; px < tile.x1; ++px) {
        const int column = (px - tile.x0) / kConeBlock;
        const double start = blockStart[column];
        const RowRay& r = rowRays_[size_t(px - tile.x0)];
        const double near = std::max(r.tNear, start);
        // Not r.tNear <= r.tFar: the sphere or the cone missed, or the cone found nothing on it.
        if (!(near <= r.tFar)) {
            if (out.bypass)
                out.bypass->push_back(
                    {Ray{r.origin, r.direction}, (py - tile.y0) * width + (px - tile.x0)});
            continue;
        }
        out.rays.push(Ray{r.origin, r.direction}, near, r.tFar);
        out.pixel.push_back((py - tile.y0) * width + (px - tile.x0));
        out.block.push_back(rowBlock + column);
    }
}

void CameraRays::rowRays(const Tile& tile, int py, const double* blockStart, bool bypassing) {
    // The rays through the pixel centres of the row, as generateRay and intersectSphere give
    // them (the same formulas in the same order), for the pixels of the blocks whose cones did
    // not miss: each run of such blocks in one loop without branches (the square roots and
    // divisions of neighbouring pixels overlap in the pipeline; GCC keeps them scalar, and the
    // branches between them were what cost).
    const int width = tile.x1 - tile.x0;
    const int blocks = (width + kConeBlock - 1) / kConeBlock;
    rowRays_.resize(size_t(width));
    const Camera::RowDirections row = camera_->rowDirections(py);
    const Point3d& o = camera_->position();
    const double c = dot(o, o) - boundingRadius_ * boundingRadius_;
    RowRay* out = rowRays_.data();
    constexpr double kMissed = std::numeric_limits<double>::infinity();
    for (int block = 0; block < blocks;) {
        if (blockStart[block] == kMissed) {
            // Where rays that skip the set still count (bypassing), their directions alone.
            if (bypassing) {
                const int end = std::min(width, (block + 1) * kConeBlock);
                for (int i = block * kConeBlock; i < end; ++i) {
                    out[i].origin = o;
                    out[i].direction = normalize(row.first + row.step * double(tile.x0 + i));
                    out[i].tNear = kMissed;
                    out[i].tFar = -1;
                }
            }
            ++block;
            continue;
        }
        const int first = block * kConeBlock;
        while (block < blocks && blockStart[block] != kMissed)
            ++block;
        const int end = std::min(width, block * kConeBlock);
        for (int i = first; i < end; ++i) {
            const Vector3d d = normalize(row.first + row.step * double(tile.x0 + i));
            const double b = dot(o, d);
            const double discriminant = b * b - c;
            const double root = std::sqrt(std::max(0.0, discriminant));
            const double tFar = -b + root;
            out[i].origin = o;
            out[i].direction = d;
            out[i].tNear = std::max(0.0, -b - root);
            // A miss (no real root, or the sphere behind the camera) as an empty interval.
            out[i].tFar = discriminant < 0 || tFar < 0 ? -1.0 : tFar;
        }
    }
}

void CameraRays::marchCones(const LaneFractal& lanes, const Tile& tile, int64_t& marchSteps,
                            LaneCounters& counters) {
    const int width = tile.x1 - tile.x0, height = tile.y1 - tile.y0;
    const int across = (width + kConeBlock - 1) / kConeBlock;
    const int down = (height + kConeBlock - 1) / kConeBlock;
    blockStart_.assign(size_t(across * down), 0.0);
    // A thin lens's rays leave from all over the lens: no cone from the pinhole holds them, so
    // each starts where it enters the bounding sphere.
    if (camera_->thinLens()) return;
    cones_.clear();
    coneBlock_.clear();
    std::vector<Ray>& centres = coneCentres_;
    centres.clear();
    for (int by = 0; by < down; ++by) {
        for (int bx = 0; bx < across; ++bx) {
            const double x0 = tile.x0 + bx * kConeBlock, y0 = tile.y0 + by * kConeBlock;
            const double x1 = std::min<double>(x0 + kConeBlock, tile.x1);
            const double y1 = std::min<double>(y0 + kConeBlock, tile.y1);
            centres.push_back(camera_->generateRay(0.5 * (x0 + x1), 0.5 * (y0 + y1)));
        }
    }
    const double ratio = coneRatio_;
    // Every ray of the block is inside the bounding sphere only where the central ray is inside
    // the sphere grown by the cone's widest radius there.
    const double farthest = length(centres.front().origin) + boundingRadius_;
    for (size_t b = 0; b < centres.size(); ++b) {
        auto interval = intersectSphere(centres[b], boundingRadius_ + ratio * farthest);
        if (!interval) {
            blockStart_[b] = std::numeric_limits<double>::infinity();
            continue;
        }
        cones_.push(centres[b], interval->tNear, interval->tFar);
        coneBlock_.push_back(int(b));
    }
    CameraMarch coneMarch = march_;
    coneMarch.cone = true;
    // Cones stop at 1.2 radii: at 1.5, case01 took 2.7% and the default scene 3.5% more march
    // steps in all (2 took 9% more steps of the pixel rays than 1.5); below 1.2 little changes.
    coneMarch.epsilon = 1.2;
    coneMarch.pixelAngle = ratio;
    traceCameraRays(lanes, coneMarch, cones_, coneResults_, counters);
    for (size_t i = 0; i < coneResults_.size(); ++i) {
        const TraceResult& r = coneResults_[i];
        marchSteps += r.steps;
        double& start = blockStart_[size_t(coneBlock_[i])];
        if (r.end == TraceEnd::Miss && r.steps < march_.maxSteps) {
            // With a glow, the rays near the set that it missed are marched all the same: their
            // least estimates are the glow's.
            start = glow_ ? 0.0 : std::numeric_limits<double>::infinity();
        } else {
            // Start the block's rays at the cone's last point whose ball was clear: the set is
            // not on them before it, and the point itself is outside, where normals are taken.
            start = r.tOutside;
        }
    }
}

void CameraRays::pushQueued(const Tile& blocks, const CameraRayBatch& out) {
    // In three loops: the sample positions (a hash each), the rays and where they cross the
    // bounding sphere (a chain of a division and two square roots per ray, which in a loop
    // without calls or stores to growing vectors overlaps from ray to ray), then the batch.
    const size_t count = queued_.size();
    for (QueuedSample& q : queued_) {
        auto [sx, sy] = samplePosition(q.k, samples_, q.px, q.py);
        q.x = q.px + sx, q.y = q.py + sy;
    }
    queuedRays_.resize(count);
    queuedNear_.resize(count);
    queuedFar_.resize(count);
    for (size_t i = 0; i < count; ++i) {
        const QueuedSample& q = queued_[i];
        const Ray ray = camera_->thinLens()
                            ? camera_->generateRay(q.x, q.y, lensSample(q.k, q.px, q.py))
                            : camera_->generateRay(q.x, q.y);
        auto interval = intersectSphere(ray, boundingRadius_);
        queuedRays_[i] = ray;
        queuedNear_[i] = interval ? interval->tNear : 1;
        queuedFar_[i] = interval ? interval->tFar : -1;  // none: tNear > tFar
    }
    const int blocksAcross = (blocks.x1 - blocks.x0 + kConeBlock - 1) / kConeBlock;
    for (size_t i = 0; i < count; ++i) {
        const QueuedSample& q = queued_[i];
        const int block =
            (q.py - blocks.y0) / kConeBlock * blocksAcross + (q.px - blocks.x0) / kConeBlock;
        const double near = std::max(queuedNear_[i], blockStart_[size_t(block)]);
        // The cone or the bounding sphere missed: the ray skips the set.
        if (!(near <= queuedFar_[i])) {
            if (out.bypass) out.bypass->push_back({queuedRays_[i], q.target});
            continue;
        }
        out.rays.push(queuedRays_[i], near, queuedFar_[i]);
        out.pixel.push_back(q.target);
        out.block.push_back(block);
    }
    queued_.clear();
}

}  // namespace quaternia
