// Bicomplex polynomials in SIMD lanes (LaneFractal::bicomplex): HypercomplexJuliaSet's
// bicomplexEstimate and potentialGradient (hypercomplex_julia.cpp) for K vectors of points at
// once. The points arrive in duplex coordinates (a, b) = duplexForm(q), in the (w, x) and (y, z)
// slots of a QuaternionT (LaneFractal::fromBicomplex composes the slice with that linear map),
// where the polynomial acts as two complex polynomials, one per component: z^2 + c costs two
// complex squares, and |q|^2 = (|a|^2 + |b|^2) / 2 decides membership in K_N.
//
// Like estimate_lanes-inl.h, this file has no namespace of its own: march_lanes-inl.h includes it
// inside its per-target namespace, once per SIMD target, after estimate_lanes-inl.h and
// gradient_lanes-inl.h.

#if defined(QUATERNIA_BICOMPLEX_LANES_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef QUATERNIA_BICOMPLEX_LANES_INL_H_
#undef QUATERNIA_BICOMPLEX_LANES_INL_H_
#else
#define QUATERNIA_BICOMPLEX_LANES_INL_H_
#endif

// Duplex component i's polynomial at w = wr + wi i by Horner's rule, its value into (pr, pi) and
// its derivative into (qr, qi); w^2 + c_i (LaneConstants::bicomplexSquare) by its own lines.
template <class D, class V = hn::Vec<D>>
HWY_INLINE void bicomplexValue(D d, const LaneConstants<D>& k, size_t i, V wr, V wi, V& pr, V& pi,
                               V& qr, V& qi) {
    const LaneVector<V>& re = k.bicomplexReal[i];
    const LaneVector<V>& im = k.bicomplexImaginary[i];
    if (k.bicomplexSquare) {
        qr = wr + wr, qi = wi + wi;
        pr = hn::MulSub(wr, wr, hn::MulSub(wi, wi, re[0]));
        pi = hn::MulAdd(qr, wi, im[0]);
        return;
    }
    const size_t degree = re.size() - 1;
    pr = re[degree], pi = im[degree];
    qr = hn::Zero(d), qi = hn::Zero(d);
    for (size_t j = degree; j-- > 0;) {
        // p' <- p' w + p, then p <- p w + c_j
        const V nqr = hn::MulSub(qr, wr, hn::MulSub(qi, wi, pr));
        qi = hn::MulAdd(qr, wi, hn::MulAdd(qi, wr, pi));
        qr = nqr;
        const V npr = hn::MulSub(pr, wr, hn::MulSub(pi, wi, re[j]));
        pi = hn::MulAdd(pr, wi, hn::MulAdd(pi, wr, im[j]));
        pr = npr;
    }
}

// How many iterates of a disconnected component's orbit the lanes keep for the pull-back
// (BicomplexComponent::distance); a lane that needs a deeper one asks the scalar reference.
inline constexpr int kPullBackOrbit = 64;

// One duplex component's orbit in estimateBicomplex: w, |w|^2, the running |w'|^2 (exact: the
// complex derivative is multiplicative), and both where the component's estimate was taken.
template <class D>
struct BicomplexComponent {
    using V = hn::Vec<D>;
    V wr, wi, r2, s2, stopR2, stopS2, stopN;  // stopN: the iterate where the estimate was taken
    hn::Mask<D> done;

