// Quaternions q = w + x i + y j + z k, templated on the components so that the same algebra runs
// on float and double and on SIMD lanes (Highway vectors: the render lanes), as Embree's
// QuaternionT<T>.
//
// A default-constructed Quaternion is zero: it is an element of the algebra H, not a rotation.
// Multiplication is Hamilton's product (Hamilton 1843; seed paper eqs. 2.7-2.9):
//   i^2 = j^2 = k^2 = ijk = -1,  ij = k, jk = i, ki = j,  ji = -k, kj = -i, ik = -j.
//
// The ring operations (sums, products, dot, norm squared, square) are in
// quaternion_arithmetic-inl.h, which this header includes for real components and the lane code
// includes again inside each SIMD target's namespace: GCC compiles a template with the target
// options of the place where it is defined, so an operator defined here could not use AVX2's
// vector instructions. Everything else here (constructors, the compound assignments, the
// functions below) is for real components only.
#pragma once

#include <cmath>
#include <ostream>
#include <type_traits>

#include "quaternia/algebra/element.h"

namespace quaternia {

// The 4-dimensional element of element.h, the quaternions' (Hamilton's product, below).
template <typename T>
struct Element<T, 4> {
    T w{}, x{}, y{}, z{};  // components along 1, i, j, k

    constexpr Element() = default;
    // By reference: a lane vector passed by value to a function compiled without its target
    // changes the ABI (GCC's -Wpsabi note).
    constexpr Element(const T& real) : w(real) {}  // NOLINT: reals embed in H
    constexpr Element(const T& w_, const T& x_, const T& y_, const T& z_)
        : w(w_), x(x_), y(y_), z(z_) {}

    template <typename U>
    constexpr explicit Element(const Element<U, 4>& q)
        : w(T(q.w)), x(T(q.x)), y(T(q.y)), z(T(q.z)) {}

    constexpr T operator[](int index) const {
        return index == 0 ? w : index == 1 ? x : index == 2 ? y : z;
    }
    constexpr T& operator[](int index) {
        return index == 0 ? w : index == 1 ? x : index == 2 ? y : z;
    }

    constexpr Element& operator+=(const Element& q) {
        w += q.w, x += q.x, y += q.y, z += q.z;
        return *this;
    }
    constexpr Element& operator-=(const Element& q) {
        w -= q.w, x -= q.x, y -= q.y, z -= q.z;
        return *this;
    }
    constexpr Element& operator*=(T s) {
        w *= s, x *= s, y *= s, z *= s;
        return *this;
    }
};

template <typename T>
using QuaternionT = Element<T, 4>;
using Quaternion = QuaternionT<double>;
using Quaternionf = QuaternionT<float>;

// The components that quaternion_arithmetic-inl.h's operations take in this namespace; the lane
// code's target namespaces take their vectors instead.
template <typename T>
concept QuaternionComponent = std::is_arithmetic_v<T>;
#include "quaternia/algebra/quaternion_arithmetic-inl.h"  // IWYU pragma: export

template <typename T>
constexpr QuaternionT<T> operator/(QuaternionT<T> a, T s) {
    return a *= T(1) / s;
}

template <typename T>
constexpr bool operator==(const QuaternionT<T>& a, const QuaternionT<T>& b) {
    return a.w == b.w && a.x == b.x && a.y == b.y && a.z == b.z;
}

template <typename T>
T norm(const QuaternionT<T>& q) {
    using std::sqrt;
    return sqrt(normSquared(q));
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
