// A pinhole camera with POV-Ray's conventions (left-handed, horizontal field of view, one ray
// through each pixel centre), so that the scenes of the reference set give the same picture.
// The formulas are those of tests/data/reference and docs/conventions.md:
//   f = normalize(look_at - position), r = normalize(cross(up, f)), u = cross(f, r),
//   R = (W/H) r, D = f |R| / (2 tan(fov/2)), U = u,
//   pixel (px, py) -> direction normalize(D + x0 R + y0 U), x0 = (px + 0.5)/W - 0.5,
//   y0 = 0.5 - (py + 0.5)/H, row 0 at the top.
#pragma once

#include <array>
#include <optional>

#include "quaternia/algebra/vecmath.h"
#include "quaternia/scene/scene.h"

namespace quaternia {

class Camera {
  public:
    Camera(const CameraSettings& settings, int width, int height);

    // The ray through the image point (x, y) in pixel units: (px + 0.5, py + 0.5) is the centre
    // of pixel (px, py); other values are used for sub-pixel samples.
    Ray generateRay(double x, double y) const {
        double x0 = x / width_ - 0.5;
        double y0 = 0.5 - y / height_;
        return Ray{position_, normalize(direction_ + right_ * x0 + up_ * y0)};
    }
    // The thin lens's ray (camera.aperture) through the image point (x, y) from lens point `lens`
    // of the unit square (mapped onto the lens's disc, lensPoint): from that point of the lens
    // to where the pinhole ray meets the plane in focus, so that every lens point sees that
    // plane alike and nearer and farther points blur. The pinhole ray where the aperture is 0.
    Ray generateRay(double x, double y, const std::array<double, 2>& lens) const;
    // Whether the camera is a thin lens of nonzero aperture.
    bool thinLens() const { return aperture_ > 0; }
    // The unnormalised directions of the pixel centres of row py: first + px * step for pixel
    // px (generateRay's direction before normalisation), for work done a row at a time.
    struct RowDirections {
        Vector3d first, step;
    };
    RowDirections rowDirections(int py) const {
        const double y0 = 0.5 - (py + 0.5) / height_;
        return {direction_ + up_ * y0 + right_ * (0.5 / width_ - 0.5), right_ / double(width_)};
    }
    // The inverse: the image point (x, y) whose ray passes through p, or nullopt when p is not
    // in front of the camera. For drawing geometry (a mesh's silhouette) in the same picture.
    std::optional<std::array<double, 2>> project(const Point3d& p) const;

    // The cone of the rays through the square [x0, x0 + size)^2 of the image (pixel units)
    // about `centre`, the ray through its middle: at distance t every such ray lies within
    // slope t of the central ray's point, the slope being the largest chord between the central
    // direction and a corner's (past the directions' rounding). The angle from the centre is
    // largest at a corner while the cone stays in front of the image plane (the directions
    // within its angle meet the plane in an ellipse): the centre's angle to the view axis plus
    // the cone's below 90 degrees, which cos(centre's) > slope ensures. Where that fails (only
    // near a field of view of 180 degrees) the answer is 0: no cone.
    double coneSlope(const Ray& centre, double x0, double y0, double size) const;
    // Width of one pixel at distance t along a ray near the image centre: t * 2 tan(fov/2) / W.
    // Marching epsilons are fractions of it, so precision follows the image resolution.
    double pixelFootprint(double t) const { return t * pixelAngle_; }
    int width() const { return width_; }
    int height() const { return height_; }
    const Point3d& position() const { return position_; }
    // The unit view axis.
    const Vector3d& forward() const { return forward_; }

  private:
    Point3d position_;
    Vector3d right_, up_, direction_;  // R, U, D above
    int width_, height_;
    double pixelAngle_;
    double aperture_, focusDistance_;  // the thin lens (CameraSettings)
    Vector3d forward_;                 // unit view axis
};

// A point of the unit disc from one of the unit square, area kept (Shirley and Chiu's concentric
// map, 1997: squares to rings, so that stratified samples stay stratified on the lens).
std::array<double, 2> lensPoint(const std::array<double, 2>& square);

}  // namespace quaternia
