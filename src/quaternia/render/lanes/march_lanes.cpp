// SIMD kernels of packet_kernels.h, compiled once per instruction set by Highway's
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
HWY_INLINE void marchBatch(D d, const LaneConstants<D>& k, RayLanes<T>& s, const RayBatch& rays,
                           const size_t& next, LaneCounters& counters, const Step& step) {
    auto stepGroups = [&](auto groups) {
        constexpr size_t G = decltype(groups)::value;
        hn::Mask<D> live[G];
        hn::Vec<D> t[G];
        LaneEstimate<D> e[G];
        if (!estimateAlongRays<kQuadratic>(d, k, s, live, t, e, counters)) return false;
        step(groups, live, t, e);
        return true;
    };
    const size_t lanes = hn::Lanes(d);
    while (next < rays.size() || !s.gatherLive(lanes, kLaneGroups * lanes)) {
        if (!stepGroups(std::integral_constant<size_t, kLaneGroups>{})) return;
    }
    while (stepGroups(std::integral_constant<size_t, 1>{})) {
    }
}

// sphereTrace (march.cpp) for a batch of camera rays, kLaneGroups vectors of rays at a time.
template <bool kQuadratic, class D>
void traceCameraLanes(D d, const LaneFractal& fractal, const CameraMarch& march,
                      const RayBatch& rays, std::vector<TraceResult>& results,
                      LaneCounters& counters) {
    using V = hn::Vec<D>;
    using M = hn::Mask<D>;
    using T = hn::TFromD<D>;
    constexpr size_t K = kLaneGroups;
    constexpr T kConfirmStep = T(kMarchConfirmStep);
    static_assert(HWY_MAX_BYTES <= kMaxLaneBytes);
    const LaneConstants<D> k(d, fractal);
    const size_t lanes = hn::Lanes(d);
    results.assign(rays.size(), TraceResult{});
    RayLanes<T> s;
    LaneScratch<T> finished;
    size_t next = 0;
    for (size_t lane = 0; lane < K * lanes; ++lane)
        s.load(lane, rays, next);

    const V zero = hn::Zero(d), one = hn::Set(d, T(1));
    const V epsilon = hn::Set(d, T(march.epsilon)), pixelAngle = hn::Set(d, T(march.pixelAngle));
    const V confirmBudget = hn::Set(d, T(march.cone ? 0 : kMarchConfirmBudget));
    const V coneShrink = march.cone ? one : zero;
    const V maxSteps = hn::Set(d, T(march.maxSteps));
    const bool spreads = march.cone && !rays.spread.empty();
    // Cones step plainly (their steps are already short of the estimate).
    const V relaxation = hn::Set(d, T(march.relaxation));
    const M relaxing = hn::FirstN(d, march.cone || !(march.relaxation > 1) ? 0 : hn::Lanes(d));
    // One step of the rays in the first G vectors of lanes, from their estimates (marchBatch).
    auto marchStep = [&](auto groups, const auto& live, const auto& t, const auto& e) {
        constexpr size_t G = decltype(groups)::value;

        uint64_t doneLanes = 0;  // bit per lane of the rays that ended this step
        for (size_t j = 0; j < G; ++j) {
            const size_t o = j * lanes;
            const V footprint = spreads ? hn::MulAdd(pixelAngle, t[j], hn::Load(d, s.spread + o))
                                        : pixelAngle * t[j];
            const V distance = e[j].distance;
            // The point before (tOutside), its estimate (radius), its plain step and the step
            // taken from it if that was longer (lastStep, else 0): where the plain step and this
            // point's ball leave a gap, the set may lie in it, so this point's estimate is dropped
            // and the ray goes back to the plain step (sphereTrace).
            const V tPrevious = hn::Load(d, s.tOutside + o);
            const V radius = hn::Load(d, s.radius + o);
            const V relaxedStep = hn::Load(d, s.lastStep + o);
            const V plainPrevious = hn::Load(d, s.plainStep + o);
            const auto gap = hn::And(live[j], relaxedStep > plainPrevious + distance);
            const V loadedConfirming = hn::Load(d, s.confirming + o);
            V confirming = hn::IfThenElse(
                gap, loadedConfirming,
                hn::IfThenElseZero(distance < epsilon * footprint, loadedConfirming + one));
            const V steps = hn::Load(d, s.steps + o) + one;
            auto insideHit = hn::AndNot(gap, hn::And(live[j], e[j].inside));
            auto grazing =
                hn::AndNot(hn::Or(gap, e[j].inside), hn::And(live[j], confirming > confirmBudget));
            const V tFar = hn::Load(d, s.tFar + o);
            const V relaxed = relaxedLength(d, relaxation, t[j], tPrevious, radius, distance);
            const V plain = hn::IfThenElse(confirming > zero,
                                           hn::Max(distance, hn::Set(d, kConfirmStep) * footprint),
                                           hn::NegMulAdd(coneShrink, footprint, distance));
            const auto relax = hn::And(relaxing, hn::And(relaxed > plain, relaxed + t[j] <= tFar));
            V step = hn::IfThenElse(relax, relaxed, plain);
            step = hn::IfThenElse(gap, plainPrevious, step);
            const V tNext = hn::IfThenElse(gap, tPrevious, t[j]) + step;
            auto ended = hn::Or(insideHit, grazing);
            auto missed =
                hn::AndNot(ended, hn::And(live[j], hn::Or(tNext > tFar, steps >= maxSteps)));
            hn::Store(t[j], d, finished.a + o);
            hn::Store(tPrevious, d, finished.b + o);
            hn::Store(steps, d, finished.c + o);
            hn::Store(hn::IfThenElseZero(insideHit, one) +
                          hn::IfThenElseZero(grazing, hn::Set(d, T(2))) +
                          hn::IfThenElseZero(missed, hn::Set(d, T(3))),
                      d, finished.kind + o);
            doneLanes |= laneBits(d, hn::Or(ended, missed)) << o;
            hn::Store(tNext, d, s.t + o);
            hn::Store(hn::IfThenElse(gap, tPrevious, t[j]), d, s.tOutside + o);
            hn::Store(hn::IfThenElse(gap, radius, distance), d, s.radius + o);
            hn::Store(hn::IfThenElse(gap, plainPrevious, plain), d, s.plainStep + o);
            hn::Store(hn::IfThenElseZero(hn::AndNot(gap, relax), relaxed), d, s.lastStep + o);
            hn::Store(confirming, d, s.confirming + o);
            hn::Store(steps, d, s.steps + o);
        }
        for (; doneLanes != 0; doneLanes &= doneLanes - 1) {
            const size_t lane = size_t(__builtin_ctzll(doneLanes));
            TraceResult& r = results[size_t(s.ray[lane])];
            r.steps = int(finished.c[lane]);
            r.t = finished.a[lane];
            if (finished.kind[lane] == T(1)) {
                r.end = TraceEnd::Inside;
                r.tOutside = finished.b[lane];
            } else if (finished.kind[lane] == T(2)) {
                r.end = TraceEnd::Grazing;
                // A cone's last point may be inside for some of its rays; the one before is
                // covered by an estimate's ball.
                r.tOutside = march.cone ? finished.b[lane] : r.t;
            }
            s.load(lane, rays, next);
        }
    };
    marchBatch<kQuadratic>(d, k, s, rays, next, counters, marchStep);
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
    RayLanes<T> s;
    LaneScratch<T> finished;
    size_t next = 0;
    for (size_t lane = 0; lane < K * lanes; ++lane)
        s.load(lane, rays, next, /*startAtZero=*/true);

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
            const V radius = hn::Load(d, s.radius + o), lastStep = hn::Load(d, s.lastStep + o);
            const V relaxation = hn::Load(d, s.relaxation + o);
            const auto gap =
                hn::And(live[j], hn::And(relaxation > one, radius + e[j].distance < lastStep));
            const auto accepted = hn::AndNot(gap, live[j]);
            auto blocked = hn::And(accepted, hn::Or(e[j].inside, e[j].distance < blockDistance));
            // The penumbra: how nearly the ray grazed the set relative to how far it went.
            V open = hn::Load(d, s.confirming + o);  // the running visibility of this ray
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
            hn::Store(hn::IfThenElse(gap, radius, newRadius), d, s.radius + o);
            hn::Store(step, d, s.lastStep + o);
            hn::Store(hn::IfThenElse(gap, one, factor), d, s.relaxation + o);
            const V steps = hn::Load(d, s.steps + o) + one;
            auto cleared = hn::AndNot(
                blocked,
                hn::And(live[j], hn::Or(tNext >= hn::Load(d, s.tFar + o), steps >= maxSteps)));
            auto done = hn::Or(blocked, cleared);
            hn::Store(tNext, d, s.t + o);
            hn::Store(open, d, s.confirming + o);
            hn::Store(steps, d, s.steps + o);
            hn::Store(hn::IfThenZeroElse(blocked, march.soft ? open : one), d, finished.a + o);
            doneLanes |= laneBits(d, done) << o;
        }
        for (; doneLanes != 0; doneLanes &= doneLanes - 1) {
            const size_t lane = size_t(__builtin_ctzll(doneLanes));
            visibility[size_t(s.ray[lane])] = finished.a[lane];
            s.load(lane, rays, next, /*startAtZero=*/true);
        }
    };
    marchBatch<kQuadratic>(d, k, s, rays, next, counters, marchStep);
}

