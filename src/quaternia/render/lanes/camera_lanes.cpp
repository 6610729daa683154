// Camera rays marched in SIMD lanes (traceCameraRays), compiled once per instruction set by
// Highway's foreach_target and chosen at run time (HWY_DYNAMIC_DISPATCH); march_lanes.h says what
// it computes. The machinery the march lanes share is march_lanes-inl.h.

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "quaternia/render/lanes/camera_lanes.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
// clang-format off: the order matters, highway.h after foreach_target.h
#include <hwy/contrib/math/math-inl.h>
#include <hwy/highway.h>
// clang-format on

#include <algorithm>
#include <cmath>
#include <cstring>
#include <type_traits>
#include <utility>

#include "quaternia/algebra/quaternion.h"
#include "quaternia/render/lanes/lane_state.h"
#include "quaternia/render/lanes/march_lanes.h"
#include "quaternia/render/lanes/march_rules.h"

HWY_BEFORE_NAMESPACE();
namespace quaternia {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

#include "quaternia/render/lanes/march_lanes-inl.h"

// The settings of sphereTrace (march.cpp) for camera rays, broadcast to lanes.
template <class D>
struct CameraMarchLanes {
    using V = hn::Vec<D>;
    using T = hn::TFromD<D>;
    V zero, one, epsilon, pixelAngle, maxSteps;
    V confirmBudget, confirmStep;  // kMarchConfirmBudget, kMarchConfirmStep (0 budget: cones)
    V coneShrink;                  // 1 where cones step by the estimate less their radius
    V relaxation;
    hn::Mask<D> relaxing;  // all lanes where steps are over-relaxed, else none
    bool spreads;          // the rays carry a cone's radius at t = 0 (RayBatch::spread)
    bool cone;
    bool closest;  // CameraMarch::closest: the least estimate, in RayLanes::visibility

    CameraMarchLanes(D d, const CameraMarch& march, const RayBatch& rays)
        : zero(hn::Zero(d)),
          one(hn::Set(d, T(1))),
          epsilon(hn::Set(d, T(march.epsilon))),
          pixelAngle(hn::Set(d, T(march.pixelAngle))),
          maxSteps(hn::Set(d, T(march.maxSteps))),
          confirmBudget(hn::Set(d, T(march.cone ? 0 : kMarchConfirmBudget))),
          confirmStep(hn::Set(d, T(kMarchConfirmStep))),
          coneShrink(march.cone ? one : zero),
          relaxation(hn::Set(d, T(march.relaxation))),
          // Cones step plainly (their steps are already short of the estimate).
          relaxing(hn::FirstN(d, march.cone || !(march.relaxation > 1) ? 0 : hn::Lanes(d))),
          spreads(march.cone && !rays.spread.empty()),
          cone(march.cone),
          closest(march.closest) {}
};

// Where a camera ray stands before its step: the point before (tOutside), its estimate
// (radius), its plain step and the step taken from it if that was longer (relaxedStep, else 0).
// Where the plain step and this point's ball leave a gap, the set may lie in it, so this point's
// estimate is dropped and the ray goes back to the plain step (sphereTrace).
template <class D>
struct CameraStepFrom {
    hn::Vec<D> tPrevious, radius, relaxedStep, plainPrevious;
    hn::Mask<D> gap;

    template <class T>
    HWY_INLINE CameraStepFrom(D d, const RayLanes<T>& rayLanes, size_t o, hn::Mask<D> live,
                              hn::Vec<D> distance)
        : tPrevious(hn::Load(d, rayLanes.tOutside + o)),
          radius(hn::Load(d, rayLanes.radius + o)),
          relaxedStep(hn::Load(d, rayLanes.lastStep + o)),
          plainPrevious(hn::Load(d, rayLanes.plainStep + o)),
          gap(hn::And(live, relaxedStep > plainPrevious + distance)) {}
};

// The step of sphereTrace from t: the plain step (the estimate, at least kMarchConfirmStep
// footprints while confirming; a cone's less its radius), or the over-relaxed one where it is
// longer and stays before tFar.
template <class D>
struct CameraStepLength {
    hn::Vec<D> plain, relaxed;
    hn::Mask<D> relax;

