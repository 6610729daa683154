// Small 3D vector algebra for the camera, rays and shading, templated on the scalar like
// Quaternion. Points and vectors share one type: the renderer needs no affine distinction.
#pragma once

#include <cmath>
#include <ostream>

namespace quaternia {

template <typename T>
struct Vector3T {
    T x{}, y{}, z{};

    constexpr Vector3T() = default;
    constexpr Vector3T(T x_, T y_, T z_) : x(x_), y(y_), z(z_) {}
    template <typename U>
    constexpr explicit Vector3T(const Vector3T<U>& v) : x(T(v.x)), y(T(v.y)), z(T(v.z)) {}

    constexpr T operator[](int index) const { return index == 0 ? x : index == 1 ? y : z; }
    constexpr T& operator[](int index) { return index == 0 ? x : index == 1 ? y : z; }

    constexpr Vector3T& operator+=(const Vector3T& v) {
        x += v.x, y += v.y, z += v.z;
        return *this;
    }
    constexpr Vector3T& operator-=(const Vector3T& v) {
        x -= v.x, y -= v.y, z -= v.z;
        return *this;
    }
    constexpr Vector3T& operator*=(T s) {
        x *= s, y *= s, z *= s;
        return *this;
    }
};

using Vector3d = Vector3T<double>;
using Vector3f = Vector3T<float>;
using Point3d = Vector3d;

template <typename T>
constexpr Vector3T<T> operator+(Vector3T<T> a, const Vector3T<T>& b) {
    return a += b;
}
template <typename T>
constexpr Vector3T<T> operator-(Vector3T<T> a, const Vector3T<T>& b) {
    return a -= b;
}
template <typename T>
constexpr Vector3T<T> operator-(const Vector3T<T>& a) {
    return {-a.x, -a.y, -a.z};
}
template <typename T>
constexpr Vector3T<T> operator*(Vector3T<T> a, T s) {
    return a *= s;
}
template <typename T>
constexpr Vector3T<T> operator*(T s, Vector3T<T> a) {
    return a *= s;
}
template <typename T>
constexpr Vector3T<T> operator/(Vector3T<T> a, T s) {
    return a *= T(1) / s;
}
// Component-wise product, for colours.
template <typename T>
constexpr Vector3T<T> operator*(const Vector3T<T>& a, const Vector3T<T>& b) {
    return {a.x * b.x, a.y * b.y, a.z * b.z};
}
template <typename T>
constexpr bool operator==(const Vector3T<T>& a, const Vector3T<T>& b) {
    return a.x == b.x && a.y == b.y && a.z == b.z;
}

template <typename T>
constexpr T dot(const Vector3T<T>& a, const Vector3T<T>& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
// The ordinary cross product; handedness is the camera's business (camera.h).
template <typename T>
constexpr Vector3T<T> cross(const Vector3T<T>& a, const Vector3T<T>& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <typename T>
T length(const Vector3T<T>& v) {
    using std::sqrt;
    return sqrt(dot(v, v));
}
template <typename T>
Vector3T<T> normalize(const Vector3T<T>& v) {
    return v / length(v);
}
template <typename T>
constexpr Vector3T<T> lerp(const Vector3T<T>& a, const Vector3T<T>& b, T t) {
    return a * (T(1) - t) + b * t;
}
template <typename T>
bool isFinite(const Vector3T<T>& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

template <typename T>
std::ostream& operator<<(std::ostream& os, const Vector3T<T>& v) {
    return os << "(" << v.x << ", " << v.y << ", " << v.z << ")";
}

// A ray o + t d with unit direction d, so that t is a distance.
struct Ray {
    Point3d origin;
    Vector3d direction;
    constexpr Point3d at(double t) const { return origin + direction * t; }
};

}  // namespace quaternia
