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

// The fractal's constants broadcast to lanes of type T.
template <class D>
struct LaneConstants {
    using V = hn::Vec<D>;
    QuaternionLanes<V> origin, axis0, axis1, axis2, c;
    V scale, bailoutSquared, escapeRadiusSquared, estimateRadiusSquared, stepScale, maxIterations;
    V gainFactor;  // 4 s^2 for d = 2, s^2 d^2 otherwise
    // The float loop of s z^2 + c in u = 2 s z (estimateLanes): 2 s, 2 s c, the bailout and
    // estimate radii squared times 4 s^2, and 1 / (4 s^2).
    V twoScale, scaledBailoutSquared, scaledEstimateRadiusSquared, inverseFourScaleSquared;
    QuaternionLanes<V> scaledC;
    int degree, maxIterationCount;
    bool certified;  // bailout >= the certified escape radius: every escape is final

    LaneConstants(D d, const LaneFractal& f)
        : degree(f.degree),
          maxIterationCount(f.maxIterations),
          certified(f.bailoutSquared >= f.escapeRadiusSquared) {
        using T = hn::TFromD<D>;
        auto lanes = [&](const std::array<double, 4>& q) {
            return QuaternionLanes<V>{hn::Set(d, T(q[0])), hn::Set(d, T(q[1])), hn::Set(d, T(q[2])),
                                      hn::Set(d, T(q[3]))};
        };
        origin = lanes(f.origin);
        axis0 = lanes(f.axes[0]);
        axis1 = lanes(f.axes[1]);
        axis2 = lanes(f.axes[2]);
        c = lanes(f.c);
        scale = hn::Set(d, T(f.scale));
        bailoutSquared = hn::Set(d, T(f.bailoutSquared));
        escapeRadiusSquared = hn::Set(d, T(f.escapeRadiusSquared));
        estimateRadiusSquared = hn::Set(d, T(continuationRadiusSquared<T>(f.degree)));
        stepScale = hn::Set(d, T(f.stepScale));
        maxIterations = hn::Set(d, T(f.maxIterations));
        gainFactor = hn::Set(d, T(f.scale * f.scale * f.degree * f.degree));
        const double fourScaleSquared = 4 * f.scale * f.scale;
        twoScale = hn::Set(d, T(2 * f.scale));
        scaledC = lanes({2 * f.scale * f.c[0], 2 * f.scale * f.c[1], 2 * f.scale * f.c[2],
                         2 * f.scale * f.c[3]});
        scaledBailoutSquared = hn::Set(d, T(fourScaleSquared * f.bailoutSquared));
        scaledEstimateRadiusSquared =
            hn::Set(d, T(fourScaleSquared * continuationRadiusSquared<T>(f.degree)));
        inverseFourScaleSquared = hn::Set(d, T(1 / fourScaleSquared));
    }

    // The slice: a 3D point to its quaternion.
    QuaternionLanes<V> quaternionFromWorld(V x, V y, V z) const {
        return {hn::MulAdd(z, axis2.w, hn::MulAdd(y, axis1.w, hn::MulAdd(x, axis0.w, origin.w))),
                hn::MulAdd(z, axis2.x, hn::MulAdd(y, axis1.x, hn::MulAdd(x, axis0.x, origin.x))),
                hn::MulAdd(z, axis2.y, hn::MulAdd(y, axis1.y, hn::MulAdd(x, axis0.y, origin.y))),
                hn::MulAdd(z, axis2.z, hn::MulAdd(y, axis1.z, hn::MulAdd(x, axis0.z, origin.z)))};
    }
};

template <class D>
struct LaneEstimate {
    hn::Vec<D> distance, trapSquared, radiusSquared;
    hn::Vec<D> iterations;  // with kOrbit only (estimateLanes)
    hn::Mask<D> inside;
};

template <class V, class M>
HWY_INLINE QuaternionLanes<V> select(M mask, const QuaternionLanes<V>& yes,
                                     const QuaternionLanes<V>& no) {
    return {hn::IfThenElse(mask, yes.w, no.w), hn::IfThenElse(mask, yes.x, no.x),
            hn::IfThenElse(mask, yes.y, no.y), hn::IfThenElse(mask, yes.z, no.z)};
}

