// Per-lane bookkeeping of the SIMD lanes (march_lanes-inl.h): aligned arrays that hold one
// value per lane, loaded into and stored from vectors each step, and the scalar refill of a lane
// whose ray has finished. Plain C++ (no SIMD), shared by every instruction-set target.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <new>
#include <vector>

#include "quaternia/render/lanes/march_lanes.h"
#include "quaternia/util/lane_width.h"

namespace quaternia {

// Rays are marched kLaneGroups vectors at a time, so that independent iterations overlap. Three
// rather than two: case01 (bench/compare) 4% faster on AVX2 and 7% on AVX-512 in interleaved
// pairs, the default scene and the compiled programs unchanged within the noise; four no faster.
inline constexpr size_t kLaneGroups = 3;
template <class T>
inline constexpr size_t kLaneCapacity = kLaneGroups* kMaxLaneBytes / sizeof(T);
// One value per lane, aligned for vector loads and stores.
#define QUATERNIA_LANE_ARRAY(T, name) alignas(kMaxLaneBytes) T name[kLaneCapacity<T>] = {}

// Memory for lane vectors, aligned to the widest vector: std::allocator's own alignment did not
// reach the 64 bytes of AVX-512 vectors here (a misaligned store faulted).
template <class T>
struct LaneAllocator {
    using value_type = T;
    LaneAllocator() = default;
    template <class U>
    LaneAllocator(const LaneAllocator<U>&) {}  // NOLINT: rebinding
    T* allocate(size_t n) {
        return static_cast<T*>(::operator new(n * sizeof(T), std::align_val_t(kMaxLaneBytes)));
    }
    void deallocate(T* p, size_t) { ::operator delete(p, std::align_val_t(kMaxLaneBytes)); }
    bool operator==(const LaneAllocator&) const { return true; }
};
template <class T>
using LaneVector = std::vector<T, LaneAllocator<T>>;

// The rays in the lanes: ray (index into the batch, -1 for an empty lane) and march state.
template <class T>
struct RayLanes {
    QUATERNIA_LANE_ARRAY(T, ox);
    QUATERNIA_LANE_ARRAY(T, oy);
    QUATERNIA_LANE_ARRAY(T, oz);
    QUATERNIA_LANE_ARRAY(T, dx);
    QUATERNIA_LANE_ARRAY(T, dy);
    QUATERNIA_LANE_ARRAY(T, dz);
    QUATERNIA_LANE_ARRAY(T, t);
    QUATERNIA_LANE_ARRAY(T, tFar);
    QUATERNIA_LANE_ARRAY(T, tOutside);
    QUATERNIA_LANE_ARRAY(T, confirming);  // camera rays: confirmation steps taken (sphereTrace)
    QUATERNIA_LANE_ARRAY(T, visibility);  // shadow rays: the running visibility (Shader::shadow)
    QUATERNIA_LANE_ARRAY(T, steps);
    QUATERNIA_LANE_ARRAY(T, live);
    // Over-relaxed marching: the last ball's radius and the last step (camera rays: the relaxed
    // step, 0 where it was plain), the factor of the last step (shadow rays), the plain step
    // (camera rays).
    QUATERNIA_LANE_ARRAY(T, radius);
    QUATERNIA_LANE_ARRAY(T, lastStep);
    QUATERNIA_LANE_ARRAY(T, relaxation);
    QUATERNIA_LANE_ARRAY(T, plainStep);
    QUATERNIA_LANE_ARRAY(T, spread);  // a cone's radius at t = 0 (RayBatch::spread)
    int64_t ray[kLaneCapacity<T>] = {};

    // Moves the ray and march state of lane `from` into lane `to`, and empties `from`.
    void moveLane(size_t from, size_t to) {
        for (T* field : {ox, oy, oz, dx, dy, dz, t, tFar, tOutside, confirming, visibility, steps,
                         live, radius, lastStep, relaxation, plainStep, spread})
            field[to] = field[from];
        ray[to] = ray[from];
        ray[from] = -1;
        live[from] = T(0);
    }

