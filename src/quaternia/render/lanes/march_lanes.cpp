// The SIMD lanes of march_lanes.h, compiled once per instruction set by Highway's
// foreach_target and chosen at run time (HWY_DYNAMIC_DISPATCH). See the header for what each
// computes; the scalar reference each one mirrors is named beside it.

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "quaternia/render/lanes/march_lanes.cpp"
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

// QuaternionT's ring operations for this target's vectors (quaternion.h says why they are
// included here again).
template <class V>
concept QuaternionComponent = !std::is_arithmetic_v<V>;
#include "quaternia/algebra/quaternion_arithmetic-inl.h"
#include "quaternia/fractal/julia_steps-inl.h"
// After the formulas it uses:
#include "quaternia/render/lanes/estimate_lanes-inl.h"
#include "quaternia/render/lanes/gradient_lanes-inl.h"

// The mask as bits, lane i at bit i (at most 64 lanes: kLaneGroups vectors of 16 floats).
template <class D>
HWY_INLINE uint64_t laneBits(D d, hn::Mask<D> mask) {
    static_assert(kLaneCapacity<float> <= 64);
    uint8_t bytes[8] = {};
    hn::StoreMaskBits(d, mask, bytes);
    uint64_t bits = 0;
    std::memcpy(&bits, bytes, sizeof bits);
    return bits;
}

// relaxedMarchStep (march.h) in lanes, written the same way so that double lanes round alike.
template <class D, class V = hn::Vec<D>>
HWY_INLINE V relaxedLength(D d, V relaxation, V t, V tPrevious, V radius, V distance) {
    const V one = hn::Set(d, hn::TFromD<D>(1));
    const V slope = hn::Max(hn::Zero(d), (radius - distance) / (t - tPrevious));
    const V factor = hn::Max(one, relaxation / (one + slope));
    return hn::IfThenElse(hn::And(t > tPrevious, radius > hn::Zero(d)), factor, one) * distance;
}

// Steps a batch of rays in lanes to its end: step(groups, live, t, e) takes one step of the rays
// in the first `groups` vectors of lanes from their estimates (estimateAlongRays), refilling
// lanes whose rays ended from the batch; the march ends when those vectors hold no ray. All
// kLaneGroups vectors step while the batch has rays to load; once the rays left fit in one
// vector they move into the first, which steps alone: the last rays of a batch would otherwise
// keep both vectors iterating for the few lanes still live.
template <bool kQuadratic, class D, class T, class Step>
HWY_INLINE void marchBatch(D d, const LaneConstants<D>& k, RayLanes<T>& rayLanes,
                           const RayBatch& rays, const size_t& next, LaneCounters& counters,
                           const Step& step) {
    auto stepGroups = [&](auto groups) {
        constexpr size_t G = decltype(groups)::value;
        hn::Mask<D> live[G];
        hn::Vec<D> t[G];
        LaneEstimate<D> e[G];
        if (!estimateAlongRays<kQuadratic>(d, k, rayLanes, live, t, e, counters)) return false;
        step(groups, live, t, e);
        return true;
    };
    const size_t lanes = hn::Lanes(d);
    while (next < rays.size() || !rayLanes.gatherLive(lanes, kLaneGroups * lanes)) {
        if (!stepGroups(std::integral_constant<size_t, kLaneGroups>{})) return;
    }
    while (stepGroups(std::integral_constant<size_t, 1>{})) {
    }
}

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
          cone(march.cone) {}
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

// Fractal::estimate for a batch of points, lanes filled in order (the last chunk padded). With
// kOrbit the whole PointEstimate; without, only the distance (0 inside): store(begin, count,
// out) takes them from out, an EstimateLanes.
template <bool kQuadratic, bool kOrbit, class D, class Store>
void estimatePointLanes(D d, const LaneFractal& fractal, const PointBatch& points,
                        LaneCounters& counters, const Store& store) {
    using T = hn::TFromD<D>;
    const LaneConstants<D> k(d, fractal);
    const size_t lanes = hn::Lanes(d);
    Vector3Lanes<T> in;
    EstimateLanes<T> out;
    for (size_t begin = 0; begin < points.size(); begin += lanes) {
        size_t count = std::min(lanes, points.size() - begin);
        in.gather(points, begin, count);
        const hn::Mask<D> live[1] = {hn::FirstN(d, count)};
        const auto x = hn::Load(d, in.x), y = hn::Load(d, in.y), z = hn::Load(d, in.z);
        LaneEstimate<D> estimates[1];
        if (kQuadratic && k.threeNumbers) {
            const QuaternionT<hn::Vec<D>> u[1] = {k.loopFromWorld(x, y, z)};
            estimateThreeNumbers<kOrbit>(d, k, u, live, estimates, counters);
        } else {
            QuaternionT<hn::Vec<D>> q[1] = {k.quaternionFromWorld(x, y, z)};
            estimateLanes<kQuadratic, kOrbit>(d, k, q, live, estimates, counters);
        }
        const LaneEstimate<D>& e = estimates[0];
        counters.estimates += int64_t(count);
        hn::Store(e.distance, d, out.distance);
        if constexpr (kOrbit) {
            hn::Store(hn::Sqrt(e.trapSquared), d, out.trap);
            hn::Store(e.iterations, d, out.iterations);
            hn::Store(e.radiusSquared, d, out.radiusSquared);
            out.insideLanes = laneBits(d, e.inside);
        }
        store(begin, count, out);
    }
}

