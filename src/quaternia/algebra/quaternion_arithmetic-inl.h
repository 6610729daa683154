// The ring operations of QuaternionT<T> (quaternion.h), for components T that satisfy
// QuaternionComponent in the including namespace: quaternion.h includes this file into
// namespace quaternia for real components, and the lane code (render/lanes/march_lanes-inl.h)
// into each SIMD target's namespace for that target's vectors, where the operations take the
// target's instructions. The constraints differ, so the two sets of overloads never compete.
// No include guard, for that reason; each place includes it once.
//
// Only +, - and * of T are used, left to right as written: real and lane components round
// alike.

template <QuaternionComponent T>
constexpr QuaternionT<T> operator+(const QuaternionT<T>& a, const QuaternionT<T>& b) {
    return {a.w + b.w, a.x + b.x, a.y + b.y, a.z + b.z};
}
template <QuaternionComponent T>
constexpr QuaternionT<T> operator-(const QuaternionT<T>& a, const QuaternionT<T>& b) {
    return {a.w - b.w, a.x - b.x, a.y - b.y, a.z - b.z};
}
template <QuaternionComponent T>
constexpr QuaternionT<T> operator-(const QuaternionT<T>& a) {
    if constexpr (std::is_arithmetic_v<T>) {
        return {-a.w, -a.x, -a.y, -a.z};
    } else {
        // Lane vectors have no unary minus; 0 - x differs from -x only in the sign of a zero.
        const T zero{};
        return {zero - a.w, zero - a.x, zero - a.y, zero - a.z};
    }
}
template <QuaternionComponent T>
constexpr QuaternionT<T> operator*(const QuaternionT<T>& a, const T& s) {
    return {a.w * s, a.x * s, a.y * s, a.z * s};
}
template <QuaternionComponent T>
constexpr QuaternionT<T> operator*(const T& s, const QuaternionT<T>& a) {
    return {a.w * s, a.x * s, a.y * s, a.z * s};
}

// Hamilton product: (a0 + va)(b0 + vb) = a0 b0 - va.vb + a0 vb + b0 va + va x vb.
template <QuaternionComponent T>
constexpr QuaternionT<T> operator*(const QuaternionT<T>& a, const QuaternionT<T>& b) {
    return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
            a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
            a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
            a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

template <QuaternionComponent T>
constexpr QuaternionT<T> conj(const QuaternionT<T>& q) {
    return {q.w, -q.x, -q.y, -q.z};
}
template <QuaternionComponent T>
constexpr T dot(const QuaternionT<T>& a, const QuaternionT<T>& b) {
    return a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
}
// |q|^2 = w^2 + x^2 + y^2 + z^2; the norm is multiplicative, |pq| = |p||q|.
template <QuaternionComponent T>
constexpr T normSquared(const QuaternionT<T>& q) {
    return q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z;
}
// |q|^2 summed as a tree, (w^2 + x^2) + (y^2 + z^2): the lanes' iteration loops
// (render/lanes/estimate_lanes-inl.h) are bound by the latency of this chain, which
// normSquared's left-to-right sum makes one multiply-add longer. It rounds differently from
// normSquared, so each caller keeps the one it has always used.
template <QuaternionComponent T>
constexpr T normSquaredPairwise(const QuaternionT<T>& q) {
    return (q.w * q.w + q.x * q.x) + (q.y * q.y + q.z * q.z);
}
// q^2 = (w^2 - |v|^2) + 2 w v: cheaper than the general product (docs/facts.md, Algebra).
template <QuaternionComponent T>
constexpr QuaternionT<T> square(const QuaternionT<T>& q) {
    T twoW = q.w + q.w;
    return {q.w * q.w - q.x * q.x - q.y * q.y - q.z * q.z, twoW * q.x, twoW * q.y, twoW * q.z};
}