    // Moves the rays of lanes [first, used) into empty lanes below `first` when they all fit
    // there; false (and nothing moved) when they do not.
    bool gatherLive(size_t first, size_t used) {
        size_t liveLanes = 0;
        for (size_t lane = 0; lane < used; ++lane)
            liveLanes += live[lane] > T(0);
        if (liveLanes > first) return false;
        size_t free = 0;
        for (size_t lane = first; lane < used; ++lane) {
            if (!(live[lane] > T(0))) continue;
            while (live[free] > T(0))
                ++free;
            moveLane(lane, free);
        }
        return true;
    }

    // Puts ray `next` of the batch into `lane` (and advances next), or empties the lane when the
    // batch is exhausted. Camera rays start at tNear; shadow rays at 0 with visibility 1.
    void load(size_t lane, const RayBatch& rays, size_t& next) {
        if (next >= rays.size()) {
            ray[lane] = -1;
            live[lane] = T(0);
            return;
        }
        size_t i = next++;
        ray[lane] = int64_t(i);
        live[lane] = T(1);
        ox[lane] = T(rays.ox[i]), oy[lane] = T(rays.oy[i]), oz[lane] = T(rays.oz[i]);
        dx[lane] = T(rays.dx[i]), dy[lane] = T(rays.dy[i]), dz[lane] = T(rays.dz[i]);
        t[lane] = T(rays.tNear[i]);
        tOutside[lane] = t[lane];
        tFar[lane] = T(rays.tFar[i]);
        confirming[lane] = T(0);
        visibility[lane] = T(1);
        steps[lane] = T(0);
        radius[lane] = lastStep[lane] = plainStep[lane] = T(0);
        spread[lane] = rays.spread.empty() ? T(0) : T(rays.spread[i]);
        relaxation[lane] = T(1);  // a shadow ray's first step: no step behind it to check
    }
};

// Points on their way into the lanes, or the gradients at them on their way out.
template <class T>
struct Vector3Lanes {
    QUATERNIA_LANE_ARRAY(T, x);
    QUATERNIA_LANE_ARRAY(T, y);
    QUATERNIA_LANE_ARRAY(T, z);
    QUATERNIA_LANE_ARRAY(T, w);  // PointBatch::w, where the points have it

    // Points [begin, begin + count); the lanes past count repeat the last point so that every
    // lane computes something finite.
    void gather(const PointBatch& points, size_t begin, size_t count) {
        const bool fourth = !points.w.empty();
        for (size_t lane = 0; lane < kLaneCapacity<T>; ++lane) {
            size_t i = begin + std::min(lane, count - 1);
            x[lane] = T(points.x[i]), y[lane] = T(points.y[i]), z[lane] = T(points.z[i]);
            if (fourth) w[lane] = T(points.w[i]);
        }
    }
};

// The estimates at points on their way out of the lanes (PointEstimate); the trap, the
// iteration counts, the radii and insideLanes are filled only where the orbit is asked for.
template <class T>
struct EstimateLanes {
    QUATERNIA_LANE_ARRAY(T, distance);
    QUATERNIA_LANE_ARRAY(T, trap);
    QUATERNIA_LANE_ARRAY(T, iterations);
    QUATERNIA_LANE_ARRAY(T, radiusSquared);
    uint64_t insideLanes = 0;  // bit per lane of the points inside
};

// What the camera rays that ended in a step leave in their lanes, for their TraceResult.
template <class T>
struct CameraEndLanes {
    QUATERNIA_LANE_ARRAY(T, t);
    QUATERNIA_LANE_ARRAY(T, tOutside);
    QUATERNIA_LANE_ARRAY(T, steps);
    // A bit per lane, lane i at bit i: the rays that ended this step, and which of them ended
    // inside or grazing (the others missed).
    uint64_t ended = 0, inside = 0, grazing = 0;

    TraceEnd endOf(size_t lane) const {
        const uint64_t bit = uint64_t(1) << lane;
        return inside & bit ? TraceEnd::Inside : grazing & bit ? TraceEnd::Grazing : TraceEnd::Miss;
    }
};

}  // namespace quaternia
