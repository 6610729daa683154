// The iteration formulas of the hot loops, written once for quaternions QuaternionT<V>
// (quaternion.h) of any component type V: plain double in the scalar reference (distance.cpp)
// and Highway SIMD vectors of float or double in the lanes (render/lanes/march_lanes-inl.h). Only
// +, - and * are used, so every V with those operators runs the same formula; Hamilton's product
// is quaternion.h's operator* (eqs. 2.7-2.9 of the seed paper).
//
// Like Highway's own -inl.h headers, this file has no namespace of its own and is included
// inside one: once per SIMD target by foreach_target (the HWY_TARGET_TOGGLE guard below lets it
// in again for each target), after quaternion_arithmetic-inl.h, and once into namespace
// quaternia for the scalar code.

#if defined(QUATERNIA_JULIA_STEPS_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef QUATERNIA_JULIA_STEPS_INL_H_
#undef QUATERNIA_JULIA_STEPS_INL_H_
#else
#define QUATERNIA_JULIA_STEPS_INL_H_
#endif

// s z^2 + c with z^2 = (w^2 - |v|^2) + 2 w v: the hot case, about 14 operations.
template <class V>
inline QuaternionT<V> quadraticStep(const QuaternionT<V>& z, V scale, const QuaternionT<V>& c) {
    V twoScaleW = (scale + scale) * z.w;
    return {scale * ((z.w * z.w - z.x * z.x) - (z.y * z.y + z.z * z.z)) + c.w,
            twoScaleW * z.x + c.x, twoScaleW * z.y + c.y, twoScaleW * z.z + c.z};
}

// s z^d + c for d >= 1, by d - 1 Hamilton products.
template <class V>
inline QuaternionT<V> powerStep(const QuaternionT<V>& z, int degree, V scale,
                                const QuaternionT<V>& c) {
    QuaternionT<V> p = z;
    for (int k = 1; k < degree; ++k)
        p = p * z;
    return scale * p + c;
}

// The derivative of s z^2 at z applied to h: s (z h + h z). Quaternions do not commute, so this
// is not 2 s z h; it is 2 s (z_w h + h_w v_z) - 2 s (v_z . v_h) in components.
template <class V>
inline QuaternionT<V> quadraticDerivative(const QuaternionT<V>& z, const QuaternionT<V>& h,
                                          V scale) {
    V twoScale = scale + scale;
    V zw = twoScale * z.w, hw = twoScale * h.w;
    return {zw * h.w - twoScale * (z.x * h.x + z.y * h.y + z.z * h.z), zw * h.x + hw * z.x,
            zw * h.y + hw * z.y, zw * h.z + hw * z.z};
}

// The derivative of s z^d at z applied to h, for d <= kMaxLaneDegree (distance.h): s
// sum_{k=0}^{d-1} z^k h z^(d-1-k) (the product rule; the factors do not commute).
template <class V>
inline QuaternionT<V> powerDerivative(const QuaternionT<V>& z, const QuaternionT<V>& h, int degree,
                                      V scale) {
    QuaternionT<V> sum = h;  // d = 1
    if (degree >= 2) {
        // powers[k] = z^k for 1 <= k < d; the terms k = 0 and k = d - 1 have a factor 1.
        QuaternionT<V> powers[kMaxLaneDegree];
        powers[1] = z;
        for (int k = 2; k < degree; ++k)
            powers[k] = powers[k - 1] * z;
        sum = h * powers[degree - 1];
        QuaternionT<V> last = powers[degree - 1] * h;
        sum = sum + last;
        for (int k = 1; k + 1 < degree; ++k) {
            QuaternionT<V> term = powers[k] * h * powers[degree - 1 - k];
            sum = sum + term;
        }
    }
    return scale * sum;
}

#endif  // QUATERNIA_JULIA_STEPS_INL_H_