// ln x for float lanes of positive, finite x, from x = m 2^e (m in [1, 2)): ln x = (e + log2 m)
// ln 2, log2 m by a degree-6 polynomial in m - 1 that interpolates it at the Chebyshev nodes of
// [1, 2] (error below 2.5e-6), lowered by that bound so that it never exceeds log2 m.
template <class D, class V = hn::Vec<D>>
HWY_INLINE V fastLogLanes(D d, V x) {
    using T = hn::TFromD<D>;
    static_assert(sizeof(T) == 4, "float lanes only");
    const hn::RebindToSigned<D> di;
    const auto bits = hn::BitCast(di, x);
    const V exponent = hn::ConvertTo(d, hn::ShiftRight<23>(bits) - hn::Set(di, 127));
    const V t =
        hn::BitCast(d, hn::Or(hn::And(bits, hn::Set(di, 0x007fffff)), hn::Set(di, 0x3f800000))) -
        hn::Set(d, T(1));
    V p = hn::Set(d, T(-0.0245685347));
    p = hn::MulAdd(p, t, hn::Set(d, T(0.117613084)));
    p = hn::MulAdd(p, t, hn::Set(d, T(-0.272697565)));
    p = hn::MulAdd(p, t, hn::Set(d, T(0.454508492)));
    p = hn::MulAdd(p, t, hn::Set(d, T(-0.71731278)));
    p = hn::MulAdd(p, t, hn::Set(d, T(1.44245353)));
    p = hn::MulAdd(p, t, hn::Set(d, T(2.44343872e-6 - 2.45e-6)));
    return (exponent + p) * hn::Set(d, T(0.693147180559945));
}

// The closing formula of the estimate, d = 0.5 |z| ln|z| / |z'| = 0.25 sqrt(|z|^2 / |z'|^2)
// ln |z|^2, with its step scale; an overflowed |z'|^2 gives 0, which is right: the distance is
// then far below any step. Double lanes compute it as JuliaSet::estimate does. Float lanes, whose
// estimate is only good to a few percent anyway (the continuation stops at |z| = 100), take
// sqrt(a / b) = a / sqrt(a b) from the reciprocal square root estimate (relative error below
// 4e-4 on every target) and the logarithm from fastLogLanes: a division, a square root and a
// longer logarithm less per estimate. (A margin of 1/512 below the exact value, tried to keep
// the rounding one-sided, moved the lanes' ambient occlusion and soft shadows visibly away from
// the scalar path's: PacketRender.ShadedImageMatchesTheScalarPath.)
template <class D, class V = hn::Vec<D>>
HWY_INLINE V closingDistance(D d, V radiusSquared, V derivativeSquared, V stepScale) {
    using T = hn::TFromD<D>;
    V distance;
    if constexpr (sizeof(T) == 4) {
        const V root = hn::ApproximateReciprocalSqrt(radiusSquared * derivativeSquared);
        distance = hn::Set(d, T(0.25)) * radiusSquared * root * fastLogLanes(d, radiusSquared);
    } else {
        distance = hn::Set(d, T(0.25)) * hn::Sqrt(radiusSquared / derivativeSquared) *
                   hn::Log(d, radiusSquared);
    }
    return hn::Max(hn::Zero(d), distance) * stepScale;
}