    HWY_INLINE CameraStepLength(D d, const CameraMarchLanes<D>& c, const CameraStepFrom<D>& from,
                                hn::Vec<D> t, hn::Vec<D> tFar, hn::Vec<D> distance,
                                hn::Vec<D> footprint, hn::Vec<D> confirming)
        : plain(hn::IfThenElse(confirming > c.zero, hn::Max(distance, c.confirmStep * footprint),
                               hn::NegMulAdd(c.coneShrink, footprint, distance))),
          relaxed(relaxedLength(d, c.relaxation, t, from.tPrevious, from.radius, distance)),
          relax(hn::And(c.relaxing, hn::And(relaxed > plain, relaxed + t <= tFar))) {}
};

// One step of the camera rays in lanes [o, o + Lanes(d)) from their estimates at t: the march
// state moves on, and the rays that end are recorded in `ends` with where they ended.
template <class D, class T>
HWY_INLINE void stepCameraLanes(D d, const CameraMarchLanes<D>& c, RayLanes<T>& rayLanes, size_t o,
                                hn::Mask<D> live, hn::Vec<D> t, const LaneEstimate<D>& e,
                                CameraEndLanes<T>& ends) {
    using V = hn::Vec<D>;
    const V footprint = c.spreads ? hn::MulAdd(c.pixelAngle, t, hn::Load(d, rayLanes.spread + o))
                                  : c.pixelAngle * t;
    const V distance = e.distance;
    const CameraStepFrom<D> from(d, rayLanes, o, live, distance);
    const auto gap = from.gap;
    const V confirmingBefore = hn::Load(d, rayLanes.confirming + o);
    const V confirming = hn::IfThenElse(
        gap, confirmingBefore,
        hn::IfThenElseZero(distance < c.epsilon * footprint, confirmingBefore + c.one));
    const V steps = hn::Load(d, rayLanes.steps + o) + c.one;
    const V tFar = hn::Load(d, rayLanes.tFar + o);
    const CameraStepLength<D> length(d, c, from, t, tFar, distance, footprint, confirming);
    V step = hn::IfThenElse(length.relax, length.relaxed, length.plain);
    step = hn::IfThenElse(gap, from.plainPrevious, step);
    const V tNext = hn::IfThenElse(gap, from.tPrevious, t) + step;

    const auto inside = hn::AndNot(gap, hn::And(live, e.inside));
    const auto grazing =
        hn::AndNot(hn::Or(gap, e.inside), hn::And(live, confirming > c.confirmBudget));
    const auto ended = hn::Or(inside, grazing);
    const auto missed = hn::AndNot(ended, hn::And(live, hn::Or(tNext > tFar, steps >= c.maxSteps)));
    hn::Store(t, d, ends.t + o);
    hn::Store(from.tPrevious, d, ends.tOutside + o);
    hn::Store(steps, d, ends.steps + o);
    ends.ended |= laneBits(d, hn::Or(ended, missed)) << o;
    ends.inside |= laneBits(d, inside) << o;
    ends.grazing |= laneBits(d, grazing) << o;

    hn::Store(tNext, d, rayLanes.t + o);
    hn::Store(hn::IfThenElse(gap, from.tPrevious, t), d, rayLanes.tOutside + o);
    hn::Store(hn::IfThenElse(gap, from.radius, distance), d, rayLanes.radius + o);
    hn::Store(hn::IfThenElse(gap, from.plainPrevious, length.plain), d, rayLanes.plainStep + o);
    hn::Store(hn::IfThenElseZero(hn::AndNot(gap, length.relax), length.relaxed), d,
              rayLanes.lastStep + o);
    hn::Store(confirming, d, rayLanes.confirming + o);
    hn::Store(steps, d, rayLanes.steps + o);
    // The camera rays leave `visibility` alone: it holds the least estimate where asked for.
    if (c.closest) {
        const V closest = hn::Load(d, rayLanes.visibility + o);
        hn::Store(hn::IfThenElse(live, hn::Min(closest, distance), closest), d,
                  rayLanes.visibility + o);
    }
}

// The TraceResults of the rays that ended this step (ends), whose lanes take the next rays of
// the batch.
template <class T>
HWY_INLINE void finishCameraRays(CameraEndLanes<T>& ends, bool cone, RayLanes<T>& rayLanes,
                                 const RayBatch& rays, size_t& next,
                                 std::vector<TraceResult>& results) {
    for (uint64_t left = ends.ended; left != 0; left &= left - 1) {
        const size_t lane = size_t(__builtin_ctzll(left));
        TraceResult& r = results[size_t(rayLanes.ray[lane])];
        r.steps = int(ends.steps[lane]);
        r.t = ends.t[lane];
        r.closest = float(rayLanes.visibility[lane]);
        r.end = ends.endOf(lane);
        if (r.end == TraceEnd::Inside) {
            r.tOutside = ends.tOutside[lane];
        } else if (r.end == TraceEnd::Grazing) {
            // A cone's last point may be inside for some of its rays; the one before is
            // covered by an estimate's ball.
            r.tOutside = cone ? ends.tOutside[lane] : r.t;
        }
        rayLanes.load(lane, rays, next);
    }
    ends.ended = ends.inside = ends.grazing = 0;
}

// sphereTrace (march.cpp) for a batch of camera rays, kLaneGroups vectors of rays at a time.
template <bool kQuadratic, class D>
void traceCameraLanes(D d, const LaneFractal& fractal, const CameraMarch& march,
                      const RayBatch& rays, std::vector<TraceResult>& results,
                      LaneCounters& counters) {
    using T = hn::TFromD<D>;
    static_assert(HWY_MAX_BYTES <= kMaxLaneBytes);
    const LaneConstants<D> k(d, fractal);
    const CameraMarchLanes<D> c(d, march, rays);
    const size_t lanes = hn::Lanes(d);
    results.assign(rays.size(), TraceResult{});
    RayLanes<T> rayLanes;
    CameraEndLanes<T> ends;
    size_t next = 0;
    for (size_t lane = 0; lane < kLaneGroups * lanes; ++lane)
        rayLanes.load(lane, rays, next);
    // One step of the rays in the first G vectors of lanes, from their estimates (marchBatch).
    auto marchStep = [&](auto groups, const auto& live, const auto& t, const auto& e) {
        constexpr size_t G = decltype(groups)::value;
        for (size_t j = 0; j < G; ++j)
            stepCameraLanes(d, c, rayLanes, j * lanes, live[j], t[j], e[j], ends);
        finishCameraRays(ends, c.cone, rayLanes, rays, next, results);
    };
    marchBatch<kQuadratic>(d, k, rayLanes, rays, next, counters, marchStep);
}

void TraceCameraRays(const LaneFractal& fractal, const CameraMarch& march, const RayBatch& rays,
                     std::vector<TraceResult>& results, LaneCounters& counters) {
    run(fractal, [&](auto d, auto quadratic) {
        traceCameraLanes<quadratic()>(d, fractal, march, rays, results, counters);
    });
}

}  // namespace HWY_NAMESPACE
}  // namespace quaternia
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace quaternia {

HWY_EXPORT(TraceCameraRays);

void traceCameraRays(const LaneFractal& fractal, const CameraMarch& march, const RayBatch& rays,
                     std::vector<TraceResult>& results, LaneCounters& counters) {
    HWY_DYNAMIC_DISPATCH(TraceCameraRays)(fractal, march, rays, results, counters);
}

}  // namespace quaternia
#endif  // HWY_ONCE
