#include "quaternia/fractal/slice.h"

#include <cmath>
#include <numbers>

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

Slice::Slice(const SliceSettings& settings) : distance_(settings.distance) {
    // SliceSettings::normal holds (x, y, z, w) in the components (w, x, y, z) of a Quaternion.
    Quaternion unit = normalize(settings.normal);
    unitNormal_ = {unit.w, unit.x, unit.y, unit.z};
    auto [planeLeft, planeRight] = rotationFromPlaneAngles(settings.anglesDegrees);
    left_ = normalize(settings.left) * planeLeft;
    right_ = planeRight * normalize(settings.right);
    // d s(p) / d x_a = e_a - (s^_a / s^_w) e_w, then rotated like the point itself.
    for (int axis = 0; axis < 3; ++axis) {
        Quaternion direction;
        direction[axis] = 1;
        direction.z = -unitNormal_[axis] / unitNormal_[3];
        tangents_[axis] = left_ * direction * right_;
    }
    stepScale_ = std::abs(unitNormal_[3]);
}

Quaternion Slice::embed(const Point3d& p) const {
    const auto& n = unitNormal_;
    double w = (distance_ - n[0] * p.x - n[1] * p.y - n[2] * p.z) / n[3];
    return {p.x, p.y, p.z, w};
}

Slice Slice::isometry(const Quaternion& origin, const std::array<Quaternion, 3>& axes) {
    Slice slice;
    slice.isometryOrigin_ = origin;
    slice.tangents_ = axes;
    return slice;
}

Quaternion Slice::quaternionFromWorld(const Point3d& p) const {
    if (isometryOrigin_)
        return *isometryOrigin_ + tangents_[0] * p.x + tangents_[1] * p.y + tangents_[2] * p.z;
    return left_ * embed(p) * right_;
}

}  // namespace quaternia