// Fractal::estimate for a batch of points, lanes filled in order (the last chunk padded). With
// kOrbit the whole PointEstimate; without, only the distance (0 inside) goes to store(begin,
// count, distances).
template <bool kQuadratic, bool kOrbit, class D, class Store>
void estimatePointLanes(D d, const LaneFractal& fractal, const PointBatch& points,
                        LaneCounters& counters, const Store& store) {
    using T = hn::TFromD<D>;
    const LaneConstants<D> k(d, fractal);
    const size_t lanes = hn::Lanes(d);
    LaneScratch<T> in, out;
    for (size_t begin = 0; begin < points.size(); begin += lanes) {
        size_t count = std::min(lanes, points.size() - begin);
        in.gather(points, begin, count);
        const hn::Mask<D> live[1] = {hn::FirstN(d, count)};
        const auto x = hn::Load(d, in.a), y = hn::Load(d, in.b), z = hn::Load(d, in.c);
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
        hn::Store(e.distance, d, out.a);
        if constexpr (kOrbit) {
            hn::Store(hn::Sqrt(e.trapSquared), d, out.b);
            hn::Store(e.iterations, d, out.c);
            hn::Store(e.radiusSquared, d, out.kind);
            hn::Store(hn::IfThenElseZero(e.inside, hn::Set(d, T(1))), d, in.kind);
        }
        store(begin, count, in, out);
    }
}

