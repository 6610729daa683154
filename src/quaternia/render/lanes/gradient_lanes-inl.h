// The analytic gradient of the potential in SIMD lanes (QuaternionJuliaSet::potentialGradient): the
// slice's three axes carried through the Jacobians of the iterates, for potentialNormalLanes
// (march_lanes-inl.h). Two forms: three numbers for float lanes of s z^2 + c, quaternions for
// the rest.
//
// Like estimate_lanes-inl.h, this file has no namespace of its own: march_lanes-inl.h includes it
// inside its per-target namespace, once per SIMD target, after estimate_lanes-inl.h.

#if defined(QUATERNIA_GRADIENT_LANES_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef QUATERNIA_GRADIENT_LANES_INL_H_
#undef QUATERNIA_GRADIENT_LANES_INL_H_
#else
#define QUATERNIA_GRADIENT_LANES_INL_H_
#endif

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
// the three tangents instead of about 50.
template <class D>
struct ThreeNumberTangents {
    using V = hn::Vec<D>;
    V a, b, p;              // u
    V dA[3], dB[3], dR[3];  // the slice's three axes carried through the Jacobians

    ThreeNumberTangents(const LaneConstants<D>& k, V x, V y, V z) {
        const QuaternionT<V> u = k.loopFromWorld(x, y, z);
        a = u.w, b = u.x, p = hn::MulAdd(u.z, u.z, u.y * u.y);
        QuaternionT<V> axes[3];
        k.tangentsAt(x, y, z, true, axes);
        for (int i = 0; i < 3; ++i) {
            dA[i] = axes[i].w, dB[i] = axes[i].x;
            dR[i] = hn::MulAdd(u.z, axes[i].z, u.y * axes[i].y);
        }
    }

    // One iterate, from aa = A^2 and rest = B^2 + P (as estimateThreeNumbers has them: the
    // same operations, so that |u|^2 = aa + rest rounds alike); hold(next, old) as in
    // iterateEachLaneItsCount.
    template <class Hold>
    HWY_INLINE void iterate(D d, const LaneConstants<D>& k, V aa, V rest, const Hold& hold) {
        using T = hn::TFromD<D>;
        const V half = hn::Set(d, T(0.5)), one = hn::Set(d, T(1));
        const V large = hn::Set(d, T(1e30)), shrink = hn::Set(d, T(1e-10));
        for (int i = 0; i < 3; ++i) {
            const V nextA = hn::MulSub(a, dA[i], hn::MulAdd(b, dB[i], dR[i]));
            const V nextB = hn::MulAdd(a, dB[i], b * dA[i]);
            const V nextR = a * hn::MulAdd(p, dA[i], a * dR[i]);
            dA[i] = hold(nextA, dA[i]), dB[i] = hold(nextB, dB[i]), dR[i] = hold(nextR, dR[i]);
        }
        const V nextA = hn::MulAdd(half, aa - rest, k.scaledC);
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
    }

    // The gradient of |u|^2 / 2 along the slice's axes.
    void gradient(V& gx, V& gy, V& gz) const {
        gx = hn::MulAdd(a, dA[0], hn::MulAdd(b, dB[0], dR[0]));
        gy = hn::MulAdd(a, dA[1], hn::MulAdd(b, dB[1], dR[1]));
        gz = hn::MulAdd(a, dA[2], hn::MulAdd(b, dB[2], dR[2]));
    }
};

// The three-number gradient after M_i iterates in lane i (the lanes of m).
template <class D, class V = hn::Vec<D>>
HWY_INLINE void threeNumberGradient(D d, const LaneConstants<D>& k, V x, V y, V z, V m, int fewest,
                                    int most, V& gx, V& gy, V& gz, LaneCounters& counters) {
    ThreeNumberTangents<D> tangents(k, x, y, z);
    iterateEachLaneItsCount(d, m, fewest, most, counters, [&](const auto& hold) {
        const V aa = tangents.a * tangents.a;
        tangents.iterate(d, k, aa, hn::MulAdd(tangents.b, tangents.b, tangents.p), hold);
    });
    tangents.gradient(gx, gy, gz);
}

