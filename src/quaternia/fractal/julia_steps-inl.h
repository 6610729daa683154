// The iteration formulas of the hot loops, written once for any lane type V: plain double in the
// scalar reference (distance.cpp) and Highway SIMD vectors of float or double in the packet
// kernels (march_lanes.cpp). Only +, - and * are used, so every V with those operators runs
// the same formula; Hamilton's product and the square follow quaternion.h (eqs. 2.7-2.9 of the
// seed paper).
//
// Like Highway's own -inl.h headers, this file has no namespace of its own and is included
// inside one: once per SIMD target by foreach_target (the HWY_TARGET_TOGGLE guard below lets it
// in again for each target), and once into namespace quaternia for the scalar code.

#if defined(QUATERNIA_JULIA_LANES_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef QUATERNIA_JULIA_LANES_INL_H_
#undef QUATERNIA_JULIA_LANES_INL_H_
#else
#define QUATERNIA_JULIA_LANES_INL_H_
#endif

// A quaternion w + x i + y j + z k whose components are lanes.
template <class V>
struct QuaternionLanes {
    V w, x, y, z;
};

// Summed as a tree, (w^2 + x^2) + (y^2 + z^2): the iteration loops are bound by the latency of
// this chain, which a left-to-right sum makes one multiply-add longer.
template <class V>
inline V normSquaredLanes(const QuaternionLanes<V>& q) {
    return (q.w * q.w + q.x * q.x) + (q.y * q.y + q.z * q.z);
}

template <class V>
inline V dotLanes(const QuaternionLanes<V>& a, const QuaternionLanes<V>& b) {
    return a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
}

// Hamilton product.
template <class V>
inline QuaternionLanes<V> multiplyLanes(const QuaternionLanes<V>& a, const QuaternionLanes<V>& b) {
    return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
            a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
            a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
            a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

// s z^2 + c with z^2 = (w^2 - |v|^2) + 2 w v: the hot case, about 14 operations.
template <class V>
inline QuaternionLanes<V> quadraticStepLanes(const QuaternionLanes<V>& z, V scale,
                                             const QuaternionLanes<V>& c) {
    V twoScaleW = (scale + scale) * z.w;
    return {scale * ((z.w * z.w - z.x * z.x) - (z.y * z.y + z.z * z.z)) + c.w,
            twoScaleW * z.x + c.x, twoScaleW * z.y + c.y, twoScaleW * z.z + c.z};
}

// s z^d + c for d >= 1, by d - 1 Hamilton products.
template <class V>
inline QuaternionLanes<V> powerStepLanes(const QuaternionLanes<V>& z, int degree, V scale,
                                         const QuaternionLanes<V>& c) {
    QuaternionLanes<V> p = z;
    for (int k = 1; k < degree; ++k)
        p = multiplyLanes(p, z);
    return {scale * p.w + c.w, scale * p.x + c.x, scale * p.y + c.y, scale * p.z + c.z};
}

// The derivative of s z^2 at z applied to h: s (z h + h z). Quaternions do not commute, so this
// is not 2 s z h; it is 2 s (z_w h + h_w v_z) - 2 s (v_z . v_h) in components.
template <class V>
inline QuaternionLanes<V> quadraticDerivativeLanes(const QuaternionLanes<V>& z,
                                                   const QuaternionLanes<V>& h, V scale) {
    V twoScale = scale + scale;
    V zw = twoScale * z.w, hw = twoScale * h.w;
    return {zw * h.w - twoScale * (z.x * h.x + z.y * h.y + z.z * h.z), zw * h.x + hw * z.x,
            zw * h.y + hw * z.y, zw * h.z + hw * z.z};
}

// The derivative of s z^d at z applied to h, for d <= kMaxLaneDegree (distance.h): s
// sum_{k=0}^{d-1} z^k h z^(d-1-k) (the product rule; the factors do not commute).
template <class V>
inline QuaternionLanes<V> powerDerivativeLanes(const QuaternionLanes<V>& z,
                                               const QuaternionLanes<V>& h, int degree, V scale) {
    QuaternionLanes<V> sum = h;  // d = 1
    if (degree >= 2) {
        // powers[k] = z^k for 1 <= k < d; the terms k = 0 and k = d - 1 have a factor 1.
        QuaternionLanes<V> powers[kMaxLaneDegree];
        powers[1] = z;
        for (int k = 2; k < degree; ++k)
            powers[k] = multiplyLanes(powers[k - 1], z);
        sum = multiplyLanes(h, powers[degree - 1]);
        QuaternionLanes<V> last = multiplyLanes(powers[degree - 1], h);
        sum = {sum.w + last.w, sum.x + last.x, sum.y + last.y, sum.z + last.z};
        for (int k = 1; k + 1 < degree; ++k) {
            QuaternionLanes<V> term =
                multiplyLanes(multiplyLanes(powers[k], h), powers[degree - 1 - k]);
            sum = {sum.w + term.w, sum.x + term.x, sum.y + term.y, sum.z + term.z};
        }
    }
    return {scale * sum.w, scale * sum.x, scale * sum.y, scale * sum.z};
}

#endif  // QUATERNIA_JULIA_LANES_INL_H_