    HWY_INLINE void start(D d, V re, V im, hn::Mask<D> live) {
        wr = re, wi = im;
        r2 = hn::MulAdd(wi, wi, wr * wr);
        s2 = stopS2 = hn::Set(d, hn::TFromD<D>(1));
        stopR2 = r2;
        stopN = hn::Zero(d);
        done = hn::Not(live);
    }
    HWY_INLINE void iterate(D d, const LaneConstants<D>& k, size_t i) {
        V pr, pi, qr, qi;
        bicomplexValue(d, k, i, wr, wi, pr, pi, qr, qi);
        s2 = s2 * hn::MulAdd(qi, qi, qr * qr);
        wr = pr, wi = pi;
        r2 = hn::MulAdd(wi, wi, wr * wr);
    }
    // After n iterates, for a lane whose |q| escaped (or that is inside): a component beyond its
    // escape radius stops at the estimate radius; one within it runs until N iterates were
    // taken (it may still escape), as the scalar reference's continuation does.
    HWY_INLINE void settle(D d, const LaneConstants<D>& k, size_t i, int n, hn::Mask<D> escaped,
                           hn::Mask<D> inside) {
        const auto certain = r2 > k.componentEscapeRadiusSquared[i];
        auto finished = hn::And(certain, r2 >= k.estimateRadiusSquared);
        if (n + 1 >= k.maxIterationCount) finished = hn::Or(finished, hn::Not(certain));
        const auto stopNow = hn::AndNot(done, hn::Or(inside, hn::And(escaped, finished)));
        stopR2 = hn::IfThenElse(stopNow, r2, stopR2);
        stopS2 = hn::IfThenElse(stopNow, s2, stopS2);
        stopN = hn::IfThenElse(stopNow, hn::Set(d, hn::TFromD<D>(n)), stopN);
        done = hn::Or(done, stopNow);
    }
    // 0.25 |w| ln|w|^2 / |w'|, or 0 where the component did not escape for certain (in K_i).
    // For a disconnected K_i (duplex_component.h) times (e^G - e^G*) / (e^G - 1), G the
    // potential ((ln|w| + ln|a_d| / (d - 1)) / d^n); lanes below 2 G* are pulled back from the
    // first iterate above it (pullBack), through the orbit's moduli and slopes kept in `orbit`
    // for the first kPullBackOrbit iterates; lanes beyond those, or of a component that is not
    // binomial, are left in `reference` for the scalar reference.
    HWY_INLINE V distance(D d, const LaneConstants<D>& k, size_t i, const V (*orbit)[2],
                          hn::Mask<D>& reference) const {
        using T = hn::TFromD<D>;
        const V radiusSquared = hn::IfThenElse(done, stopR2, r2);
        const V slopeSquared = hn::IfThenElse(done, stopS2, s2);
        const auto escaped = radiusSquared > k.componentEscapeRadiusSquared[i];
        const V estimate = hn::IfThenElseZero(
            escaped, closingDistance(d, radiusSquared, slopeSquared, hn::Set(d, T(1))));
        if (k.componentConnected[i]) return estimate;
        const V iterate = hn::IfThenElse(done, stopN, hn::Set(d, T(k.maxIterationCount)));
        const V level = hn::MulAdd(hn::Set(d, T(0.5)), hn::Log(d, radiusSquared), k.leadLog[i]);
        const V potential =
            hn::Max(level, hn::Zero(d)) * hn::Exp(d, hn::Neg(iterate * k.logDegree));
        const V twice = k.criticalPotential[i] + k.criticalPotential[i];
        const V direct =
            hn::IfThenElseZero(potential >= twice, estimate * koebe(d, k, i, potential));
        const auto below = hn::AndNot(potential >= twice, escaped);
        if (hn::AllFalse(d, below)) return direct;
        if (!k.componentBinomial[i]) {
            reference = hn::Or(reference, below);
            return direct;
        }
        // j: the first iterate with d^j G >= 2 G* (at least 1, at most the stop), then
        // r_j = estimate |w'_j| koebe(d^j G), pulled back by Q's inverse growth to iterate 0.
        // (as DuplexComponent::distance finds it: the potential times d until it reaches 2 G*)
        const V degree = hn::Set(d, T(k.degree)), one = hn::Set(d, T(1));
        V j = hn::Zero(d), lifted = potential;
        for (int m = 0; m < kPullBackOrbit; ++m) {
            const auto grow = hn::And(below, hn::And(lifted < twice, j < iterate));
            if (hn::AllFalse(d, grow)) break;
            lifted = hn::IfThenElse(grow, lifted * degree, lifted);
            j = hn::IfThenElse(grow, j + one, j);
        }
        const V kept = hn::Set(d, T(kPullBackOrbit - 1));
        reference = hn::Or(reference, hn::And(below, j > kept));
        const auto shallow = hn::And(below, hn::And(j <= kept, j <= k.pullBackLimit[i]));
        if (hn::AllFalse(d, shallow)) return direct;
        const V atJ = estimate * koebe(d, k, i, lifted);
        const int deepest = int(hn::GetLane(hn::MaxOfLanes(d, hn::IfThenElseZero(shallow, j))));
        V bound = hn::Zero(d);
        for (int m = deepest; m >= 0; --m) {
            const V index = hn::Set(d, T(m));
            bound = hn::IfThenElse(j == index, atJ * hn::Sqrt(orbit[m][1]), bound);
            bound = hn::IfThenElse(
                index < j, growthInverse(d, k, hn::Sqrt(orbit[m][0]), bound * k.inverseLead[i]),
                bound);
        }
        return hn::IfThenElse(below, hn::IfThenElseZero(shallow, bound), direct);
    }
    // (e^G - e^G*) / (e^G - 1) for G >= 2 G* (duplex_component.h, koebeFactor).
    HWY_INLINE static V koebe(D d, const LaneConstants<D>& k, size_t i, V potential) {
        const V whole = hn::Expm1(d, potential);
        return (whole - k.expm1Critical[i]) / hn::Max(whole, hn::Set(d, hn::TFromD<D>(1e-30)));
    }
    // DuplexComponent::binomialGrowthInverse in lanes, with a margin for float rounding.
    HWY_INLINE static V growthInverse(D d, const LaneConstants<D>& k, V r, V x) {
        using T = hn::TFromD<D>;
        const int degree = k.degree;
        V rPower = hn::Set(d, T(1));
        for (int m = 0; m < degree; ++m)
            rPower = rPower * r;
        const V total = rPower + x;
        const V s = degree == 2 ? hn::Sqrt(total)
                                : hn::Exp(d, hn::Log(d, total) * hn::Set(d, T(1.0 / degree)));
        // sum_{m < d} s^m r^(d-1-m), by Horner in s over the powers of r
        V sum = hn::Zero(d), rPart = hn::Set(d, T(1));
        for (int m = 0; m < degree; ++m) {
            sum = hn::MulAdd(sum, s, rPart);  // (rPart grows as r^m while s's power falls)
            rPart = rPart * r;
        }
        const T margin = sizeof(T) == 4 ? T(1e-4) : T(1e-12);  // the scalar reference's in double
        const V e = x / hn::Max(sum, hn::Set(d, T(1e-30))) * hn::Set(d, T(1) - margin);
        return hn::IfThenElseZero(x > hn::Zero(d), e);
    }
};

