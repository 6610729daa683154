// From 3D to 4D: which quaternion a point of the rendered space stands for.
//
// 1. The slice embedding s(p) of POV-Ray's `slice <n>, d` (tests/data/reference): the normal is
//    normalised to s^ = n / |n|, and (x, y, z) becomes the quaternion x + y i + z j + w k with
//    w = (d - s^_x x - s^_y y - s^_z z) / s^_w, a point of the hyperplane s^ . q = d.
// 2. A rotation of 4D space, q -> L q R with unit quaternions L and R. Every rotation of R^4 has
//    this form (Cayley); the seed paper's view g(q k) of section 3.2.1 is L = 1, R = -k, and
//    L = u, R = conj(u) turns the imaginary 3-space about the axis of u. The six plane angles
//    are composed into L and R: a turn by theta in the plane (1, u) is l = r = exp(u theta/2),
//    one in the plane (v, w) of imaginary units is l = exp(u theta/2), r = exp(-u theta/2)
//    with u = v x w.
// A 3D point p is drawn iff quaternionFromWorld(p) = L s(p) R is in the set.
//
// The 8-component algebras (hypercomplex.h) take an isometry instead: the point (x, y, z) stands
// for origin + x e_0 + y e_1 + z e_2 with orthonormal e_n (slice.origin and slice.axes). One
// Slice serves every algebra: fromWorld gives the point of the algebra, whichever it is.
#pragma once

#include <array>
#include <optional>

#include "quaternia/algebra/hypercomplex.h"
#include "quaternia/algebra/quaternion.h"
#include "quaternia/algebra/vecmath.h"
#include "quaternia/fractal/fractal_settings.h"

namespace quaternia {

class Slice {
  public:
    // The slice of `algebra` (validated by the caller: normal with w != 0, left and right
    // non-zero; they are normalised). Throws UserError naming slice.axes where the axes of an
    // 8-component algebra do not span three dimensions.
    explicit Slice(const SliceSettings& settings, Algebra algebra = Algebra::kQuaternion);
    // The map p -> origin + x axes[0] + y axes[1] + z axes[2] into H for orthonormal axes and an
    // origin orthogonal to them (an isometry onto its image, and |p| <= |q(p)|: the bounding
    // sphere of the set is still the bailout's). Left and right are 1.
    static Slice isometry(const Quaternion& origin, const std::array<Quaternion, 3>& axes);

    // The point of the algebra that p stands for (components past its dimension 0).
    Hypercomplex fromWorld(const Point3d& p) const;
    // The same for a 4-component algebra, as a quaternion: fromWorld's first four components.
    Quaternion quaternionFromWorld(const Point3d& p) const;
    // The images of the unit x, y and z directions under the (affine) map: the columns of its
    // Jacobian, including the tilt of the slice (w depends on x, y and z) and the rotation.
    const std::array<Hypercomplex, 3>& tangents() const { return tangents_; }
    const std::array<Quaternion, 3>& quaternionTangents() const { return quaternionTangents_; }
    // A 3D step of length L moves the algebra's point by at most L / stepScale(): multiply a
    // distance there by this factor to get a safe 3D step (docs/methods.md, Slices and the step
    // factor). The rotation and the 8-component isometry keep lengths.
    double stepScale() const { return stepScale_; }
    // A radius about the 3D origin outside which no point maps into the ball |q| <= bailout:
    // the bailout for the quaternion slice (|p| <= |s(p)|, and the rotation keeps norms); for
    // the isometry of the 8-component algebras, the bailout plus the length of the origin's part
    // along the axes.
    double boundingRadius(double bailout) const;
    const Quaternion& left() const { return left_; }
    const Quaternion& right() const { return right_; }

  private:
    Slice() = default;
    Quaternion embed(const Point3d& p) const;  // s(p)
    void setQuaternionTangents(const std::array<Quaternion, 3>& tangents);

    int dimension_ = 4;
    std::array<double, 4> unitNormal_{};  // s^ as (x, y, z, w)
    double distance_ = 0;
    Quaternion left_{1}, right_{1};
    std::array<Quaternion, 3> quaternionTangents_{};
    std::optional<Quaternion> isometryOrigin_;  // set by isometry()
    Hypercomplex origin_{};                     // the 8-component isometry's
    std::array<Hypercomplex, 3> tangents_{};
    double stepScale_ = 1;
};

// The rotation pair (l, r) for the six plane angles in degrees, planes (1,i), (1,j), (1,k),
// (i,j), (i,k), (j,k), applied in that order: q -> l q r.
std::array<Quaternion, 2> rotationFromPlaneAngles(const std::array<double, 6>& anglesDegrees);

}  // namespace quaternia