// The three-number gradient where each lane's M is the iteration count that its estimate
// reaches (estimateThreeNumbers' stopping rule, on the same numbers: past the estimate radius,
// or inside after N - 1 iterates), found on the way: the hit's estimate is not needed for its
// normal. Lanes stop where the rule stops them (merge-masked, as settleFrozen's loops).
template <class D, class V = hn::Vec<D>, class M = hn::Mask<D>>
HWY_INLINE void threeNumberGradientToItsCount(D d, const LaneConstants<D>& k, V x, V y, V z, M live,
                                              V& gx, V& gy, V& gz, LaneCounters& counters) {
    ThreeNumberTangents<D> tangents(k, x, y, z);
    V aa = tangents.a * tangents.a, rest = hn::MulAdd(tangents.b, tangents.b, tangents.p);
    M escaped, done, inside;
    startLanes(d, aa + rest, live, k.scaledBailoutSquared, k.scaledEscapeRadiusSquared,
               k.scaledEstimateRadiusSquared, k.maxIterationCount, escaped, done, inside);
    const int iterationCap = k.maxIterationCount + kMaxContinuation;
    int64_t running = 0;
    int n = 1;
    for (; n < iterationCap && !hn::AllTrue(d, done); ++n) {
        const M moving = hn::Not(done);
        tangents.iterate(d, k, aa, rest, [&](const V& next, const V& old) {
            return hn::IfThenElse(moving, next, old);
        });
        aa = tangents.a * tangents.a;
        rest = hn::MulAdd(tangents.b, tangents.b, tangents.p);
        settleFrozen(d, aa + rest, k.scaledEstimateRadiusSquared, k.scaledBailoutSquared,
                     n + 1 >= k.maxIterationCount, done, inside, running);
    }
    counters.laneIterations += running;
    counters.laneSlots += int64_t(hn::Lanes(d)) * int64_t(n - 1);
    tangents.gradient(gx, gy, gz);
}

// One iterate of a real form p(z) = sum a_k z^k + c (LaneConstants::realCoefficients) and of
// three tangents through its Jacobian. With z = a + v and s2 = |v|^2, p(z) - c = X + Y v for
// X, Y functions of a and s2 (estimate_lanes-inl.h, RealThreeNumbersGroup), so
// Dp(z)[h] = (X_a h0 + X_s ds2) + (Y_a h0 + Y_s ds2) v + Y hv, ds2 = 2 v . hv: the four
// partial derivatives come once per iterate from Horner's rule (forward mode), and each tangent
// costs a dozen operations instead of the quaternion products of the product rule.
template <class D, class V = hn::Vec<D>>
HWY_INLINE void realFormStep(const LaneConstants<D>& k, QuaternionT<V>& z, QuaternionT<V> (&t)[3]) {
    const LaneVector<V>& coefficient = k.realCoefficients;
    const std::size_t degree = coefficient.size() - 1;
    const V a = z.w, s2 = hn::MulAdd(z.x, z.x, hn::MulAdd(z.y, z.y, z.z * z.z));
    V x = hn::MulAdd(coefficient[degree], a, coefficient[degree - 1]), y = coefficient[degree];
    V xa = coefficient[degree], ya = hn::Zero(D()), xs = hn::Zero(D()), ys = hn::Zero(D());
    for (std::size_t n = degree - 1; n-- > 0;) {
        const V nextXa = hn::NegMulAdd(s2, ya, hn::MulAdd(xa, a, x));
        const V nextXs = hn::NegMulAdd(s2, ys, hn::MulSub(xs, a, y));
        const V nextYa = hn::MulAdd(ya, a, xa + y);
        const V nextYs = hn::MulAdd(ys, a, xs);
        const V nextX = hn::NegMulAdd(s2, y, hn::MulAdd(x, a, coefficient[n]));
        y = hn::MulAdd(y, a, x);
        x = nextX;
        xa = nextXa, xs = nextXs, ya = nextYa, ys = nextYs;
    }
    for (QuaternionT<V>& h : t) {
        const V ds2 = (hn::MulAdd(z.x, h.x, hn::MulAdd(z.y, h.y, z.z * h.z))) * hn::Set(D(), 2);
        const V dx = hn::MulAdd(xa, h.w, xs * ds2), dy = hn::MulAdd(ya, h.w, ys * ds2);
        h = {dx, hn::MulAdd(dy, z.x, y * h.x), hn::MulAdd(dy, z.y, y * h.y),
             hn::MulAdd(dy, z.z, y * h.z)};
    }
    z = {x + k.c.w, hn::MulAdd(y, z.x, k.c.x), hn::MulAdd(y, z.y, k.c.y),
         hn::MulAdd(y, z.z, k.c.z)};
}