// The lanes of `pullBack`: the scalar reference's estimate of each point (in double; the
// duplex coordinates back to the algebra), in the lanes' units.
template <class D>
HWY_NOINLINE hn::Vec<D> pulledBackDistance(D d, const LaneConstants<D>& k,
                                           const QuaternionT<hn::Vec<D>>& q, hn::Mask<D> pullBack,
                                           hn::Vec<D> distance) {
    using T = hn::TFromD<D>;
    constexpr size_t kMax = kLaneCapacity<float>;
    const size_t lanes = hn::Lanes(d);
    T a[kMax], b[kMax], c[kMax], e[kMax], out[kMax];
    hn::StoreU(q.w, d, a), hn::StoreU(q.x, d, b), hn::StoreU(q.y, d, c), hn::StoreU(q.z, d, e);
    hn::StoreU(distance, d, out);
    uint8_t bits[kMax / 8 + 1] = {};
    hn::StoreMaskBits(d, pullBack, bits);
    for (size_t lane = 0; lane < lanes; ++lane) {
        if (!(bits[lane / 8] >> (lane % 8) & 1)) continue;
        const Hypercomplex z = fromDuplexForm(std::complex<double>(a[lane], b[lane]),
                                              std::complex<double>(c[lane], e[lane]));
        out[lane] = T(k.bicomplexReference->estimate(z).distance);
    }
    return hn::LoadU(d, out);
}

