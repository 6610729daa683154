#include "quaternia/render/shadow_rays.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace quaternia {

void ShadowRays::march(const LaneFractal& lanes, const ShadowMarch& march, LaneCounters& counters) {
    traceShadowRays(lanes, march, rays_, visibility_, counters);
}

void ShadowRays::marchClippedHardShadows(const LaneFractal& lanes, const CameraMarch& cameraMarch,
                                         const ShadowMarch& march, const Vector3d& toLight,
                                         double boundingRadius, int blocks,
                                         const std::function<int(int owner)>& blockOf,
                                         LaneCounters& counters) {
    clipHardShadows(lanes, cameraMarch, toLight, boundingRadius, blocks, blockOf, counters);
    traceShadowRays(lanes, march, rays_, visibility_, counters);
    // The rays that the cylinders cleared whole were left out of the march.
    if (!cleared_.empty()) {
        marchedVisibility_.swap(visibility_);
        visibility_.assign(owners_.size(), 1.0);
        for (size_t r = 0, marched = 0; r < owners_.size(); ++r) {
            if (!cleared_[r]) visibility_[r] = marchedVisibility_[marched++];
        }
    }
}

void ShadowRays::clipHardShadows(const LaneFractal& lanes, const CameraMarch& cameraMarch,
                                 const Vector3d& toLight, double boundingRadius, int blocks,
                                 const std::function<int(int owner)>& blockOf,
                                 LaneCounters& counters) {
    // Hard shadow rays of one block of pixels are parallel (the key light is a direction) and
    // start within a few footprints of each other. A cylinder about them that holds all their
    // origins, marched as a cone of constant radius from the far side of the bounding sphere
    // towards them (step: the estimate less the radius), proves the set absent from the part
    // of every ray beyond where it stopped (as the cones of the camera rays do), so each ray is
    // marched only from its origin to there; a cylinder that gets past every origin clears its
    // rays whole. It stops where the set comes within 1.2 radii: at an occluder, whose rays
    // then meet it on their own, or at the surface the rays start from.
    cleared_.clear();
    if (owners_.empty()) return;
    orderByBlock(blocks, blockOf);
    cylinders_.clear();
    cylinderRays_.clear();
    for (size_t block = 0; block < size_t(blocks); ++block) {
        const size_t first = size_t(blockStarts_[block]), end = size_t(blockStarts_[block + 1]);
        if (end - first >= kMinCylinderRays) pushCylinder(first, end, toLight, boundingRadius);
    }
    if (cylinders_.size() == 0) return;
    CameraMarch cylinderMarch = cameraMarch;
    cylinderMarch.cone = true;
    cylinderMarch.epsilon = 1.2;
    cylinderMarch.pixelAngle = 0;
    traceCameraRays(lanes, cylinderMarch, cylinders_, cylinderResults_, counters);
    // The batch to march: the rays not cleared whole, in their order. (A cylinder stops at the
    // surface its rays start from, so most frames clear none: then the batch stays as it is.)
    if (shortenToCylinders(toLight, cameraMarch.maxSteps) == 0) {
        cleared_.clear();
        return;
    }
    rays_.removeFlagged(cleared_);
}

void ShadowRays::orderByBlock(int blocks, const std::function<int(int owner)>& blockOf) {
    // A counting sort: hits come in rows, so the rays of each block stay in order.
    const size_t count = owners_.size();
    block_.resize(count);
    for (size_t r = 0; r < count; ++r)
        block_[r] = blockOf(owners_[r]);
    blockStarts_.assign(size_t(blocks) + 1, 0);
    for (size_t r = 0; r < count; ++r)
        ++blockStarts_[size_t(block_[r]) + 1];
    for (size_t b = 0; b < size_t(blocks); ++b)
        blockStarts_[b + 1] += blockStarts_[b];
    order_.resize(count);
    blockFill_.assign(blockStarts_.begin(), blockStarts_.end() - 1);
    for (size_t r = 0; r < count; ++r)
        order_[size_t(blockFill_[size_t(block_[r])]++)] = int(r);
}

ShadowRays::RayBundle ShadowRays::bundleOf(size_t first, size_t end, const Vector3d& direction,
                                           double boundingRadius) const {
    Vector3d sum;
    for (size_t k = first; k < end; ++k)
        sum += Vector3d(origin(size_t(order_[k])));
    RayBundle bundle;
    bundle.centre = Point3d(sum / double(end - first));
    // The widest offset of an origin from the axis, and the axial extent from the nearest
    // origin to the farthest end of a ray.
    double widest = 0;
    bundle.nearest = std::numeric_limits<double>::infinity();
    bundle.farthest = -bundle.nearest;
    for (size_t k = first; k < end; ++k) {
        const size_t r = size_t(order_[k]);
        const Vector3d offset = origin(r) - bundle.centre;
        const double along = dot(offset, direction);
        widest = std::max(widest, dot(offset, offset) - along * along);
        bundle.nearest = std::min(bundle.nearest, along);
        bundle.farthest = std::max(bundle.farthest, along + rays_.tFar[r]);
    }
    // A margin for rounding, and never a zero radius.
    bundle.radius = std::sqrt(std::max(0.0, widest)) * (1 + 1e-6) + 1e-9 * boundingRadius;
    return bundle;
}

