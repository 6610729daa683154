// Shadow rays marched in SIMD lanes (traceShadowRays), compiled once per instruction set by
// Highway's foreach_target and chosen at run time (HWY_DYNAMIC_DISPATCH); march_lanes.h says what
// it computes. The machinery the march lanes share is march_lanes-inl.h.

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "quaternia/render/lanes/shadow_lanes.cpp"
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

// The settings of Shader::shadow for shadow rays, broadcast to lanes.
template <class D>
struct ShadowMarchLanes {
    using V = hn::Vec<D>;
    using T = hn::TFromD<D>;
    V zero, one, minimumStep;
    V blockDistance;  // a ray is blocked where the estimate falls below half the minimum step
    V softness, maxSteps, baseRelaxation, maxRelaxation;
    bool soft;

    ShadowMarchLanes(D d, const ShadowMarch& march)
        : zero(hn::Zero(d)),
          one(hn::Set(d, T(1))),
          minimumStep(hn::Set(d, T(march.minimumStep))),
          blockDistance(hn::Set(d, T(0.5 * march.minimumStep))),
          softness(hn::Set(d, T(march.softness))),
          maxSteps(hn::Set(d, T(march.maxSteps))),
          baseRelaxation(hn::Set(d, T(march.relaxation))),
          maxRelaxation(hn::Set(d, T(march.maxRelaxation))),
          soft(march.soft) {}
};

// What the shadow rays that ended in a step leave in their lanes: their visibility, and a bit
// per lane (lane i at bit i) for the rays that ended.
template <class T>
struct ShadowEndLanes {
    QUATERNIA_LANE_ARRAY(T, visibility);
    uint64_t ended = 0;
};

// Where a shadow ray stands before its step: the last ball's radius, the last step and its
// over-relaxation factor. Over-relaxation as Shader::shadow: where the balls of this point and
// the last do not overlap (gap), the set may lie between them, so the ray goes back to the plain
// step; the lanes without a gap accept this point's estimate.
template <class D>
struct ShadowStepFrom {
    hn::Vec<D> radius, lastStep, relaxation;
    hn::Mask<D> gap, accepted;

    template <class T>
    HWY_INLINE ShadowStepFrom(D d, const ShadowMarchLanes<D>& s, const RayLanes<T>& rayLanes,
                              size_t o, hn::Mask<D> live, hn::Vec<D> distance)
        : radius(hn::Load(d, rayLanes.radius + o)),
          lastStep(hn::Load(d, rayLanes.lastStep + o)),
          relaxation(hn::Load(d, rayLanes.relaxation + o)),
          gap(hn::And(live, hn::And(relaxation > s.one, radius + distance < lastStep))),
          accepted(hn::AndNot(gap, live)) {}
};

// The penumbra: how nearly the ray grazed the set relative to how far it went (the lowest
// softness * distance / t along it), where soft shadows are asked for.
template <class D, class V = hn::Vec<D>>
HWY_INLINE V penumbraLanes(const ShadowMarchLanes<D>& s, hn::Mask<D> accepted, V open, V t,
                           V distance) {
    if (!s.soft) return open;
    return hn::IfThenElse(hn::And(accepted, t > s.zero), hn::Min(open, s.softness * distance / t),
                          open);
}

// Shader::shadowRelaxation in lanes: the factor of the next step, from how fast the balls
// shrink.
template <class D, class V = hn::Vec<D>>
HWY_INLINE V shadowRelaxationLanes(D d, const ShadowMarchLanes<D>& s, const ShadowStepFrom<D>& from,
                                   V newRadius) {
    using T = hn::TFromD<D>;
    const V slope = hn::Max(hn::Set(d, T(-0.8)), (from.radius - newRadius) / from.lastStep);
    return hn::IfThenElse(
        from.lastStep > s.zero,
        hn::Min(s.maxRelaxation, hn::Max(s.one, s.baseRelaxation / (s.one + slope))),
        s.baseRelaxation);
}