// HypercomplexJuliaSet::bicomplexEstimate in lanes: both components iterate while |q| <= bailout
// and fewer than N iterates were tested; after |q| escaped each continues on its own (above),
// and the distance is sqrt((d_1^2 + d_2^2) / 2) from the two complex estimates (0 inside K_N).
// LaneFractal::fromBicomplex takes only bailouts under which an escape of |q| is one of some
// component, so the scalar reference's Lipschitz fallback is never needed. kOrbit also keeps the
// trap (least |q|^2 up to the escape), the escape iteration and |q|^2 there: the smooth count
// and the normal's M are then the scalar reference's.
template <bool kOrbit, size_t K, class D>
HWY_INLINE void estimateBicomplex(D d, const LaneConstants<D>& k,
                                  const QuaternionT<hn::Vec<D>> (&q)[K],
                                  const hn::Mask<D> (&live)[K], LaneEstimate<D> (&result)[K],
                                  LaneCounters& counters) {
    using V = hn::Vec<D>;
    using M = hn::Mask<D>;
    using T = hn::TFromD<D>;
    const V half = hn::Set(d, T(0.5));
    BicomplexComponent<D> a[K], b[K];
    // |w_n|^2 and |w'_n|^2 of the first iterates, for the pull-back of disconnected components.
    V orbitA[K][kPullBackOrbit][2], orbitB[K][kPullBackOrbit][2];
    const bool keepOrbit = !k.componentConnected[0] || !k.componentConnected[1];
    V trap[K], escapeIteration[K], escapeRadiusSquared[K];
    M escaped[K], inside[K];
    bool allDone = true;
    for (size_t j = 0; j < K; ++j) {
        a[j].start(d, q[j].w, q[j].x, live[j]);
        b[j].start(d, q[j].y, q[j].z, live[j]);
        const V q2 = half * (a[j].r2 + b[j].r2);
        escaped[j] = hn::And(live[j], q2 > k.bailoutSquared);
        inside[j] = k.maxIterationCount <= 1 ? hn::AndNot(escaped[j], live[j]) : hn::FirstN(d, 0);
        trap[j] = escapeRadiusSquared[j] = q2;
        escapeIteration[j] = hn::Zero(d);
        a[j].settle(d, k, 0, 0, escaped[j], inside[j]);
        b[j].settle(d, k, 1, 0, escaped[j], inside[j]);
        if (keepOrbit) {
            orbitA[j][0][0] = a[j].r2, orbitA[j][0][1] = a[j].s2;
            orbitB[j][0][0] = b[j].r2, orbitB[j][0][1] = b[j].s2;
        }
        allDone = allDone && hn::AllTrue(d, hn::And(a[j].done, b[j].done));
    }
    const int64_t lanes = int64_t(hn::Lanes(d));
    const int iterationCap = k.maxIterationCount + kMaxContinuation;
    for (int n = 1; n < iterationCap && !allDone; ++n) {
        allDone = true;
        const V iteration = hn::Set(d, T(n));
        for (size_t j = 0; j < K; ++j) {
            counters.laneIterations +=
                int64_t(hn::CountTrue(d, hn::Not(hn::And(a[j].done, b[j].done))));
            counters.laneSlots += lanes;
            a[j].iterate(d, k, 0);
            b[j].iterate(d, k, 1);
            if (keepOrbit && n < kPullBackOrbit) {
                orbitA[j][n][0] = a[j].r2, orbitA[j][n][1] = a[j].s2;
                orbitB[j][n][0] = b[j].r2, orbitB[j][n][1] = b[j].s2;
            }
            const M pending = hn::AndNot(hn::Or(escaped[j], inside[j]), live[j]);
            const V q2 = half * (a[j].r2 + b[j].r2);
            if constexpr (kOrbit) trap[j] = hn::IfThenElse(pending, hn::Min(trap[j], q2), trap[j]);
            const M escapedNow = hn::And(pending, q2 > k.bailoutSquared);
            escaped[j] = hn::Or(escaped[j], escapedNow);
            if constexpr (kOrbit) {
                escapeIteration[j] = hn::IfThenElse(escapedNow, iteration, escapeIteration[j]);
                escapeRadiusSquared[j] = hn::IfThenElse(escapedNow, q2, escapeRadiusSquared[j]);
            }
            if (n + 1 >= k.maxIterationCount)
                inside[j] = hn::Or(inside[j], hn::AndNot(escaped[j], pending));
            a[j].settle(d, k, 0, n, escaped[j], inside[j]);
            b[j].settle(d, k, 1, n, escaped[j], inside[j]);
            allDone = allDone && hn::AllTrue(d, hn::And(a[j].done, b[j].done));
        }
    }
    for (size_t j = 0; j < K; ++j) {
        M pullBack = hn::FirstN(d, 0);
        const V da = a[j].distance(d, k, 0, orbitA[j], pullBack),
                db = b[j].distance(d, k, 1, orbitB[j], pullBack);
        result[j].inside = inside[j];
        V distance = hn::Sqrt(half * hn::MulAdd(da, da, db * db));
        pullBack = hn::AndNot(inside[j], hn::And(pullBack, live[j]));
        if (!hn::AllFalse(d, pullBack))
            distance = pulledBackDistance(d, k, q[j], pullBack, distance);
        result[j].distance = hn::IfThenZeroElse(inside[j], distance) * k.stepScale;
        result[j].trapSquared = trap[j];
        result[j].iterations = hn::IfThenElse(inside[j], k.maxIterations, escapeIteration[j]);
        result[j].radiusSquared = escapeRadiusSquared[j];
    }
}