void ShadowRays::pushCylinder(size_t first, size_t end, const Vector3d& toLight,
                              double boundingRadius) {
    const RayBundle b = bundleOf(first, end, toLight, boundingRadius);
    cylinders_.push(Ray{b.centre + toLight * b.farthest, -toLight}, 0, b.farthest - b.nearest);
    cylinders_.spread.push_back(b.radius);
    cylinderRays_.push_back({first, end});
}

size_t ShadowRays::shortenToCylinders(const Vector3d& toLight, int maxSteps) {
    // A cylinder is clear from its far end to tOutside (to its end where it missed); on a ray,
    // that is from (far end - origin) . light - tOutside on.
    cleared_.assign(owners_.size(), 0);
    size_t cleared = 0;
    for (size_t c = 0; c < cylinders_.size(); ++c) {
        const TraceResult& result = cylinderResults_[c];
        const bool whole = result.end == TraceEnd::Miss && result.steps < maxSteps;
        const Point3d farEnd(cylinders_.ox[c], cylinders_.oy[c], cylinders_.oz[c]);
        for (size_t k = cylinderRays_[c].first; k < cylinderRays_[c].second; ++k) {
            const size_t r = size_t(order_[k]);
            const double clearFrom = dot(farEnd - origin(r), toLight) - result.tOutside;
            if (whole || clearFrom <= 0) {
                cleared_[r] = 1;
                ++cleared;
            } else {
                rays_.tFar[r] = std::min(rays_.tFar[r], clearFrom);
            }
        }
    }
    return cleared;
}

void ShadowRays::clearLitByCones(const LaneFractal& lanes, const CameraMarch& cameraMarch,
                                 const LightSource& light, double boundingRadius,
                                 const std::function<int(int owner)>& blockOf,
                                 LaneCounters& counters) {
    // The shadow rays of a directional light from the ground points of one block of 4x4 camera
    // pixels are parallel and start close together. A cone about them, from the nearest origin
    // along the light, of radius r + s / k at s along it (r holding every origin off its axis,
    // k the penumbra's sharpness; 0 for hard shadows), marched as the camera's cones are (steps
    // of the estimate less the radius, ending where the estimate falls below 1.2 radii), proves
    // where it gets through that every ray of the block passes at h >= t / k from the set at
    // every t along it: min k h / t >= 1, fully lit, and no ray of it need be marched.
    // (Most of the ground sees the light past the set's bounding sphere but far from the set.)
    if (light.kind != LightKind::Directional || owners_.size() < kMinCylinderRays) return;
    const size_t count = owners_.size();
    block_.resize(count);
    for (size_t r = 0; r < count; ++r)
        block_[r] = blockOf(owners_[r]);
    order_.resize(count);
    for (size_t r = 0; r < count; ++r)
        order_[r] = int(r);
    std::stable_sort(order_.begin(), order_.end(),
                     [&](int a, int b) { return block_[size_t(a)] < block_[size_t(b)]; });
    const Vector3d& l = light.direction;
    cylinders_.clear();
    cylinderRays_.clear();
    for (size_t first = 0; first < count;) {
        size_t end = first + 1;
        while (end < count && block_[size_t(order_[end])] == block_[size_t(order_[first])])
            ++end;
        if (block_[size_t(order_[first])] >= 0 && end - first >= kMinCylinderRays) {
            const RayBundle bundle = bundleOf(first, end, l, boundingRadius);
            cylinders_.push(Ray{bundle.centre + l * bundle.nearest, l}, 0,
                            bundle.farthest - bundle.nearest);
            cylinders_.spread.push_back(bundle.radius);
            cylinderRays_.push_back({first, end});
        }
        first = end;
    }
    if (cylinders_.size() == 0) return;
    CameraMarch coneMarch = cameraMarch;
    coneMarch.cone = true;
    coneMarch.epsilon = 1.2;
    coneMarch.pixelAngle = light.shadows == Shadows::Soft ? 1 / light.softness : 0.0;
    traceCameraRays(lanes, coneMarch, cylinders_, cylinderResults_, counters);
    cleared_.assign(count, 0);
    size_t cleared = 0;
    for (size_t c = 0; c < cylinders_.size(); ++c) {
        const TraceResult& result = cylinderResults_[c];
        const bool whole = result.end == TraceEnd::Miss && result.steps < cameraMarch.maxSteps;
        // The cone's start and where it was last clear: before that, every ray of it is lit
        // (k h / t >= 1 there), so its own march starts there.
        const Point3d start(cylinders_.ox[c], cylinders_.oy[c], cylinders_.oz[c]);
        for (size_t i = cylinderRays_[c].first; i < cylinderRays_[c].second; ++i) {
            const size_t r = size_t(order_[i]);
            const double clearTo = result.tOutside - dot(origin(r) - start, l);
            if (whole || clearTo >= rays_.tFar[r]) {
                cleared_[r] = 1;
                ++cleared;
            } else {
                rays_.tNear[r] = std::max(rays_.tNear[r], clearTo);
            }
        }
    }
    if (cleared == 0) return;
    rays_.removeFlagged(cleared_);
    size_t kept = 0;
    for (size_t r = 0; r < count; ++r)
        if (!cleared_[r]) owners_[kept++] = owners_[r];
    owners_.resize(kept);
}

}  // namespace quaternia