// One step of the shadow rays in lanes [o, o + Lanes(d)) from their estimates at t: the march
// state moves on, and the rays that end (blocked, or cleared: past tFar or out of steps) are
// recorded in `ends` with their visibility.
template <class D, class T>
HWY_INLINE void stepShadowLanes(D d, const ShadowMarchLanes<D>& s, RayLanes<T>& rayLanes, size_t o,
                                hn::Mask<D> live, hn::Vec<D> t, const LaneEstimate<D>& e,
                                ShadowEndLanes<T>& ends) {
    using V = hn::Vec<D>;
    const ShadowStepFrom<D> from(d, s, rayLanes, o, live, e.distance);
    const auto gap = from.gap;
    auto blocked = hn::And(from.accepted, hn::Or(e.inside, e.distance < s.blockDistance));
    const V open =
        penumbraLanes(s, from.accepted, hn::Load(d, rayLanes.visibility + o), t, e.distance);
    const V newRadius = hn::Max(e.distance, s.minimumStep);
    const V factor = shadowRelaxationLanes(d, s, from, newRadius);
    const V step = hn::IfThenElse(gap, from.radius, factor * newRadius);
    const V tNext = hn::IfThenElse(gap, t + from.radius - from.lastStep, t + step);
    hn::Store(hn::IfThenElse(gap, from.radius, newRadius), d, rayLanes.radius + o);
    hn::Store(step, d, rayLanes.lastStep + o);
    hn::Store(hn::IfThenElse(gap, s.one, factor), d, rayLanes.relaxation + o);
    const V steps = hn::Load(d, rayLanes.steps + o) + s.one;
    auto cleared = hn::AndNot(blocked, hn::And(live, hn::Or(tNext >= hn::Load(d, rayLanes.tFar + o),
                                                            steps >= s.maxSteps)));
    hn::Store(tNext, d, rayLanes.t + o);
    hn::Store(open, d, rayLanes.visibility + o);
    hn::Store(steps, d, rayLanes.steps + o);
    hn::Store(hn::IfThenZeroElse(blocked, s.soft ? open : s.one), d, ends.visibility + o);
    ends.ended |= laneBits(d, hn::Or(blocked, cleared)) << o;
}

// The visibility of the rays that ended this step (ends), whose lanes take the next rays of the
// batch.
template <class T>
HWY_INLINE void finishShadowRays(ShadowEndLanes<T>& ends, RayLanes<T>& rayLanes,
                                 const RayBatch& rays, size_t& next,
                                 std::vector<double>& visibility) {
    for (; ends.ended != 0; ends.ended &= ends.ended - 1) {
        const size_t lane = size_t(__builtin_ctzll(ends.ended));
        visibility[size_t(rayLanes.ray[lane])] = ends.visibility[lane];
        rayLanes.load(lane, rays, next);
    }
}

// Shader::shadow (shade.cpp) for a batch of shadow rays, marched from their tNear (0 from a
// surface; the ground's start where they enter the sphere that holds their penumbra).
template <bool kQuadratic, class D>
void traceShadowLanes(D d, const LaneFractal& fractal, const ShadowMarch& march,
                      const RayBatch& rays, std::vector<double>& visibility,
                      LaneCounters& counters) {
    using T = hn::TFromD<D>;
    const LaneConstants<D> k(d, fractal);
    const ShadowMarchLanes<D> s(d, march);
    const size_t lanes = hn::Lanes(d);
    visibility.assign(rays.size(), 1.0);
    RayLanes<T> rayLanes;
    ShadowEndLanes<T> ends;
    size_t next = 0;
    for (size_t lane = 0; lane < kLaneGroups * lanes; ++lane)
        rayLanes.load(lane, rays, next);
    // One step of the rays in the first G vectors of lanes, from their estimates (marchBatch).
    auto marchStep = [&](auto groups, const auto& live, const auto& t, const auto& e) {
        constexpr size_t G = decltype(groups)::value;
        for (size_t j = 0; j < G; ++j)
            stepShadowLanes(d, s, rayLanes, j * lanes, live[j], t[j], e[j], ends);
        finishShadowRays(ends, rayLanes, rays, next, visibility);
    };
    marchBatch<kQuadratic>(d, k, rayLanes, rays, next, counters, marchStep);
}

void TraceShadowRays(const LaneFractal& fractal, const ShadowMarch& march, const RayBatch& rays,
                     std::vector<double>& visibility, LaneCounters& counters) {
    run(fractal, [&](auto d, auto quadratic) {
        traceShadowLanes<quadratic()>(d, fractal, march, rays, visibility, counters);
    });
}

}  // namespace HWY_NAMESPACE
}  // namespace quaternia
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace quaternia {

HWY_EXPORT(TraceShadowRays);

void traceShadowRays(const LaneFractal& fractal, const ShadowMarch& march, const RayBatch& rays,
                     std::vector<double>& visibility, LaneCounters& counters) {
    HWY_DYNAMIC_DISPATCH(TraceShadowRays)(fractal, march, rays, visibility, counters);
}

}  // namespace quaternia
#endif  // HWY_ONCE
