// SIMD kernels of packet_kernels.h, compiled once per instruction set by Highway's
// foreach_target and chosen at run time (HWY_DYNAMIC_DISPATCH). See the header for what each
// computes; the scalar reference each one mirrors is named beside it.

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "quaternia/packet_kernels.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
// clang-format off: the order matters, highway.h after foreach_target.h
#include <hwy/contrib/math/math-inl.h>
#include <hwy/highway.h>
// clang-format on

#include <algorithm>
#include <cmath>
#include <cstring>
#include <type_traits>

#include "quaternia/lane_state.h"
#include "quaternia/march.h"
#include "quaternia/packet_kernels.h"

HWY_BEFORE_NAMESPACE();
namespace quaternia {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

#include "quaternia/julia_lanes-inl.h"
// After the formulas it uses:
#include "quaternia/estimate_lanes-inl.h"

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
    for (;;) {
        M live[K];
        V t[K];
        LaneEstimate<D> e[K];
        if (!estimateAlongRays<kQuadratic>(d, k, s, live, t, e, counters)) break;

        uint64_t doneLanes = 0;  // bit per lane of the rays that ended this step
        for (size_t j = 0; j < K; ++j) {
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
    }
}

// Shader::shadow (shade.cpp) for a batch of shadow rays, marched from t = 0.
template <bool kQuadratic, class D>
void traceShadowLanes(D d, const LaneFractal& fractal, const ShadowMarch& march,
                      const RayBatch& rays, std::vector<double>& visibility,
                      LaneCounters& counters) {
    using V = hn::Vec<D>;
    using M = hn::Mask<D>;
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
    for (;;) {
        M live[K];
        V t[K];
        LaneEstimate<D> e[K];
        if (!estimateAlongRays<kQuadratic>(d, k, s, live, t, e, counters)) break;

        uint64_t doneLanes = 0;
        for (size_t j = 0; j < K; ++j) {
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
    }
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
            const QuaternionLanes<hn::Vec<D>> u[1] = {k.loopFromWorld(x, y, z)};
            estimateThreeNumbers<kOrbit>(d, k, u, live, estimates, counters);
        } else {
            QuaternionLanes<hn::Vec<D>> q[1] = {k.quaternionFromWorld(x, y, z)};
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

// `hold(next, old)` for a single lane vector, as select() is for quaternions.
template <class V, class M>
HWY_INLINE V select(M mask, V yes, V no) {
    return hn::IfThenElse(mask, yes, no);
}

// Calls iterate(hold) until lane i has done m_i iterates (m_i in the lanes of m; fewest and most
// their least and greatest). `hold(next, old)` gives a lane's new value, or keeps the old one in
// a lane that is done; while every lane still runs (most of the iterations, as the M of
// neighbouring hits differ little), nothing needs holding.
template <class D, class V, class Iterate>
HWY_INLINE void iterateEachLaneItsCount(D d, V m, int fewest, int most, LaneCounters& counters,
                                        const Iterate& iterate) {
    const int64_t lanes = int64_t(hn::Lanes(d));
    for (int iteration = 0; iteration < fewest; ++iteration) {
        counters.laneIterations += lanes;
        counters.laneSlots += lanes;
        iterate([](const auto& next, const auto&) { return next; });
    }
    for (int iteration = fewest; iteration < most; ++iteration) {
        const auto running = hn::Set(d, hn::TFromD<D>(iteration)) < m;
        counters.laneIterations += int64_t(hn::CountTrue(d, running));
        counters.laneSlots += lanes;
        iterate([&](const auto& next, const auto& old) { return select(running, next, old); });
    }
}

// potentialNormalLanes' gradient for float lanes of s z^2 + c, in the three numbers of
// estimateThreeNumbers: u = 2 s z = A + B i + E (E in span{j, k}, P = |E|^2) maps to A' = (A^2 -
// B^2 - P) / 2 + 2 s c.w, B' = A B + 2 s c.x, E' = A E. A tangent of the slice, dU, then needs
// dA, dB and dR = E . dE alone: dA' = A dA - B dB - dR, dB' = A dB + B dA, dR' = E' . dE' =
// A (P dA + A dR) (from dE' = dA E + A dE), and u . dU = A dA + B dB + dR is the gradient of
// |u|^2 / 2, 4 s^2 times that of |z|^2 / 2: the same direction. 27 operations per iterate with
// the three tangents instead of about 50. `m` holds each lane's M; the gradient's components
// along the slice's axes go to gx, gy, gz.
template <class D, class V = hn::Vec<D>>
HWY_INLINE void threeNumberGradient(D d, const LaneConstants<D>& k, V x, V y, V z, V m, int fewest,
                                    int most, V& gx, V& gy, V& gz, LaneCounters& counters) {
    using T = hn::TFromD<D>;
    const QuaternionLanes<V> u = k.loopFromWorld(x, y, z);
    V a = u.w, b = u.x, p = hn::MulAdd(u.z, u.z, u.y * u.y);
    V dA[3], dB[3], dR[3];
    const QuaternionLanes<V>* axes[3] = {&k.loopAxis0, &k.loopAxis1, &k.loopAxis2};
    for (int i = 0; i < 3; ++i) {
        dA[i] = axes[i]->w, dB[i] = axes[i]->x;
        dR[i] = hn::MulAdd(u.z, axes[i]->z, u.y * axes[i]->y);
    }
    const V half = hn::Set(d, T(0.5)), one = hn::Set(d, T(1));
    const V large = hn::Set(d, T(1e30)), shrink = hn::Set(d, T(1e-10));
    // One iterate (iterateEachLaneItsCount's `hold`).
    iterateEachLaneItsCount(d, m, fewest, most, counters, [&](const auto& hold) {
        const V aa = a * a;
        for (int i = 0; i < 3; ++i) {
            const V nextA = hn::MulSub(a, dA[i], hn::MulAdd(b, dB[i], dR[i]));
            const V nextB = hn::MulAdd(a, dB[i], b * dA[i]);
            const V nextR = a * hn::MulAdd(p, dA[i], a * dR[i]);
            dA[i] = hold(nextA, dA[i]), dB[i] = hold(nextB, dB[i]), dR[i] = hold(nextR, dR[i]);
        }
        const V nextA = hn::MulAdd(half, aa - hn::MulAdd(b, b, p), k.scaledC);
        const V nextB = hn::MulAdd(a, b, k.scaledCi);
        const V nextP = aa * p;
        a = hold(nextA, a), b = hold(nextB, b), p = hold(nextP, p);
        // Only the direction matters: rescale the tangents together before they overflow.
        V largest = hn::Zero(d);
        for (int i = 0; i < 3; ++i)
            largest =
                hn::Max(largest, hn::Max(hn::Abs(dA[i]), hn::Max(hn::Abs(dB[i]), hn::Abs(dR[i]))));
        const auto huge = largest > large;
        if (!hn::AllFalse(d, huge)) {
            const V factor = hn::IfThenElse(huge, shrink, one);
            for (int i = 0; i < 3; ++i)
                dA[i] = dA[i] * factor, dB[i] = dB[i] * factor, dR[i] = dR[i] * factor;
        }
    });
    gx = hn::MulAdd(a, dA[0], hn::MulAdd(b, dB[0], dR[0]));
    gy = hn::MulAdd(a, dA[1], hn::MulAdd(b, dB[1], dR[1]));
    gz = hn::MulAdd(a, dA[2], hn::MulAdd(b, dB[2], dR[2]));
}

// potentialNormalLanes' gradient in quaternions, for any s z^d + c in float or double: the
// three tangents of the slice carried through the Jacobian of p at each iterate (the chain
// rule), and their inner products with z_M.
template <bool kQuadratic, class D, class V = hn::Vec<D>>
HWY_INLINE void quaternionGradient(D d, const LaneConstants<D>& k, V x, V y, V z0, V m, int fewest,
                                   int most, V& gx, V& gy, V& gz, LaneCounters& counters) {
    using T = hn::TFromD<D>;
    constexpr T kLarge = sizeof(T) == 4 ? T(1e30) : T(1e200);
    constexpr T kShrink = sizeof(T) == 4 ? T(1e-10) : T(1e-100);
    const V one = hn::Set(d, T(1));
    // Only the direction matters: rescale all three together before they overflow.
    auto rescale = [&](QuaternionLanes<V>& t0, QuaternionLanes<V>& t1, QuaternionLanes<V>& t2) {
        V largest =
            hn::Max(normSquaredLanes(t0), hn::Max(normSquaredLanes(t1), normSquaredLanes(t2)));
        auto huge = largest > hn::Set(d, kLarge);
        if (!hn::AllFalse(d, huge)) {
            const V factor = hn::IfThenElse(huge, hn::Set(d, kShrink), one);
            t0 = {t0.w * factor, t0.x * factor, t0.y * factor, t0.z * factor};
            t1 = {t1.w * factor, t1.x * factor, t1.y * factor, t1.z * factor};
            t2 = {t2.w * factor, t2.x * factor, t2.y * factor, t2.z * factor};
        }
    };
    auto z = k.quaternionFromWorld(x, y, z0);
    QuaternionLanes<V> t0 = k.axis0, t1 = k.axis1, t2 = k.axis2;
    // One iteration of the point and the tangents (iterateEachLaneItsCount's `hold`).
    iterateEachLaneItsCount(d, m, fewest, most, counters, [&](const auto& hold) {
        QuaternionLanes<V> n0, n1, n2, nz;
        if constexpr (kQuadratic) {
            n0 = quadraticDerivativeLanes(z, t0, k.scale);
            n1 = quadraticDerivativeLanes(z, t1, k.scale);
            n2 = quadraticDerivativeLanes(z, t2, k.scale);
            nz = quadraticStepLanes(z, k.scale, k.c);
        } else {
            n0 = powerDerivativeLanes(z, t0, k.degree, k.scale);
            n1 = powerDerivativeLanes(z, t1, k.degree, k.scale);
            n2 = powerDerivativeLanes(z, t2, k.degree, k.scale);
            nz = powerStepLanes(z, k.degree, k.scale, k.c);
        }
        t0 = hold(n0, t0), t1 = hold(n1, t1), t2 = hold(n2, t2), z = hold(nz, z);
        rescale(t0, t1, t2);
    });
    gx = dotLanes(z, t0), gy = dotLanes(z, t1), gz = dotLanes(z, t2);
}

// Fractal::normal / JuliaSet::potentialGradient for a batch of points, M_i iterations in lane i:
// the gradient of the potential along the slice's axes, then the outward unit normal.
template <bool kQuadratic, class D>
void potentialNormalLanes(D d, const LaneFractal& fractal, const PointBatch& points,
                          const std::vector<int>& iterations, std::vector<Vector3d>& normals,
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
        int most = 0;
        for (size_t lane = 0; lane < lanes; ++lane) {
            int m = lane < count ? iterations[begin + lane] : 0;
            in.kind[lane] = T(m);
            most = std::max(most, m);
        }
        const V m = hn::Load(d, in.kind);
        const int fewest = int(hn::GetLane(hn::MinOfLanes(d, m)));
        V gx, gy, gz;  // the gradient along the slice's axes
        if constexpr (kQuadratic && sizeof(T) == 4) {
            threeNumberGradient(d, k, hn::Load(d, in.a), hn::Load(d, in.b), hn::Load(d, in.c), m,
                                fewest, most, gx, gy, gz, counters);
        } else {
            quaternionGradient<kQuadratic>(d, k, hn::Load(d, in.a), hn::Load(d, in.b),
                                           hn::Load(d, in.c), m, fewest, most, gx, gy, gz,
                                           counters);
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
        potentialNormalLanes<quadratic()>(d, fractal, points, iterations, normals, counters);
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
const char* laneTargetName() {
    return HWY_DYNAMIC_DISPATCH(TargetName)();
}

}  // namespace quaternia
#endif  // HWY_ONCE