// potentialNormalLanes' gradient for bicomplex polynomials: the gradient of |q_M|^2 =
// (|a_M|^2 + |b_M|^2) / 2 along the slice's axes. Each component is complex analytic, so its
// Jacobian is multiplication by the complex derivative w'_M = dw_M / dw_0, and along an axis
// whose duplex image is (A, B) the gradient is Re(conj(a_M) a'_M A) + Re(conj(b_M) b'_M B): the
// direction of HypercomplexJuliaSet::potentialGradient, M at least 1 as there.
template <class D, class V = hn::Vec<D>>
HWY_INLINE void bicomplexGradient(D d, const LaneConstants<D>& k, V x, V y, V z, V m, int fewest,
                                  int most, V& gx, V& gy, V& gz, LaneCounters& counters) {
    const V one = hn::Set(d, hn::TFromD<D>(1));
    const QuaternionT<V> q = k.quaternionFromWorld(x, y, z);
    V wr[2] = {q.w, q.y}, wi[2] = {q.x, q.z};
    V sr[2] = {one, one}, si[2] = {hn::Zero(d), hn::Zero(d)};
    iterateEachLaneItsCount(d, hn::Max(m, one), std::max(1, fewest), std::max(1, most), counters,
                            [&](const auto& hold) {
                                for (size_t i = 0; i < 2; ++i) {
                                    V pr, pi, qr, qi;
                                    bicomplexValue(d, k, i, wr[i], wi[i], pr, pi, qr, qi);
                                    const V nsr = hn::MulSub(qr, sr[i], qi * si[i]);
                                    const V nsi = hn::MulAdd(qr, si[i], qi * sr[i]);
                                    sr[i] = hold(nsr, sr[i]), si[i] = hold(nsi, si[i]);
                                    wr[i] = hold(pr, wr[i]), wi[i] = hold(pi, wi[i]);
                                }
                                // Only the direction matters: rescale both together.
                                const V largest = hn::Max(hn::MulAdd(si[0], si[0], sr[0] * sr[0]),
                                                          hn::MulAdd(si[1], si[1], sr[1] * sr[1]));
                                V factor;
                                if (tangentShrink(d, largest, factor)) {
                                    for (size_t i = 0; i < 2; ++i)
                                        sr[i] = sr[i] * factor, si[i] = si[i] * factor;
                                }
                            });
    // t = conj(w) w', and Re(t A) = t.r A.r - t.i A.i per component.
    V tr[2], ti[2];
    for (size_t i = 0; i < 2; ++i) {
        tr[i] = hn::MulAdd(wi[i], si[i], wr[i] * sr[i]);
        ti[i] = hn::MulSub(wr[i], si[i], wi[i] * sr[i]);
    }
    auto along = [&](const QuaternionT<V>& axis) {
        return hn::MulSub(tr[1], axis.y, ti[1] * axis.z) +
               hn::MulSub(tr[0], axis.w, ti[0] * axis.x);
    };
    gx = along(k.axis0), gy = along(k.axis1), gz = along(k.axis2);
}

#endif  // QUATERNIA_BICOMPLEX_LANES_INL_H_