template <bool kQuadratic, class D>
void estimatePointLanes(D d, const LaneFractal& fractal, const PointBatch& points,
                        std::vector<PointEstimate>& results, LaneCounters& counters) {
    results.assign(points.size(), PointEstimate{});
    estimatePointLanes<kQuadratic, true>(d, fractal, points, counters,
                                         [&](size_t begin, size_t count, auto& in, auto& out) {
                                             for (size_t lane = 0; lane < count; ++lane) {
                                                 PointEstimate& r = results[begin + lane];
                                                 r.distance = out.a[lane];
                                                 r.trap = out.b[lane];
                                                 r.iterations = int(out.c[lane]);
                                                 r.radiusSquared = out.kind[lane];
                                                 r.inside = in.kind[lane] != 0;
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
    LaneScratch<T> in, out;
    for (size_t begin = 0; begin < points.size(); begin += lanes) {
        size_t count = std::min(lanes, points.size() - begin);
        in.gather(points, begin, count);
        const V x = hn::Load(d, in.a), y = hn::Load(d, in.b), z = hn::Load(d, in.c);
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
                in.kind[lane] = T(m);
                most = std::max(most, m);
            }
            const V m = hn::Load(d, in.kind);
            const int fewest = int(hn::GetLane(hn::MinOfLanes(d, m)));
            if constexpr (kQuadratic && sizeof(T) == 4) {
                threeNumberGradient(d, k, x, y, z, m, fewest, most, gx, gy, gz, counters);
            } else {
                quaternionGradient<kQuadratic>(d, k, x, y, z, m, fewest, most, gx, gy, gz,
                                               counters);
            }
        }
        hn::Store(gx, d, out.a);
        hn::Store(gy, d, out.b);
        hn::Store(gz, d, out.c);
        for (size_t lane = 0; lane < count; ++lane) {
            Vector3d g(out.a[lane], out.b[lane], out.c[lane]);
            Point3d p(points.x[begin + lane], points.y[begin + lane], points.z[begin + lane]);
            normals[begin + lane] = normalOrOutward(g, p);
        }
    }
}

// Calls kernel(d, quadratic) with the fractal's precision as the lane tag and its form as a
// std::bool_constant: each kernel in both precisions and both forms, chosen at run time.
template <class Kernel>
void run(const LaneFractal& fractal, const Kernel& kernel) {
    auto withForm = [&](auto d) {
        if (fractal.degree == 2) {
            kernel(d, std::true_type{});
        } else {
            kernel(d, std::false_type{});
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
            d, fractal, points, counters, [&](size_t begin, size_t count, auto&, auto& out) {
                std::copy(out.a, out.a + count, distances.begin() + std::ptrdiff_t(begin));
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
