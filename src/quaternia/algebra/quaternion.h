// Quaternions q = w + x i + y j + z k, templated on the scalar so that the same algebra runs on
// float and double, as Embree's QuaternionT<T> (the SIMD lanes use fractal/julia_steps-inl.h).
//
// A default-constructed Quaternion is zero: it is an element of the algebra H, not a rotation.
// Multiplication is Hamilton's product (Hamilton 1843; seed paper eqs. 2.7-2.9):
//   i^2 = j^2 = k^2 = ijk = -1,  ij = k, jk = i, ki = j,  ji = -k, kj = -i, ik = -j.
#pragma once

#include <cmath>
#include <ostream>

namespace quaternia {

template <typename T>
struct QuaternionT {
    T w{}, x{}, y{}, z{};  // components along 1, i, j, k

    constexpr QuaternionT() = default;
    constexpr QuaternionT(T real) : w(real) {}  // NOLINT: reals embed in H
    constexpr QuaternionT(T w_, T x_, T y_, T z_) : w(w_), x(x_), y(y_), z(z_) {}

    template <typename U>
    constexpr explicit QuaternionT(const QuaternionT<U>& q)
        : w(T(q.w)), x(T(q.x)), y(T(q.y)), z(T(q.z)) {}

    constexpr T operator[](int index) const {
        return index == 0 ? w : index == 1 ? x : index == 2 ? y : z;
    }
    constexpr T& operator[](int index) {
        return index == 0 ? w : index == 1 ? x : index == 2 ? y : z;
    }

    constexpr QuaternionT& operator+=(const QuaternionT& q) {
        w += q.w, x += q.x, y += q.y, z += q.z;
        return *this;
    }
    constexpr QuaternionT& operator-=(const QuaternionT& q) {
        w -= q.w, x -= q.x, y -= q.y, z -= q.z;
        return *this;
    }
    constexpr QuaternionT& operator*=(T s) {
        w *= s, x *= s, y *= s, z *= s;
        return *this;
    }
};

using Quaternion = QuaternionT<double>;
using Quaternionf = QuaternionT<float>;

template <typename T>
constexpr QuaternionT<T> operator+(QuaternionT<T> a, const QuaternionT<T>& b) {
    return a += b;
}
template <typename T>
constexpr QuaternionT<T> operator-(QuaternionT<T> a, const QuaternionT<T>& b) {
    return a -= b;
}
template <typename T>
constexpr QuaternionT<T> operator-(const QuaternionT<T>& a) {
    return {-a.w, -a.x, -a.y, -a.z};
}
template <typename T>
constexpr QuaternionT<T> operator*(QuaternionT<T> a, T s) {
    return a *= s;
}
template <typename T>
constexpr QuaternionT<T> operator*(T s, QuaternionT<T> a) {
    return a *= s;
}
template <typename T>
constexpr QuaternionT<T> operator/(QuaternionT<T> a, T s) {
    return a *= T(1) / s;
}

// Hamilton product: (a0 + va)(b0 + vb) = a0 b0 - va.vb + a0 vb + b0 va + va x vb.
template <typename T>
constexpr QuaternionT<T> operator*(const QuaternionT<T>& a, const QuaternionT<T>& b) {
    return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
            a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
            a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
            a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

template <typename T>
constexpr bool operator==(const QuaternionT<T>& a, const QuaternionT<T>& b) {
    return a.w == b.w && a.x == b.x && a.y == b.y && a.z == b.z;
}

template <typename T>
constexpr QuaternionT<T> conj(const QuaternionT<T>& q) {
    return {q.w, -q.x, -q.y, -q.z};
}
// |q|^2 = w^2 + x^2 + y^2 + z^2; the norm is multiplicative, |pq| = |p||q|.
template <typename T>
constexpr T normSquared(const QuaternionT<T>& q) {
    return q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z;
}
template <typename T>
T norm(const QuaternionT<T>& q) {
    using std::sqrt;
    return sqrt(normSquared(q));
}
template <typename T>
constexpr T dot(const QuaternionT<T>& a, const QuaternionT<T>& b) {
    return a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
}
// q^-1 = conj(q) / |q|^2. The caller guarantees q != 0.
template <typename T>
constexpr QuaternionT<T> inverse(const QuaternionT<T>& q) {
    return conj(q) / normSquared(q);
}
template <typename T>
QuaternionT<T> normalize(const QuaternionT<T>& q) {
    return q / norm(q);
}
// q^2 = (w^2 - |v|^2) + 2 w v: cheaper than the general product (docs/facts.md, Algebra).
template <typename T>
constexpr QuaternionT<T> square(const QuaternionT<T>& q) {
    T twoW = q.w + q.w;
    return {q.w * q.w - q.x * q.x - q.y * q.y - q.z * q.z, twoW * q.x, twoW * q.y, twoW * q.z};
}
template <typename T>
constexpr T realPart(const QuaternionT<T>& q) {
    return q.w;
}
// Norm of the imaginary part v = x i + y j + z k.
template <typename T>
T imaginaryNorm(const QuaternionT<T>& q) {
    using std::sqrt;
    return sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
}

// exp(u theta) = cos(theta) + u sin(theta) for a unit imaginary u: the unit quaternion that, used
// as l = r, turns the plane (1, u) by 2 theta (see slice.h).
template <typename T>
QuaternionT<T> expImaginary(const QuaternionT<T>& unitImaginary, T theta) {
    using std::cos;
    using std::sin;
    T s = sin(theta);
    return {cos(theta), unitImaginary.x * s, unitImaginary.y * s, unitImaginary.z * s};
}

template <typename T>
bool isFinite(const QuaternionT<T>& q) {
    return std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z);
}

template <typename T>
std::ostream& operator<<(std::ostream& os, const QuaternionT<T>& q) {
    return os << "(" << q.w << ", " << q.x << ", " << q.y << ", " << q.z << ")";
}

inline constexpr Quaternion kUnitI{0, 1, 0, 0};
inline constexpr Quaternion kUnitJ{0, 0, 1, 0};
inline constexpr Quaternion kUnitK{0, 0, 0, 1};

}  // namespace quaternia