// Tangents carried through many Jacobians grow without bound, and only their direction is used:
// the factor that shrinks them in the lanes whose largest squared tangent passed a threshold
// near the type's range (1 elsewhere); false, and no factor, where no lane needs it.
template <class D, class V = hn::Vec<D>>
HWY_INLINE bool tangentShrink(D d, V largestSquared, V& factor) {
    using T = hn::TFromD<D>;
    constexpr T kLarge = sizeof(T) == 4 ? T(1e30) : T(1e200);
    constexpr T kShrink = sizeof(T) == 4 ? T(1e-10) : T(1e-100);
    const auto huge = largestSquared > hn::Set(d, kLarge);
    if (hn::AllFalse(d, huge)) return false;
    factor = hn::IfThenElse(huge, hn::Set(d, kShrink), hn::Set(d, T(1)));
    return true;
}

// potentialNormalLanes' gradient in quaternions, for any s z^d + c or program in float or double:
// the three tangents of the slice carried through the Jacobian of p at each iterate (the chain
// rule), and their inner products with z_M.
template <bool kQuadratic, class D, class V = hn::Vec<D>>
HWY_INLINE void quaternionGradient(D d, const LaneConstants<D>& k, V x, V y, V z0, V m, int fewest,
                                   int most, V& gx, V& gy, V& gz, LaneCounters& counters) {
    // Only the direction matters: rescale all three together before they overflow.
    auto rescale = [&](QuaternionT<V>& t0, QuaternionT<V>& t1, QuaternionT<V>& t2) {
        V largest = hn::Max(normSquaredPairwise(t0),
                            hn::Max(normSquaredPairwise(t1), normSquaredPairwise(t2)));
        V factor;
        if (tangentShrink(d, largest, factor)) {
            t0 = t0 * factor;
            t1 = t1 * factor;
            t2 = t2 * factor;
        }
    };
    auto z = k.quaternionFromWorld(x, y, z0);
    QuaternionT<V> axes[3];
    k.tangentsAt(x, y, z0, false, axes);
    QuaternionT<V> t0 = axes[0], t1 = axes[1], t2 = axes[2];
    // One iteration of the point and the tangents (iterateEachLaneItsCount's `hold`).
    iterateEachLaneItsCount(d, m, fewest, most, counters, [&](const auto& hold) {
        QuaternionT<V> n0, n1, n2, nz;
        if (!kQuadratic && k.realForm) {
            QuaternionT<V> next[3] = {t0, t1, t2};
            nz = z;
            realFormStep(k, nz, next);
            n0 = next[0], n1 = next[1], n2 = next[2];
        } else if (!kQuadratic && k.program) {
            const QuaternionT<V> h[3] = {t0, t1, t2};
            QuaternionT<V> next[3];
            nz = k.program.stepWithTangents(d, z, h, next);
            n0 = next[0], n1 = next[1], n2 = next[2];
        } else if constexpr (kQuadratic) {
            n0 = quadraticDerivative(z, t0, k.scale);
            n1 = quadraticDerivative(z, t1, k.scale);
            n2 = quadraticDerivative(z, t2, k.scale);
            nz = quadraticStep(z, k.scale, k.c);
        } else {
            n0 = powerDerivative(z, t0, k.degree, k.scale);
            n1 = powerDerivative(z, t1, k.degree, k.scale);
            n2 = powerDerivative(z, t2, k.degree, k.scale);
            nz = powerStep(z, k.degree, k.scale, k.c);
        }
        t0 = hold(n0, t0), t1 = hold(n1, t1), t2 = hold(n2, t2), z = hold(nz, z);
        rescale(t0, t1, t2);
    });
    gx = dot(z, t0), gy = dot(z, t1), gz = dot(z, t2);
}

#endif  // QUATERNIA_GRADIENT_LANES_INL_H_
