// The rendered object: a Julia set seen through a 3D slice, in the quaternions (JuliaSet, the
// fast paths) or another algebra of section 2.3 (hypercomplex_julia.h, the scalar reference).
// This is the distance field every consumer shares (the marchers, shading, the mesher and the
// explorer): it answers in 3D world coordinates, with distances already made safe for 3D steps.
#pragma once

#include <memory>
#include <optional>

#include "quaternia/algebra/vecmath.h"
#include "quaternia/fractal/distance.h"
#include "quaternia/fractal/fractal_settings.h"
#include "quaternia/fractal/hypercomplex_julia.h"
#include "quaternia/fractal/slice.h"

namespace quaternia {

// g / |g| for a gradient g; where g has no direction (zero or not finite: the orbit sits on a
// critical point), the direction from the origin to p, outward for star-shaped sets.
Vector3d normalOrOutward(const Vector3d& g, const Point3d& p);

// Whether an octonion formula is drawn in the quaternions where its form allows (octonion_fold.h:
// the SIMD lanes and the mesher then draw it), or always in the octonions (the scalar reference).
enum class OctonionFolding { kWherePossible, kNever };

class Fractal {
  public:
    Fractal(JuliaSet set, Slice slice) : set_(std::move(set)), slice_(slice) {}
    explicit Fractal(std::shared_ptr<const HypercomplexFractal> other)
        : hypercomplex_(std::move(other)) {}
    // Compiles fractal.formula with fractal.c in fractal.algebra; throws UserError naming the
    // bad key (scene/scene_fractal.h builds the fractal of a scene).
    static Fractal fromSettings(const FractalSettings& fractal, const SliceSettings& slice,
                                OctonionFolding folding);

    // Whether the set lives in an algebra other than the quaternions (then set() and slice()
    // must not be called: only the scalar reference paths, which use the members below, apply).
    bool isQuaternion() const { return hypercomplex_ == nullptr; }
    const HypercomplexFractal* hypercomplex() const { return hypercomplex_.get(); }
    // The same, shared: for a consumer that may outlive this Fractal (the lanes' fallback).
    std::shared_ptr<const HypercomplexFractal> sharedHypercomplex() const { return hypercomplex_; }
    // What estimate() returns: an estimate to march by, or a proven but short distance that the
    // renderer combines with Algorithm 2's fixed steps.
    DistanceKind distanceKind() const;
    // Where orbits surely escape (the bailout where no radius is certain).
    double escapeRadius() const;

    // The 4D estimate at quaternionFromWorld(p), its distance scaled by the slice's step scale
    // so that a 3D step of that length cannot cross the set.
    DistanceEstimate estimate(const Point3d& p) const;
    bool contains(const Point3d& p) const;
    // Unit outward normal from the analytic Jacobian (one pass, docs/methods.md, Normals).
    Vector3d normal(const Point3d& p) const;
    // Unit normal from central differences of the potential ln|z_M|, step h: the simple
    // reference that tests hold the analytic normal to.
    Vector3d normalByDifferences(const Point3d& p, double h) const;

    // The object lies in the ball of this radius about the origin: |p| <= |s(p)| = |L s(p) R|.
    double boundingRadius() const;
    const JuliaSet& set() const { return *set_; }
    const Slice& slice() const { return *slice_; }

  private:
    std::optional<JuliaSet> set_;
    std::optional<Slice> slice_;
    std::shared_ptr<const HypercomplexFractal> hypercomplex_;
};

}  // namespace quaternia