// JuliaSet::estimate (distance.cpp) in lanes: iterate while |z| <= bailout and fewer than N
// iterates were tested, then, where escape is certain, continue to the estimate radius. Every
// lane runs the same iterations (no per-lane selects on z, which would lengthen the dependency
// chain); a lane whose estimate is final is marked done and its |z|^2 and |z'|^2 are kept at
// that iteration, while its z runs on unused (it may overflow; nothing reads it). The loop ends
// when every lane is done. kOrbit also keeps the orbit trap and the iteration count.
//
// The marching kernels' case, a certified bailout without the orbit, is the hot loop of the
// renderer. There, float lanes of s z^2 + c iterate u = 2 s z instead of z: u <- u^2 / 2 + 2 s c
// and |u'|^2 <- |u|^2 |u'|^2 are the same map and the same running derivative (|z'_{n+1}|^2 =
// 4 s^2 |z_n|^2 |z'_n|^2 = |u_n|^2 |z'_n|^2) without the two multiplications by 2 s, and the
// radii compare against thresholds scaled by 4 s^2. Only the counters want the iteration count
// there; they count the running lanes instead of keeping each lane's count.
template <bool kQuadratic, bool kOrbit, size_t K, class D>
HWY_INLINE void estimateLanes(D d, const LaneConstants<D>& k, QuaternionLanes<hn::Vec<D>> (&z)[K],
                              const hn::Mask<D> (&live)[K], LaneEstimate<D> (&result)[K],
                              LaneCounters& counters) {
    using V = hn::Vec<D>;
    using M = hn::Mask<D>;
    using T = hn::TFromD<D>;
    const V one = hn::Set(d, T(1)), half = hn::Set(d, T(0.5));
    // Where the bailout is at least the certified escape radius (the default), every escape is
    // final and |z| grows from then on: a lane stops at the estimate radius, and the lanes not
    // escaped after N iterates are inside; the escaped mask is then needed only for the trap.
    const bool certified = !kOrbit && k.certified;
    const bool scaled = certified && kQuadratic && sizeof(T) == 4;  // iterate u = 2 s z
    // K independent groups of lanes, iterated side by side so that their dependency chains
    // overlap in the pipeline.
    V r2[K], derivativeSquared[K], stopRadiusSquared[K], stopDerivativeSquared[K], trap[K],
        stopIteration[K];
    M escaped[K], done[K], inside[K];
    bool allDone = true;
    for (size_t j = 0; j < K; ++j) {
        r2[j] = normSquaredLanes(z[j]);
        derivativeSquared[j] = one;
        escaped[j] = hn::And(live[j], r2[j] > k.bailoutSquared);
        // Escaped at z_0: final unless escape is certain and the estimate radius not reached.
        auto continues = hn::And(r2[j] > k.escapeRadiusSquared, r2[j] < k.estimateRadiusSquared);
        done[j] = hn::Or(hn::Not(live[j]), hn::AndNot(continues, escaped[j]));
        inside[j] = hn::FirstN(d, 0);
        if (k.maxIterationCount <= 1) {
            inside[j] = hn::AndNot(escaped[j], live[j]);
            done[j] = hn::Or(done[j], inside[j]);
        }
        trap[j] = r2[j];
        stopIteration[j] = hn::Zero(d);
        allDone = allDone && hn::AllTrue(d, done[j]);
        if (scaled) {
            z[j] = {k.twoScale * z[j].w, k.twoScale * z[j].x, k.twoScale * z[j].y,
                    k.twoScale * z[j].z};
            r2[j] = normSquaredLanes(z[j]);
        }
        stopRadiusSquared[j] = r2[j];
        stopDerivativeSquared[j] = one;
    }
    const int64_t lanes = int64_t(hn::Lanes(d));
    const int iterationCap = k.maxIterationCount + kMaxContinuation;
    int64_t running = 0;  // lane iterations of the certified loops, which keep no counts
    V iteration = hn::Zero(d);
    int n = 1;
    if (scaled) {
        // The hot loop, on its own so that its registers hold nothing else.
        for (; n < iterationCap && !allDone; ++n) {
            allDone = true;
            const bool last = n + 1 >= k.maxIterationCount;  // z_0 .. z_{N-1} tested
            for (size_t j = 0; j < K; ++j) {
                derivativeSquared[j] = derivativeSquared[j] * r2[j];
                z[j] = halfSquareStepLanes(z[j], half, k.scaledC);
                r2[j] = normSquaredLanes(z[j]);
                running += lanes - int64_t(hn::CountTrue(d, done[j]));
                auto stopNow = hn::AndNot(done[j], r2[j] >= k.scaledEstimateRadiusSquared);
                if (last) {
                    const auto insideNow = hn::AndNot(done[j], r2[j] <= k.scaledBailoutSquared);
                    inside[j] = hn::Or(inside[j], insideNow);
                    stopNow = hn::Or(stopNow, insideNow);
                }
                stopRadiusSquared[j] = hn::IfThenElse(stopNow, r2[j], stopRadiusSquared[j]);
                stopDerivativeSquared[j] =
                    hn::IfThenElse(stopNow, derivativeSquared[j], stopDerivativeSquared[j]);
                done[j] = hn::Or(done[j], stopNow);
                allDone = allDone && hn::AllTrue(d, done[j]);
            }
        }
    }
    for (; n < iterationCap && !allDone; ++n) {
        allDone = true;
        if (!certified) iteration = iteration + one;
        for (size_t j = 0; j < K; ++j) {
            if constexpr (kQuadratic) {
                derivativeSquared[j] = derivativeSquared[j] * (k.gainFactor * r2[j]);
                z[j] = quadraticStepLanes(z[j], k.scale, k.c);
            } else {
                V gain = k.gainFactor;
                for (int e = 1; e < k.degree; ++e)
                    gain = gain * r2[j];
                derivativeSquared[j] = derivativeSquared[j] * gain;
                z[j] = powerStepLanes(z[j], k.degree, k.scale, k.c);
            }
            r2[j] = normSquaredLanes(z[j]);
            if (certified) {
                running += lanes - int64_t(hn::CountTrue(d, done[j]));
                auto stopNow = hn::AndNot(done[j], r2[j] >= k.estimateRadiusSquared);
                if (n + 1 >= k.maxIterationCount) {
                    const auto insideNow = hn::AndNot(done[j], r2[j] <= k.bailoutSquared);
                    inside[j] = hn::Or(inside[j], insideNow);
                    stopNow = hn::Or(stopNow, insideNow);
                }
                stopRadiusSquared[j] = hn::IfThenElse(stopNow, r2[j], stopRadiusSquared[j]);
                stopDerivativeSquared[j] =
                    hn::IfThenElse(stopNow, derivativeSquared[j], stopDerivativeSquared[j]);
                done[j] = hn::Or(done[j], stopNow);
                allDone = allDone && hn::AllTrue(d, done[j]);
                continue;
            }
            const auto settled = hn::Or(escaped[j], done[j]);  // before this iterate
            if constexpr (kOrbit)
                trap[j] = hn::IfThenElse(settled, trap[j], hn::Min(trap[j], r2[j]));
            const auto escapedNow = hn::AndNot(settled, r2[j] > k.bailoutSquared);
            escaped[j] = hn::Or(escaped[j], escapedNow);
            // An escaped lane stops at the estimate radius, or at once if escape is not certain.
            auto stopNow = hn::AndNot(
                done[j],
                hn::And(escaped[j], hn::Or(r2[j] >= k.estimateRadiusSquared,
                                           hn::AndNot(r2[j] > k.escapeRadiusSquared, escapedNow))));
            if (n + 1 >= k.maxIterationCount) {  // z_0 .. z_{N-1} tested: the rest are inside
                const auto insideNow = hn::Not(hn::Or(escaped[j], done[j]));
                inside[j] = hn::Or(inside[j], insideNow);
                stopNow = hn::Or(stopNow, insideNow);
            }
            stopRadiusSquared[j] = hn::IfThenElse(stopNow, r2[j], stopRadiusSquared[j]);
            stopDerivativeSquared[j] =
                hn::IfThenElse(stopNow, derivativeSquared[j], stopDerivativeSquared[j]);
            stopIteration[j] = hn::IfThenElse(stopNow, iteration, stopIteration[j]);
            done[j] = hn::Or(done[j], stopNow);
            allDone = allDone && hn::AllTrue(d, done[j]);
        }
    }
    counters.laneIterations += running;
    for (size_t j = 0; j < K; ++j) {
        const auto unfinished = hn::Not(done[j]);  // the continuation cap ended them
        V radiusSquared = hn::IfThenElse(unfinished, r2[j], stopRadiusSquared[j]);
        if (scaled) radiusSquared = radiusSquared * k.inverseFourScaleSquared;
        V derivative = hn::IfThenElse(unfinished, derivativeSquared[j], stopDerivativeSquared[j]);
        counters.laneSlots += lanes * int64_t(n - 1);
        if (!certified) {
            stopIteration[j] = hn::IfThenElse(unfinished, iteration, stopIteration[j]);
            // Utilisation: each lane did useful work until it stopped; the slots are all lanes.
            counters.laneIterations += int64_t(
                hn::GetLane(hn::SumOfLanes(d, hn::IfThenElseZero(live[j], stopIteration[j]))));
        }
        result[j].inside = inside[j];
        result[j].distance = hn::IfThenZeroElse(
            inside[j], closingDistance(d, radiusSquared, derivative, k.stepScale));
        result[j].trapSquared = trap[j];
        result[j].iterations = hn::IfThenElse(inside[j], k.maxIterations, stopIteration[j]);
        result[j].radiusSquared = radiusSquared;
    }
}

