#include "quaternia/fractal/slice.h"

#include <cmath>
#include <numbers>
#include <string>

#include "quaternia/util/error.h"

namespace quaternia {

std::array<Quaternion, 2> rotationFromPlaneAngles(const std::array<double, 6>& anglesDegrees) {
    // Plane (1, u): l = r = exp(u theta/2) turns 1 towards u by theta and fixes the plane
    // orthogonal to it. Plane (v, w) of imaginary units: conjugation by exp(u theta/2) with
    // u = v x w turns v towards w by theta and fixes 1 and u.
    struct PlaneTurn {
        Quaternion axis;
        bool sameSide;  // l = r (plane through 1) or r = conj(l)
    };
    static constexpr std::array<PlaneTurn, 6> kPlanes{{
        {kUnitI, true},    // (1, i)
        {kUnitJ, true},    // (1, j)
        {kUnitK, true},    // (1, k)
        {kUnitK, false},   // (i, j): i x j = k
        {-kUnitJ, false},  // (i, k): i x k = -j
        {kUnitI, false},   // (j, k): j x k = i
    }};
    Quaternion left{1}, right{1};
    for (int plane = 0; plane < 6; ++plane) {
        double halfAngle = anglesDegrees[plane] * std::numbers::pi / 360.0;
        if (halfAngle == 0) continue;
        Quaternion l = expImaginary(kPlanes[plane].axis, halfAngle);
        Quaternion r = kPlanes[plane].sameSide ? l : conj(l);
        left = l * left;
        right = right * r;
    }
    return {left, right};
}

Slice::Slice(const SliceSettings& settings, Algebra algebra)
    : dimension_(algebraDimension(algebra)), distance_(settings.distance) {
    if (dimension_ == 8) {
        for (size_t n = 0; n < settings.origin.size() && n < 8; ++n)
            origin_[n] = settings.origin[n];
        if (settings.axes.size() != 24 && settings.axes.size() != 12) {
            tangents_ = {basisElement(0), basisElement(1), basisElement(2)};
            return;
        }
        // Gram-Schmidt in the order given; axes of 4 components have the rest 0.
        const size_t perAxis = settings.axes.size() / 3;
        for (size_t a = 0; a < 3; ++a) {
            Hypercomplex v{};
            for (size_t n = 0; n < perAxis; ++n)
                v[n] = settings.axes[perAxis * a + n];
            const double given = std::sqrt(normSquared(v));
            for (size_t b = 0; b < a; ++b)
                v = v - dotProduct(v, tangents_[b]) * tangents_[b];
            const double left = std::sqrt(normSquared(v));
            if (!(given > 0) || !(left > 1e-9 * given)) {
                throw UserError("slice.axes", "slice.axes: axis " + std::to_string(a + 1) +
                                                  " lies in the span of the axes before it; "
                                                  "three independent directions are needed");
            }
            tangents_[a] = (1 / left) * v;
        }
        return;
    }
    // SliceSettings::normal holds (x, y, z, w) in the components (w, x, y, z) of a Quaternion.
    Quaternion unit = normalize(settings.normal);
    unitNormal_ = {unit.w, unit.x, unit.y, unit.z};
    auto [planeLeft, planeRight] = rotationFromPlaneAngles(settings.anglesDegrees);
    left_ = normalize(settings.left) * planeLeft;
    right_ = planeRight * normalize(settings.right);
    // d s(p) / d x_a = e_a - (s^_a / s^_w) e_w, then rotated like the point itself.
    std::array<Quaternion, 3> tangents;
    for (int axis = 0; axis < 3; ++axis) {
        Quaternion direction;
        direction[axis] = 1;
        direction.z = -unitNormal_[axis] / unitNormal_[3];
        tangents[axis] = left_ * direction * right_;
    }
    setQuaternionTangents(tangents);
    stepScale_ = std::abs(unitNormal_[3]);
}

void Slice::setQuaternionTangents(const std::array<Quaternion, 3>& tangents) {
    quaternionTangents_ = tangents;
    for (size_t a = 0; a < 3; ++a) {
        const Quaternion& t = tangents[a];
        tangents_[a] = {t.w, t.x, t.y, t.z, 0, 0, 0, 0};
    }
}

Quaternion Slice::embed(const Point3d& p) const {
    const auto& n = unitNormal_;
    double w = (distance_ - n[0] * p.x - n[1] * p.y - n[2] * p.z) / n[3];
    return {p.x, p.y, p.z, w};
}

Slice Slice::isometry(const Quaternion& origin, const std::array<Quaternion, 3>& axes) {
    Slice slice;
    slice.isometryOrigin_ = origin;
    slice.setQuaternionTangents(axes);
    return slice;
}

Quaternion Slice::quaternionFromWorld(const Point3d& p) const {
    if (isometryOrigin_) {
        const std::array<Quaternion, 3>& t = quaternionTangents_;
        return *isometryOrigin_ + t[0] * p.x + t[1] * p.y + t[2] * p.z;
    }
    return left_ * embed(p) * right_;
}

Hypercomplex Slice::fromWorld(const Point3d& p) const {
    if (dimension_ == 8)
        return origin_ + p.x * tangents_[0] + p.y * tangents_[1] + p.z * tangents_[2];
    const Quaternion q = quaternionFromWorld(p);
    return {q.w, q.x, q.y, q.z, 0, 0, 0, 0};
}

double Slice::boundingRadius(double bailout) const {
    if (dimension_ == 4) return bailout;
    double along = 0;
    for (const Hypercomplex& axis : tangents_)
        along += dotProduct(origin_, axis) * dotProduct(origin_, axis);
    return bailout + std::sqrt(along);
}

}  // namespace quaternia
