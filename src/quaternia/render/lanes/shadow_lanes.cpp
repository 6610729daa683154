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

// Shader::shadow (shade.cpp) for a batch of shadow rays, marched from t = 0.
template <bool kQuadratic, class D>
void traceShadowLanes(D d, const LaneFractal& fractal, const ShadowMarch& march,
                      const RayBatch& rays, std::vector<double>& visibility,
                      LaneCounters& counters) {
    using V = hn::Vec<D>;
    using T = hn::TFromD<D>;
    constexpr size_t K = kLaneGroups;
    const LaneConstants<D> k(d, fractal);
    const size_t lanes = hn::Lanes(d);
    visibility.assign(rays.size(), 1.0);
    RayLanes<T> rayLanes;
    QUATERNIA_LANE_ARRAY(T, endVisibility);  // of the rays that ended this step
    size_t next = 0;
    for (size_t lane = 0; lane < K * lanes; ++lane)
        rayLanes.load(lane, rays, next, /*startAtZero=*/true);

    const V zero = hn::Zero(d), one = hn::Set(d, T(1));
    const V minimumStep = hn::Set(d, T(march.minimumStep));
    const V blockDistance = hn::Set(d, T(0.5 * march.minimumStep));
    const V softness = hn::Set(d, T(march.softness));
    const V maxSteps = hn::Set(d, T(march.maxSteps));
    const V baseRelaxation = hn::Set(d, T(march.relaxation));
    const V maxRelaxation = hn::Set(d, T(march.maxRelaxation));
    // One step of the rays in the first G vectors of lanes, from their estimates (marchBatch).
    auto marchStep = [&](auto groups, const auto& live, const auto& t, const auto& e) {
        constexpr size_t G = decltype(groups)::value;

        uint64_t doneLanes = 0;
        for (size_t j = 0; j < G; ++j) {
            const size_t o = j * lanes;
            // Over-relaxation as Shader::shadow: where the balls of this point and the last do
            // not overlap, go back to the plain step.
            const V radius = hn::Load(d, rayLanes.radius + o),
                    lastStep = hn::Load(d, rayLanes.lastStep + o);
            const V relaxation = hn::Load(d, rayLanes.relaxation + o);
            const auto gap =
                hn::And(live[j], hn::And(relaxation > one, radius + e[j].distance < lastStep));
            const auto accepted = hn::AndNot(gap, live[j]);
            auto blocked = hn::And(accepted, hn::Or(e[j].inside, e[j].distance < blockDistance));
            // The penumbra: how nearly the ray grazed the set relative to how far it went.
            V open = hn::Load(d, rayLanes.visibility + o);
            if (march.soft) {
                open = hn::IfThenElse(hn::And(accepted, t[j] > zero),
                                      hn::Min(open, softness * e[j].distance / t[j]), open);
            }
            const V newRadius = hn::Max(e[j].distance, minimumStep);
            // Shader::shadowRelaxation in lanes.
            const V slope = hn::Max(hn::Set(d, T(-0.8)), (radius - newRadius) / lastStep);
            const V factor =
                hn::IfThenElse(lastStep > zero,
                               hn::Min(maxRelaxation, hn::Max(one, baseRelaxation / (one + slope))),
                               baseRelaxation);
            const V step = hn::IfThenElse(gap, radius, factor * newRadius);
            const V tNext = hn::IfThenElse(gap, t[j] + radius - lastStep, t[j] + step);
            hn::Store(hn::IfThenElse(gap, radius, newRadius), d, rayLanes.radius + o);
            hn::Store(step, d, rayLanes.lastStep + o);
            hn::Store(hn::IfThenElse(gap, one, factor), d, rayLanes.relaxation + o);
            const V steps = hn::Load(d, rayLanes.steps + o) + one;
            auto cleared =
                hn::AndNot(blocked, hn::And(live[j], hn::Or(tNext >= hn::Load(d, rayLanes.tFar + o),
                                                            steps >= maxSteps)));
            auto done = hn::Or(blocked, cleared);
            hn::Store(tNext, d, rayLanes.t + o);
            hn::Store(open, d, rayLanes.visibility + o);
            hn::Store(steps, d, rayLanes.steps + o);
            hn::Store(hn::IfThenZeroElse(blocked, march.soft ? open : one), d, endVisibility + o);
            doneLanes |= laneBits(d, done) << o;
        }
        for (; doneLanes != 0; doneLanes &= doneLanes - 1) {
            const size_t lane = size_t(__builtin_ctzll(doneLanes));
            visibility[size_t(rayLanes.ray[lane])] = endVisibility[lane];
            rayLanes.load(lane, rays, next, /*startAtZero=*/true);
        }
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
