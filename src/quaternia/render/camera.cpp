#include "quaternia/render/camera.h"

#include <algorithm>

#include <cmath>
#include <numbers>

namespace quaternia {

Camera::Camera(const CameraSettings& settings, int width, int height)
    : position_(settings.position),
      width_(width),
      height_(height),
      aperture_(settings.aperture),
      focusDistance_(settings.focusDistance > 0 ? settings.focusDistance
                                                : length(settings.lookAt - settings.position)) {
    Vector3d forward = normalize(settings.lookAt - settings.position);
    forward_ = forward;
    // cross(sky, f) with the ordinary formula gives POV-Ray's right vector: the scene is
    // left-handed, x to the right, y up, z into the screen.
    Vector3d rightUnit = normalize(cross(settings.up, forward));
    Vector3d upUnit = cross(forward, rightUnit);
    right_ = rightUnit * (double(width) / double(height));
    up_ = upUnit;
    double halfAngle = settings.fovDegrees * std::numbers::pi / 360.0;
    direction_ = forward * (length(right_) / (2.0 * std::tan(halfAngle)));
    pixelAngle_ = 2.0 * std::tan(halfAngle) / double(width);
}

Ray Camera::generateRay(double x, double y, const std::array<double, 2>& lens) const {
    const Ray pinhole = generateRay(x, y);
    if (!(aperture_ > 0)) return pinhole;
    // Where the pinhole ray meets the plane in focus, focusDistance_ along the view axis.
    const Point3d focus = pinhole.at(focusDistance_ / dot(pinhole.direction, forward_));
    const auto [u, v] = lensPoint(lens);
    const Point3d origin = position_ + (normalize(right_) * u + up_ * v) * (0.5 * aperture_);
    return Ray{origin, normalize(focus - origin)};
}

std::array<double, 2> lensPoint(const std::array<double, 2>& square) {
    const double a = 2 * square[0] - 1, b = 2 * square[1] - 1;
    if (a == 0 && b == 0) return {0, 0};
    double r, phi;
    if (std::abs(a) > std::abs(b)) {
        r = a;
        phi = std::numbers::pi / 4 * (b / a);
    } else {
        r = b;
        phi = std::numbers::pi / 2 - std::numbers::pi / 4 * (a / b);
    }
    return {r * std::cos(phi), r * std::sin(phi)};
}

std::optional<std::array<double, 2>> Camera::project(const Point3d& p) const {
    // D, R and U are orthogonal: p - position = s (D + x0 R + y0 U) splits along them.
    Vector3d v = p - position_;
    double s = dot(v, direction_) / dot(direction_, direction_);
    if (!(s > 0)) return std::nullopt;
    double x0 = dot(v, right_) / (s * dot(right_, right_));
    double y0 = dot(v, up_) / (s * dot(up_, up_));
    return std::array<double, 2>{(x0 + 0.5) * width_, (0.5 - y0) * height_};
}

double Camera::coneSlope(const Ray& centre, double x0, double y0, double size) const {
    double rho = 0;
    for (int corner = 0; corner < 4; ++corner) {
        const Ray edge = generateRay(x0 + (corner & 1) * size, y0 + (corner >> 1) * size);
        rho = std::max(rho, length(edge.direction - centre.direction));
    }
    rho = rho * (1 + 1e-9) + 1e-15;
    return dot(centre.direction, forward_) > rho ? rho : 0;
}

}  // namespace quaternia
