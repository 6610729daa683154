// The distance estimate in SIMD lanes, shared by the march lanes (march_lanes-inl.h):
// QuaternionJuliaSet::estimate for K vectors of points at once
// (estimateLanes), and the estimates along the rays held in lanes (estimateAlongRays).
//
// Like julia_steps-inl.h, this file has no namespace of its own: march_lanes-inl.h includes it
// inside its per-target namespace, once per SIMD target (the HWY_TARGET_TOGGLE guard below lets
// it in again for each), after hwy/highway.h, julia_steps-inl.h, lane_state.h and
// march_lanes.h, with hn naming the target's Highway namespace.

#if defined(QUATERNIA_ESTIMATE_LANES_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef QUATERNIA_ESTIMATE_LANES_INL_H_
#undef QUATERNIA_ESTIMATE_LANES_INL_H_
#else
#define QUATERNIA_ESTIMATE_LANES_INL_H_
#endif

template <class D>
struct LaneEstimate {
    hn::Vec<D> distance, trapSquared, radiusSquared;
    hn::Vec<D> iterations;  // with kOrbit only (estimateLanes)
    hn::Mask<D> inside;
};

template <class V, class M>
HWY_INLINE QuaternionT<V> select(M mask, const QuaternionT<V>& yes, const QuaternionT<V>& no) {
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
// then far below any step. Double lanes compute it as QuaternionJuliaSet::estimate does. Float lanes, whose
// estimate is only good to a few percent anyway (the continuation stops at |z| = 100), take
// sqrt(a / b) = a / (sqrt(a) sqrt(b)) from reciprocal square root estimates (relative error
// below 4e-4 each on every target) and the logarithm from fastLogLanes: a division, a square root
// and a longer logarithm less per estimate. (A margin of 1/512 below the exact value, tried to keep
// the rounding one-sided, moved the lanes' ambient occlusion and soft shadows visibly away from
// the scalar path's: LaneRender.ShadedImageMatchesTheScalarPath.)
template <class D, class V = hn::Vec<D>>
HWY_INLINE V closingDistance(D d, V radiusSquared, V derivativeSquared, V stepScale) {
    using T = hn::TFromD<D>;
    V distance;
    if constexpr (sizeof(T) == 4) {
        // Two estimates rather than one of the product, which overflows floats at high degrees
        // (|z|^2 near 1e20 after the last step of z^5, |z'|^2 beyond 1e18).
        const V root = hn::ApproximateReciprocalSqrt(radiusSquared) *
                       hn::ApproximateReciprocalSqrt(derivativeSquared);
        distance = hn::Set(d, T(0.25)) * radiusSquared * root * fastLogLanes(d, radiusSquared);
    } else {
        distance = hn::Set(d, T(0.25)) * hn::Sqrt(radiusSquared / derivativeSquared) *
                   hn::Log(d, radiusSquared);
    }
    return hn::Max(hn::Zero(d), distance) * stepScale;
}

// One group of lanes at z_0, whose |z_0|^2 is r2 (the radii squared in the loop's scale):
// escaped at z_0, done (empty lanes, and escapes that are final: uncertain, or past the estimate
// radius), and with N = 1 inside (the lanes not escaped).
template <class D, class V = hn::Vec<D>, class M = hn::Mask<D>>
HWY_INLINE void startLanes(D d, V r2, M live, V bailoutSquared, V escapeRadiusSquared,
                           V estimateRadiusSquared, int maxIterationCount, M& escaped, M& done,
                           M& inside) {
    escaped = hn::And(live, r2 > bailoutSquared);
    // Escaped at z_0: final unless escape is certain and the estimate radius not reached.
    const auto continues = hn::And(r2 > escapeRadiusSquared, r2 < estimateRadiusSquared);
    done = hn::Or(hn::Not(live), hn::AndNot(continues, escaped));
    inside = hn::FirstN(d, 0);
    if (maxIterationCount <= 1) {
        inside = hn::AndNot(escaped, live);
        done = hn::Or(done, inside);
    }
}

// The certified loops' bookkeeping after an iterate of one group of lanes whose stopped lanes
// keep |z|^2 (r2) themselves (estimateThreeNumbers: merge-masked arithmetic): count its running
// lanes, stop those past stopRadius and, after the N-th iterate (`last`), those still within
// insideRadius (inside K_N). True when every lane of the group is done.
template <class D, class V = hn::Vec<D>, class M = hn::Mask<D>>
HWY_INLINE bool settleFrozen(D d, V r2, V stopRadius, V insideRadius, bool last, M& done, M& inside,
                             int64_t& running) {
    running += int64_t(hn::Lanes(d)) - int64_t(hn::CountTrue(d, done));
    auto stopNow = hn::AndNot(done, r2 >= stopRadius);
    if (last) {
        const auto insideNow = hn::AndNot(done, r2 <= insideRadius);
        inside = hn::Or(inside, insideNow);
        stopNow = hn::Or(stopNow, insideNow);
    }
    done = hn::Or(done, stopNow);
    return hn::AllTrue(d, done);
}

// settleFrozen for loops whose lanes run on once stopped (estimateLanes): the lanes' |z|^2 and
// |z'|^2 (derivativeSquared) are copied where they stop.
template <class D, class V = hn::Vec<D>, class M = hn::Mask<D>>
HWY_INLINE bool settleCertified(D d, V r2, V derivativeSquared, V stopRadius, V insideRadius,
                                bool last, M& done, M& inside, V& stopRadiusSquared,
                                V& stopDerivativeSquared, int64_t& running) {
    const M doneBefore = done;
    const bool allDone = settleFrozen(d, r2, stopRadius, insideRadius, last, done, inside, running);
    const M stopNow = hn::AndNot(doneBefore, done);
    stopRadiusSquared = hn::IfThenElse(stopNow, r2, stopRadiusSquared);
    stopDerivativeSquared = hn::IfThenElse(stopNow, derivativeSquared, stopDerivativeSquared);
    return allDone;
}

// One group of lanes of estimateLanes: |z|^2 and |z'|^2 of the current iterate, and for the
// lanes done, their |z|^2, |z'|^2 and iteration count where they stopped; kOrbit also keeps
// the orbit trap (the least |z|^2 up to the first iterate past the bailout).
template <class D>
struct EstimateGroup {
    using V = hn::Vec<D>;
    using M = hn::Mask<D>;
    V r2, derivativeSquared, stopRadiusSquared, stopDerivativeSquared, trap, stopIteration;
    M escaped, done, inside;

    // At z_0, whose derivative is 1.
    HWY_INLINE void start(D d, const LaneConstants<D>& k, const QuaternionT<V>& z, M live, V one) {
        r2 = normSquaredPairwise(z);
        derivativeSquared = one;
        startLanes(d, r2, live, k.bailoutSquared, k.escapeRadiusSquared, k.estimateRadiusSquared,
                   k.maxIterationCount, escaped, done, inside);
        trap = r2;
        stopIteration = hn::Zero(d);
        stopRadiusSquared = r2;
        stopDerivativeSquared = one;
    }

    // The next iterate z <- s z^d + c, with |z'|^2 <- s^2 d^2 |z|^(2 (d - 1)) |z'|^2 from the
    // |z|^2 before it. (Programs step all groups at once: estimateLanes.)
    template <bool kQuadratic>
    HWY_INLINE void iterate(const LaneConstants<D>& k, QuaternionT<V>& z) {
        if constexpr (kQuadratic) {
            derivativeSquared = derivativeSquared * (k.gainFactor * r2);
            z = quadraticStep(z, k.scale, k.c);
        } else {
            V gain = k.gainFactor;
            for (int e = 1; e < k.degree; ++e)
                gain = gain * r2;
            derivativeSquared = derivativeSquared * gain;
            z = powerStep(z, k.degree, k.scale, k.c);
        }
        r2 = normSquaredPairwise(z);
    }

    // The general loop's bookkeeping after an iterate (`iteration`; `last`: z_0 .. z_{N-1}
    // tested, the lanes not escaped are inside), where an escape need not be final. True when
    // every lane of the group is done.
    template <bool kOrbit>
    HWY_INLINE bool settle(D d, const LaneConstants<D>& k, bool last, V iteration) {
        const auto settled = hn::Or(escaped, done);  // before this iterate
        if constexpr (kOrbit) trap = hn::IfThenElse(settled, trap, hn::Min(trap, r2));
        const auto escapedNow = hn::AndNot(settled, r2 > k.bailoutSquared);
        escaped = hn::Or(escaped, escapedNow);
        // An escaped lane stops at the estimate radius, or at once if escape is not certain.
        auto stopNow = hn::AndNot(
            done, hn::And(escaped, hn::Or(r2 >= k.estimateRadiusSquared,
                                          hn::AndNot(r2 > k.escapeRadiusSquared, escapedNow))));
        if (last) {
            const auto insideNow = hn::Not(hn::Or(escaped, done));
            inside = hn::Or(inside, insideNow);
            stopNow = hn::Or(stopNow, insideNow);
        }
        stopRadiusSquared = hn::IfThenElse(stopNow, r2, stopRadiusSquared);
        stopDerivativeSquared = hn::IfThenElse(stopNow, derivativeSquared, stopDerivativeSquared);
        stopIteration = hn::IfThenElse(stopNow, iteration, stopIteration);
        done = hn::Or(done, stopNow);
        return hn::AllTrue(d, done);
    }

    // The group's estimates once the loop ended after n - 1 iterates (at `iteration` where it
    // counted them), and the lanes' iterations in the counters.
    HWY_INLINE void finish(D d, const LaneConstants<D>& k, bool certified, int n, V iteration,
                           M live, LaneEstimate<D>& result, LaneCounters& counters) {
        const auto unfinished = hn::Not(done);  // the continuation cap ended them
        // |z|^2 where the lanes iterate a conjugate w (LaneFractal::squareMap): the estimate is
        // then the scalar reference's, 0.5 |z| ln|z| / |z'| (|z'| = |w'|).
        const V radiusSquared =
            hn::IfThenElse(unfinished, r2, stopRadiusSquared) * k.normSquaredScale;
        V derivative = hn::IfThenElse(unfinished, derivativeSquared, stopDerivativeSquared);
        counters.laneSlots += int64_t(hn::Lanes(d)) * int64_t(n - 1);
        if (!certified) {
            stopIteration = hn::IfThenElse(unfinished, iteration, stopIteration);
            // Utilisation: each lane did useful work until it stopped; the slots are all lanes.
            counters.laneIterations +=
                int64_t(hn::GetLane(hn::SumOfLanes(d, hn::IfThenElseZero(live, stopIteration))));
        }
        result.inside = inside;
        result.distance =
            hn::IfThenZeroElse(inside, closingDistance(d, radiusSquared, derivative, k.stepScale));
        if (!k.certified) {
            // Lanes stopped by a bailout below the escape radius: uncertainEscapeDistance
            // (distance.h), in the iterate's scale times |z| / |w|.
            const V r2Stopped = hn::IfThenElse(unfinished, r2, stopRadiusSquared);
            const auto uncertain = hn::AndNot(inside, r2Stopped <= k.escapeRadiusSquared);
            const V linear =
                hn::Max(hn::Zero(d), hn::Sqrt(r2Stopped) - hn::Sqrt(k.bailoutSquared)) /
                hn::Sqrt(derivative);
            result.distance = hn::IfThenElse(
                uncertain, hn::Set(d, hn::TFromD<D>(0.5)) * linear * k.normScale * k.stepScale,
                result.distance);
        }
        result.trapSquared = trap * k.normSquaredScale;
        result.iterations = hn::IfThenElse(inside, k.maxIterations, stopIteration);
        result.radiusSquared = radiusSquared;
    }
};

// QuaternionJuliaSet::estimate (distance.cpp) in lanes: iterate while |z| <= bailout and fewer than N
// iterates were tested, then, where escape is certain, continue to the estimate radius. Every
// lane runs the same iterations (no per-lane selects on z, which would lengthen the dependency
// chain); a lane whose estimate is final is marked done and its |z|^2 and |z'|^2 are kept at
// that iteration, while its z runs on unused (it may overflow; nothing reads it). The loop ends
// when every lane is done. kOrbit also keeps the orbit trap and the iteration count. (The
// marchers' hot case has its own loop: estimateThreeNumbers.)
template <bool kQuadratic, bool kOrbit, size_t K, class D>
HWY_INLINE void estimateLanes(D d, const LaneConstants<D>& k, QuaternionT<hn::Vec<D>> (&z)[K],
                              const hn::Mask<D> (&live)[K], LaneEstimate<D> (&result)[K],
                              LaneCounters& counters) {
    using V = hn::Vec<D>;
    using T = hn::TFromD<D>;
    const V one = hn::Set(d, T(1));
    // Where the bailout is at least the certified escape radius (the default), every escape is
    // final and |z| grows from then on: a lane stops at the estimate radius, and the lanes not
    // escaped after N iterates are inside; the escaped mask is then needed only for the trap.
    const bool certified = !kOrbit && k.certified;
    // K independent groups of lanes, iterated side by side so that their dependency chains
    // overlap in the pipeline.
    EstimateGroup<D> g[K];
    bool allDone = true;
    for (size_t j = 0; j < K; ++j) {
        g[j].start(d, k, z[j], live[j], one);
        allDone = allDone && hn::AllTrue(d, g[j].done);
    }
    const int iterationCap = k.maxIterationCount + kMaxContinuation;
    int64_t running = 0;  // lane iterations of the certified loop, which keeps no counts
    V iteration = hn::Zero(d);
    int n = 1;
    for (; n < iterationCap && !allDone; ++n) {
        allDone = true;
        if (!certified) iteration = iteration + one;
        const bool last = n + 1 >= k.maxIterationCount;  // z_0 .. z_{N-1} tested
        const bool program = !kQuadratic && k.program;
        if (program) {
            // |z'|^2 <- P'(|z|)^2 |z'|^2, the bound the scalar reference carries, then z <- p(z).
            for (size_t j = 0; j < K; ++j)
                g[j].derivativeSquared =
                    g[j].derivativeSquared * k.derivativeBound.gainSquared(g[j].r2);
            k.program.step(z);
            for (size_t j = 0; j < K; ++j)
                g[j].r2 = normSquaredPairwise(z[j]);
        }
        for (size_t j = 0; j < K; ++j) {
            if (!program) g[j].template iterate<kQuadratic>(k, z[j]);
            const bool groupDone =
                certified
                    ? settleCertified(d, g[j].r2, g[j].derivativeSquared, k.estimateRadiusSquared,
                                      k.bailoutSquared, last, g[j].done, g[j].inside,
                                      g[j].stopRadiusSquared, g[j].stopDerivativeSquared, running)
                    : g[j].template settle<kOrbit>(d, k, last, iteration);
            allDone = allDone && groupDone;
        }
    }
    counters.laneIterations += running;
    for (size_t j = 0; j < K; ++j)
        g[j].finish(d, k, certified, n, iteration, live[j], result[j], counters);
}

// The estimates of a group of estimateThreeNumbers once its loop ended after n - 1 iterates: its
// |z|^2, |z'|^2, trap and iteration counts where each lane stopped, radii times radiusScale to
// |z|^2 (1 / (4 s^2) for u = 2 s z, 1 for z itself).
template <bool kOrbit, class D, class Group>
HWY_INLINE void finishFrozenGroup(D d, const LaneConstants<D>& k, int n, hn::Vec<D> radiusScale,
                                  Group& g, LaneEstimate<D>& result, LaneCounters& counters) {
    using T = hn::TFromD<D>;
    const auto unfinished = hn::Not(g.done);  // the continuation cap ended them
    const hn::Vec<D> radiusSquared = g.r2 * radiusScale;
    counters.laneSlots += int64_t(hn::Lanes(d)) * int64_t(n - 1);
    result.inside = g.inside;
    result.distance = hn::IfThenZeroElse(
        g.inside, closingDistance(d, radiusSquared, g.derivativeSquared, k.stepScale));
    result.radiusSquared = radiusSquared;
    if constexpr (kOrbit) {
        result.trapSquared = g.trap * radiusScale;
        g.stopIteration = hn::IfThenElse(unfinished, hn::Set(d, T(n - 1)), g.stopIteration);
        result.iterations = hn::IfThenElse(g.inside, k.maxIterations, g.stopIteration);
    }
}

// One group of lanes of estimateThreeNumbers (below): the orbit as a, b, rho, with aa = a^2 and
// rest = b^2 + rho (|u|^2 = aa + rest); |u|^2 and |u'|^2 of the lanes still running, a lane's
// staying where it stopped (merge-masked arithmetic: no separate copies taken when lanes stop, two
// operations less per iterate); kOrbit also the trap and each lane's iteration count.
template <class D>
struct ThreeNumbersGroup {
    using V = hn::Vec<D>;
    using M = hn::Mask<D>;
    V a, b, rho, aa, rest;
    V r2, derivativeSquared;
    V trap, stopIteration;  // kOrbit only
    M done, inside, escaped;

    // At u_0, whose derivative is 1.
    HWY_INLINE void start(D d, const LaneConstants<D>& k, const QuaternionT<V>& u, M live, V one) {
        a = u.w, b = u.x;
        rho = hn::MulAdd(u.z, u.z, u.y * u.y);
        aa = a * a;
        rest = hn::MulAdd(b, b, rho);
        r2 = aa + rest;
        derivativeSquared = one;
        startLanes(d, r2, live, k.scaledBailoutSquared, k.scaledEscapeRadiusSquared,
                   k.scaledEstimateRadiusSquared, k.maxIterationCount, escaped, done, inside);
        trap = r2;
        stopIteration = hn::Zero(d);
    }

    // The thresholds in the loop's scale: where a lane's estimate is final, and the bailout.
    static V stopRadius(const LaneConstants<D>& k) { return k.scaledEstimateRadiusSquared; }
    static V insideRadius(const LaneConstants<D>& k) { return k.scaledBailoutSquared; }

    // The next iterate of the running lanes: |u'|^2 <- |u|^2 |u'|^2, then a <- (a^2 - b^2 -
    // rho) / 2 + 2 s c.w, b <- a b + 2 s c.x, rho <- a^2 rho.
    HWY_INLINE void iterate(const LaneConstants<D>& k, M running, V half) {
        derivativeSquared = hn::IfThenElse(running, derivativeSquared * r2, derivativeSquared);
        const V nextA = hn::MulAdd(half, aa - rest, k.scaledC);
        b = hn::MulAdd(a, b, k.scaledCi);
        rho = aa * rho;
        a = nextA;
        aa = a * a;
        rest = hn::MulAdd(b, b, rho);
        r2 = hn::IfThenElse(running, aa + rest, r2);
    }

    // The group's estimates once the loop ended after n - 1 iterates.
    template <bool kOrbit>
    HWY_INLINE void finish(D d, const LaneConstants<D>& k, int n, LaneEstimate<D>& result,
                           LaneCounters& counters) {
        finishFrozenGroup<kOrbit>(d, k, n, k.inverseFourScaleSquared, *this, result, counters);
    }
};

// One group of lanes of estimateThreeNumbers for a real form p(z) = sum a_k z^k + c
// (LaneConstants::realThreeNumbers), unscaled: z = a + b i + e, e in span{j, k}, rho = |e|^2.
// With v = Im z and s2 = |v|^2 = b^2 + rho, v^2 = -s2, so every power of z, and p(z) - c, lies in
// span{1, v}: X + Y v, computed by Horner's rule in pairs, (X, Y) z = (X a - s2 Y, X + Y a).
// Then z <- (X + c.w) + (Y b + c.x) i + Y e: a, b and rho <- Y^2 rho carry the orbit (c is
// complex in the float lanes' rotated frame, LaneFractal::withComplexConstant). The derivative's
// gain is the scalar reference's bound P'(|z|)^2 (exact for s z^d + c).
template <class D>
struct RealThreeNumbersGroup {
    using V = hn::Vec<D>;
    using M = hn::Mask<D>;
    V a, b, rho;
    V r2, derivativeSquared;
    V trap, stopIteration;  // kOrbit only
    M done, inside, escaped;

    static V stopRadius(const LaneConstants<D>& k) { return k.estimateRadiusSquared; }
    static V insideRadius(const LaneConstants<D>& k) { return k.bailoutSquared; }

    HWY_INLINE void start(D d, const LaneConstants<D>& k, const QuaternionT<V>& z, M live, V one) {
        a = z.w, b = z.x;
        rho = hn::MulAdd(z.z, z.z, z.y * z.y);
        r2 = hn::MulAdd(a, a, hn::MulAdd(b, b, rho));
        derivativeSquared = one;
        startLanes(d, r2, live, k.bailoutSquared, k.escapeRadiusSquared, k.estimateRadiusSquared,
                   k.maxIterationCount, escaped, done, inside);
        trap = r2;
        stopIteration = hn::Zero(d);
    }

    HWY_INLINE void iterate(const LaneConstants<D>& k, M running, V) {
        derivativeSquared = hn::IfThenElse(
            running, derivativeSquared * k.derivativeBound.gainSquared(r2), derivativeSquared);
        const LaneVector<V>& coefficient = k.realCoefficients;
        const V s2 = hn::MulAdd(b, b, rho);
        const std::size_t degree = coefficient.size() - 1;
        // (X, Y) = a_d z + a_{d-1}, then times z plus a_k down to k = 0 (a_0 = 0).
        V x = hn::MulAdd(coefficient[degree], a, coefficient[degree - 1]);
        V y = coefficient[degree];
        for (std::size_t n = degree - 1; n-- > 0;) {
            const V nextX = hn::NegMulAdd(s2, y, hn::MulAdd(x, a, coefficient[n]));
            y = hn::MulAdd(y, a, x);
            x = nextX;
        }
        a = x + k.c.w;
        b = hn::MulAdd(y, b, k.c.x);
        rho = y * y * rho;
        r2 = hn::IfThenElse(running, hn::MulAdd(a, a, hn::MulAdd(b, b, rho)), r2);
    }

    template <bool kOrbit>
    HWY_INLINE void finish(D d, const LaneConstants<D>& k, int n, LaneEstimate<D>& result,
                           LaneCounters& counters) {
        finishFrozenGroup<kOrbit>(d, k, n, hn::Set(d, hn::TFromD<D>(1)), *this, result, counters);
    }
};

// estimateLanes' certified case for float lanes of s z^2 + c and distances alone: the hot loop
// of the renderer (LaneConstants::threeNumbers). The points come as u = 2 s z
// (LaneConstants::loopFromWorld), for which the map reads u <- u^2 / 2 + 2 s c and the running
// derivative |u'|^2 <- |u|^2 |u'|^2 (|z'_{n+1}|^2 = 4 s^2 |z_n|^2 |z'_n|^2 = |u_n|^2 |z'_n|^2):
// no multiplication by 2 s, and radii compared against thresholds times 4 s^2. Float lanes see c
// as complex (LaneConstants), so u = a + b i + e, e in span{j, k}, maps to ((a^2 - b^2 - |e|^2)
// / 2 + 2 s c.w) + (a b + 2 s c.x) i + a e: e only scales, and a, b and rho = |e|^2 (rho <- a^2
// rho) carry the orbit, 8 operations per iterate with the derivative instead of 13. Only the
// counters want the iteration count; they count the running lanes instead of keeping each
// lane's count. Fills distance, inside and radiusSquared; kOrbit also the trap and the
// iteration count, as estimateLanes does.
//
// The same loop takes real forms sum a_k z^k + c with Group = RealThreeNumbersGroup (the points
// then as z itself, LaneConstants::quaternionFromWorld).
template <bool kOrbit, class Group, size_t K, class D>
HWY_INLINE void estimateThreeNumbers(D d, const LaneConstants<D>& k,
                                     const QuaternionT<hn::Vec<D>> (&u)[K],
                                     const hn::Mask<D> (&live)[K], LaneEstimate<D> (&result)[K],
                                     LaneCounters& counters) {
    using V = hn::Vec<D>;
    using M = hn::Mask<D>;
    using T = hn::TFromD<D>;
    const V one = hn::Set(d, T(1)), half = hn::Set(d, T(0.5));
    const V stopRadius = Group::stopRadius(k), insideRadius = Group::insideRadius(k);
    Group g[K];
    bool allDone = true;
    for (size_t j = 0; j < K; ++j) {
        g[j].start(d, k, u[j], live[j], one);
        allDone = allDone && hn::AllTrue(d, g[j].done);
    }
    const int iterationCap = k.maxIterationCount + kMaxContinuation;
    int64_t runningLanes = 0;
    int n = 1;
    for (; n < iterationCap && !allDone; ++n) {
        allDone = true;
        const bool last = n + 1 >= k.maxIterationCount;  // z_0 .. z_{N-1} tested
        for (size_t j = 0; j < K; ++j) {
            const M doneBefore = g[j].done;
            g[j].iterate(k, hn::Not(doneBefore), half);
            if constexpr (kOrbit) {
                // The trap takes the iterates up to the first past the bailout.
                const auto settled = hn::Or(g[j].escaped, doneBefore);
                g[j].trap = hn::IfThenElse(settled, g[j].trap, hn::Min(g[j].trap, g[j].r2));
                g[j].escaped = hn::Or(g[j].escaped, g[j].r2 > insideRadius);
            }
            const bool groupDone = settleFrozen(d, g[j].r2, stopRadius, insideRadius, last,
                                                g[j].done, g[j].inside, runningLanes);
            if constexpr (kOrbit) {
                g[j].stopIteration = hn::IfThenElse(hn::AndNot(doneBefore, g[j].done),
                                                    hn::Set(d, T(n)), g[j].stopIteration);
            }
            allDone = allDone && groupDone;
        }
    }
    counters.laneIterations += runningLanes;
    for (size_t j = 0; j < K; ++j)
        g[j].template finish<kOrbit>(d, k, n, result[j], counters);
}

// Bicomplex polynomials' estimates (bicomplex_lanes-inl.h, included after this file).
template <bool kOrbit, size_t K, class D>
HWY_INLINE void estimateBicomplex(D d, const LaneConstants<D>& k,
                                  const QuaternionT<hn::Vec<D>> (&q)[K],
                                  const hn::Mask<D> (&live)[K], LaneEstimate<D> (&result)[K],
                                  LaneCounters& counters);

// The estimates at the current points of the rays in the lanes (o + t d, through the slice):
// live lanes, their t, and the estimates. False when no lane holds a ray.
template <bool kQuadratic, size_t K, class D, class T>
HWY_INLINE bool estimateAlongRays(D d, const LaneConstants<D>& k, const RayLanes<T>& rayLanes,
                                  hn::Mask<D> (&live)[K], hn::Vec<D> (&t)[K],
                                  LaneEstimate<D> (&e)[K], LaneCounters& counters) {
    const size_t lanes = hn::Lanes(d);
    QuaternionT<hn::Vec<D>> q[K];
    bool anyLive = false;
    for (size_t j = 0; j < K; ++j) {
        const size_t o = j * lanes;
        live[j] = hn::Load(d, rayLanes.live + o) > hn::Zero(d);
        anyLive = anyLive || !hn::AllFalse(d, live[j]);
        t[j] = hn::Load(d, rayLanes.t + o);
        const auto x = hn::MulAdd(hn::Load(d, rayLanes.dx + o), t[j], hn::Load(d, rayLanes.ox + o));
        const auto y = hn::MulAdd(hn::Load(d, rayLanes.dy + o), t[j], hn::Load(d, rayLanes.oy + o));
        const auto z = hn::MulAdd(hn::Load(d, rayLanes.dz + o), t[j], hn::Load(d, rayLanes.oz + o));
        q[j] = kQuadratic && k.threeNumbers ? k.loopFromWorld(x, y, z)
                                            : k.quaternionFromWorld(x, y, z);
    }
    if (!anyLive) return false;
    if (k.bicomplex) {
        estimateBicomplex<false>(d, k, q, live, e, counters);
    } else if (kQuadratic && k.threeNumbers) {
        estimateThreeNumbers<false, ThreeNumbersGroup<D>>(d, k, q, live, e, counters);
    } else if (!kQuadratic && k.realThreeNumbers) {
        estimateThreeNumbers<false, RealThreeNumbersGroup<D>>(d, k, q, live, e, counters);
    } else {
        estimateLanes<kQuadratic, false>(d, k, q, live, e, counters);
    }
    for (size_t j = 0; j < K; ++j)
        counters.estimates += int64_t(hn::CountTrue(d, live[j]));
    return true;
}

#endif  // QUATERNIA_ESTIMATE_LANES_INL_H_