// The estimates at the current points of the rays in the lanes (o + t d, through the slice):
// live lanes, their t, and the estimates. False when no lane holds a ray.
template <bool kQuadratic, size_t K, class D, class T>
HWY_INLINE bool estimateAlongRays(D d, const LaneConstants<D>& k, const RayLanes<T>& s,
                                  hn::Mask<D> (&live)[K], hn::Vec<D> (&t)[K],
                                  LaneEstimate<D> (&e)[K], LaneCounters& counters) {
    const size_t lanes = hn::Lanes(d);
    QuaternionLanes<hn::Vec<D>> q[K];
    bool anyLive = false;
    for (size_t j = 0; j < K; ++j) {
        const size_t o = j * lanes;
        live[j] = hn::Load(d, s.live + o) > hn::Zero(d);
        anyLive = anyLive || !hn::AllFalse(d, live[j]);
        t[j] = hn::Load(d, s.t + o);
        q[j] =
            k.quaternionFromWorld(hn::MulAdd(hn::Load(d, s.dx + o), t[j], hn::Load(d, s.ox + o)),
                                  hn::MulAdd(hn::Load(d, s.dy + o), t[j], hn::Load(d, s.oy + o)),
                                  hn::MulAdd(hn::Load(d, s.dz + o), t[j], hn::Load(d, s.oz + o)));
    }
    if (!anyLive) return false;
    estimateLanes<kQuadratic, false>(d, k, q, live, e, counters);
    for (size_t j = 0; j < K; ++j)
        counters.estimates += int64_t(hn::CountTrue(d, live[j]));
    return true;
}

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
        QuaternionLanes<hn::Vec<D>> q[1] = {
            k.quaternionFromWorld(hn::Load(d, in.a), hn::Load(d, in.b), hn::Load(d, in.c))};
        LaneEstimate<D> estimates[1];
        estimateLanes<kQuadratic, kOrbit>(d, k, q, live, estimates, counters);
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