template <bool kQuadratic, class D>
void estimatePointLanes(D d, const LaneFractal& fractal, const PointBatch& points,
                        std::vector<PointEstimate>& results, LaneCounters& counters) {
    results.assign(points.size(), PointEstimate{});
    estimatePointLanes<kQuadratic, true>(d, fractal, points, counters,
                                         [&](size_t begin, size_t count, const auto& out) {
                                             for (size_t lane = 0; lane < count; ++lane) {
                                                 PointEstimate& r = results[begin + lane];
                                                 r.distance = out.distance[lane];
                                                 r.trap = out.trap[lane];
                                                 r.iterations = int(out.iterations[lane]);
                                                 r.radiusSquared = out.radiusSquared[lane];
                                                 r.inside = (out.insideLanes >> lane) & 1;
                                             }
                                         });
}

// Fractal::normal / JuliaSet::potentialGradient for a batch of points, M_i iterations in lane i
// (iterations[i]; without `iterations`, the M that each point's estimate reaches, found on the
// way: float lanes of z^2 + c with a certified bailout only, LaneConstants::threeNumbers): the
// gradient of the potential along the slice's axes, then the outward unit normal.
template <bool kQuadratic, class D>
void potentialNormalLanes(D d, const LaneFractal& fractal, const PointBatch& points,
                          const std::vector<int>* iterations, std::vector<Vector3d>& normals,
                          LaneCounters& counters) {
    using V = hn::Vec<D>;
    using T = hn::TFromD<D>;
    const LaneConstants<D> k(d, fractal);
    const size_t lanes = hn::Lanes(d);
    normals.assign(points.size(), Vector3d());
    Vector3Lanes<T> in, gradient;
    QUATERNIA_LANE_ARRAY(T, iterationCounts);  // M per lane
    for (size_t begin = 0; begin < points.size(); begin += lanes) {
        size_t count = std::min(lanes, points.size() - begin);
        in.gather(points, begin, count);
        const V x = hn::Load(d, in.x), y = hn::Load(d, in.y), z = hn::Load(d, in.z);
        V gx, gy, gz;  // the gradient along the slice's axes
        if (!iterations) {
            if constexpr (kQuadratic && sizeof(T) == 4) {
                threeNumberGradientToItsCount(d, k, x, y, z, hn::FirstN(d, count), gx, gy, gz,
                                              counters);
            }
        } else {
            int most = 0;
            for (size_t lane = 0; lane < lanes; ++lane) {
                int m = lane < count ? (*iterations)[begin + lane] : 0;
                iterationCounts[lane] = T(m);
                most = std::max(most, m);
            }
            const V m = hn::Load(d, iterationCounts);
            const int fewest = int(hn::GetLane(hn::MinOfLanes(d, m)));
            if constexpr (kQuadratic && sizeof(T) == 4) {
                threeNumberGradient(d, k, x, y, z, m, fewest, most, gx, gy, gz, counters);
            } else {
                quaternionGradient<kQuadratic>(d, k, x, y, z, m, fewest, most, gx, gy, gz,
                                               counters);
            }
        }
        hn::Store(gx, d, gradient.x);
        hn::Store(gy, d, gradient.y);
        hn::Store(gz, d, gradient.z);
        for (size_t lane = 0; lane < count; ++lane) {
            Vector3d g(gradient.x[lane], gradient.y[lane], gradient.z[lane]);
            Point3d p(points.x[begin + lane], points.y[begin + lane], points.z[begin + lane]);
            normals[begin + lane] = normalOrOutward(g, p);
        }
    }
}

// Calls work(d, quadratic) with the fractal's precision as the lane tag and its form as a
// std::bool_constant: each march and estimate in both precisions and both forms, chosen at run
// time.
template <class Work>
void run(const LaneFractal& fractal, const Work& work) {
    auto withForm = [&](auto d) {
        if (fractal.degree == 2) {
            work(d, std::true_type{});
        } else {
            work(d, std::false_type{});
        }
    };
    if (fractal.precision == Precision::Double) {
        withForm(hn::ScalableTag<double>());
    } else {
        withForm(hn::ScalableTag<float>());
    }
}

