// What the march lanes (camera_lanes.cpp, shadow_lanes.cpp, point_lanes.cpp) share, for each
// instruction-set target: the quaternion arithmetic and the estimate on this target's vectors,
// masks as bits, over-relaxed step lengths, the batch loop, and the dispatch on precision and
// form. Three translation units instead of one so that the build compiles them in parallel (each
// is compiled once per Highway target; under the sanitizers the one file took over ten minutes).
//
// Like Highway's own -inl.h headers, this file has no namespace of its own and is included
// inside quaternia::HWY_NAMESPACE, once per target (the HWY_TARGET_TOGGLE guard lets it in again).

#if defined(QUATERNIA_MARCH_LANES_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef QUATERNIA_MARCH_LANES_INL_H_
#undef QUATERNIA_MARCH_LANES_INL_H_
#else
#define QUATERNIA_MARCH_LANES_INL_H_
#endif

// QuaternionT's ring operations for this target's vectors (quaternion.h says why they are
// included here again).
template <class V>
concept QuaternionComponent = !std::is_arithmetic_v<V>;
#include "quaternia/algebra/quaternion_arithmetic-inl.h"
// The programs' interpreters and the iteration formulas for these vectors:
#include "quaternia/algebra/formula_program_run-inl.h"
#include "quaternia/fractal/julia_steps-inl.h"
// After the formulas they use:
#include "quaternia/render/lanes/program_lanes-inl.h"
// After the programs' lanes, which LaneConstants holds:
#include "quaternia/render/lanes/lane_constants-inl.h"
// After the constants:
#include "quaternia/render/lanes/estimate_lanes-inl.h"
#include "quaternia/render/lanes/gradient_lanes-inl.h"
// After the estimate's and the gradient's helpers, which it shares:
#include "quaternia/render/lanes/bicomplex_lanes-inl.h"

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

// Calls work(d, quadratic) with the fractal's precision as the lane tag and its form as a
// std::bool_constant (true for s z^2 + c; s z^d + c and programs share the other, and tell
// themselves apart at run time: LaneConstants::program): each march and estimate in both
// precisions and both forms, chosen at run time.
template <class Work>
void run(const LaneFractal& fractal, const Work& work) {
    auto withForm = [&](auto d) {
        if (fractal.degree == 2 && !fractal.program && !fractal.bicomplex) {
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

#endif  // QUATERNIA_MARCH_LANES_INL_H_