// Fractal::normal / JuliaSet::potentialGradient for a batch of points: the three tangents of
// the slice carried through the Jacobian of p at each iterate (the chain rule), M_i iterations
// in lane i.
template <bool kQuadratic, class D>
void potentialNormalLanes(D d, const LaneFractal& fractal, const PointBatch& points,
                          const std::vector<int>& iterations, std::vector<Vector3d>& normals,
                          LaneCounters& counters) {
    using V = hn::Vec<D>;
    using T = hn::TFromD<D>;
    constexpr T kLarge = sizeof(T) == 4 ? T(1e30) : T(1e200);
    constexpr T kShrink = sizeof(T) == 4 ? T(1e-10) : T(1e-100);
    const LaneConstants<D> k(d, fractal);
    const size_t lanes = hn::Lanes(d);
    normals.assign(points.size(), Vector3d());
    LaneScratch<T> in, out;
    const V one = hn::Set(d, T(1));
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
        auto z = k.quaternionFromWorld(hn::Load(d, in.a), hn::Load(d, in.b), hn::Load(d, in.c));
        QuaternionLanes<V> t0 = k.axis0, t1 = k.axis1, t2 = k.axis2;
        V n = hn::Zero(d);
        // Lanes have their own M; while every lane still runs (most of the iterations, as the
        // M of neighbouring hits differ little), the selects that hold finished lanes are skipped.
        const int fewest = int(hn::GetLane(hn::MinOfLanes(d, m)));
        for (int iteration = 0; iteration < fewest; ++iteration) {
            counters.laneIterations += int64_t(lanes);
            counters.laneSlots += int64_t(lanes);
            if constexpr (kQuadratic) {
                t0 = quadraticDerivativeLanes(z, t0, k.scale);
                t1 = quadraticDerivativeLanes(z, t1, k.scale);
                t2 = quadraticDerivativeLanes(z, t2, k.scale);
                z = quadraticStepLanes(z, k.scale, k.c);
            } else {
                t0 = powerDerivativeLanes(z, t0, k.degree, k.scale);
                t1 = powerDerivativeLanes(z, t1, k.degree, k.scale);
                t2 = powerDerivativeLanes(z, t2, k.degree, k.scale);
                z = powerStepLanes(z, k.degree, k.scale, k.c);
            }
            n = n + one;
            rescale(t0, t1, t2);
        }
        for (int iteration = fewest; iteration < most; ++iteration) {
            auto running = n < m;
            counters.laneIterations += int64_t(hn::CountTrue(d, running));
            counters.laneSlots += int64_t(lanes);
            if constexpr (kQuadratic) {
                t0 = select(running, quadraticDerivativeLanes(z, t0, k.scale), t0);
                t1 = select(running, quadraticDerivativeLanes(z, t1, k.scale), t1);
                t2 = select(running, quadraticDerivativeLanes(z, t2, k.scale), t2);
                z = select(running, quadraticStepLanes(z, k.scale, k.c), z);
            } else {
                t0 = select(running, powerDerivativeLanes(z, t0, k.degree, k.scale), t0);
                t1 = select(running, powerDerivativeLanes(z, t1, k.degree, k.scale), t1);
                t2 = select(running, powerDerivativeLanes(z, t2, k.degree, k.scale), t2);
                z = select(running, powerStepLanes(z, k.degree, k.scale, k.c), z);
            }
            n = n + one;
            rescale(t0, t1, t2);
        }
        hn::Store(dotLanes(z, t0), d, out.a);
        hn::Store(dotLanes(z, t1), d, out.b);
        hn::Store(dotLanes(z, t2), d, out.c);
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