void TraceCameraRays(const LaneFractal& fractal, const CameraMarch& march, const RayBatch& rays,
                     std::vector<TraceResult>& results, LaneCounters& counters) {
    run(fractal, [&](auto d, auto quadratic) {
        traceCameraLanes<quadratic()>(d, fractal, march, rays, results, counters);
    });
}
void TraceShadowRays(const LaneFractal& fractal, const ShadowMarch& march, const RayBatch& rays,
                     std::vector<double>& visibility, LaneCounters& counters) {
    run(fractal, [&](auto d, auto quadratic) {
        traceShadowLanes<quadratic()>(d, fractal, march, rays, visibility, counters);
    });
}
void EstimatePoints(const LaneFractal& fractal, const PointBatch& points,
                    std::vector<PointEstimate>& results, LaneCounters& counters) {
    run(fractal, [&](auto d, auto quadratic) {
        estimatePointLanes<quadratic()>(d, fractal, points, results, counters);
    });
}
void EstimateDistances(const LaneFractal& fractal, const PointBatch& points,
                       std::vector<double>& distances, LaneCounters& counters) {
    distances.assign(points.size(), 0.0);
    run(fractal, [&](auto d, auto quadratic) {
        estimatePointLanes<quadratic(), false>(
            d, fractal, points, counters, [&](size_t begin, size_t count, const auto& out) {
                std::copy(out.distance, out.distance + count,
                          distances.begin() + std::ptrdiff_t(begin));
            });
    });
}
void PotentialNormals(const LaneFractal& fractal, const PointBatch& points,
                      const std::vector<int>& iterations, std::vector<Vector3d>& normals,
                      LaneCounters& counters) {
    run(fractal, [&](auto d, auto quadratic) {
        potentialNormalLanes<quadratic()>(d, fractal, points, &iterations, normals, counters);
    });
}
void PotentialNormalsAlone(const LaneFractal& fractal, const PointBatch& points,
                           std::vector<Vector3d>& normals, LaneCounters& counters) {
    run(fractal, [&](auto d, auto quadratic) {
        if constexpr (quadratic() && sizeof(hn::TFromD<decltype(d)>) == 4) {
            if (LaneConstants<decltype(d)>(d, fractal).threeNumbers) {
                potentialNormalLanes<true>(d, fractal, points, nullptr, normals, counters);
                return;
            }
        }
        // Elsewhere the counts come from the estimates.
        std::vector<PointEstimate> estimates;
        estimatePointLanes<quadratic()>(d, fractal, points, estimates, counters);
        std::vector<int> iterations(points.size());
        for (size_t i = 0; i < points.size(); ++i)
            iterations[i] = gradientIterationsOf(estimates[i], fractal.maxIterations);
        potentialNormalLanes<quadratic()>(d, fractal, points, &iterations, normals, counters);
    });
}
const char* TargetName() {
    return hwy::TargetName(HWY_TARGET);
}

}  // namespace HWY_NAMESPACE
}  // namespace quaternia
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace quaternia {

HWY_EXPORT(TraceCameraRays);
HWY_EXPORT(TraceShadowRays);
HWY_EXPORT(EstimatePoints);
HWY_EXPORT(EstimateDistances);
HWY_EXPORT(PotentialNormals);
HWY_EXPORT(PotentialNormalsAlone);
HWY_EXPORT(TargetName);

void traceCameraRays(const LaneFractal& fractal, const CameraMarch& march, const RayBatch& rays,
                     std::vector<TraceResult>& results, LaneCounters& counters) {
    HWY_DYNAMIC_DISPATCH(TraceCameraRays)(fractal, march, rays, results, counters);
}
void traceShadowRays(const LaneFractal& fractal, const ShadowMarch& march, const RayBatch& rays,
                     std::vector<double>& visibility, LaneCounters& counters) {
    HWY_DYNAMIC_DISPATCH(TraceShadowRays)(fractal, march, rays, visibility, counters);
}
void estimatePoints(const LaneFractal& fractal, const PointBatch& points,
                    std::vector<PointEstimate>& results, LaneCounters& counters) {
    HWY_DYNAMIC_DISPATCH(EstimatePoints)(fractal, points, results, counters);
}
void estimateDistances(const LaneFractal& fractal, const PointBatch& points,
                       std::vector<double>& distances, LaneCounters& counters) {
    HWY_DYNAMIC_DISPATCH(EstimateDistances)(fractal, points, distances, counters);
}
void potentialNormals(const LaneFractal& fractal, const PointBatch& points,
                      const std::vector<int>& iterations, std::vector<Vector3d>& normals,
                      LaneCounters& counters) {
    HWY_DYNAMIC_DISPATCH(PotentialNormals)(fractal, points, iterations, normals, counters);
}
void potentialNormalsAlone(const LaneFractal& fractal, const PointBatch& points,
                           std::vector<Vector3d>& normals, LaneCounters& counters) {
    HWY_DYNAMIC_DISPATCH(PotentialNormalsAlone)(fractal, points, normals, counters);
}
const char* laneTargetName() {
    return HWY_DYNAMIC_DISPATCH(TargetName)();
}

}  // namespace quaternia
#endif  // HWY_ONCE
