// The rendered object: a Julia set (julia_set.h) in any algebra of section 2.3, seen through a 3D
// slice (slice.h). This is the distance field every consumer shares (the marchers, shading, the
// mesher and the explorer): it answers in 3D world coordinates, with distances already made safe
// for 3D steps.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "quaternia/algebra/vecmath.h"
#include "quaternia/fractal/distance.h"
#include "quaternia/fractal/fractal_settings.h"
#include "quaternia/fractal/hypercomplex_julia.h"
#include "quaternia/fractal/julia_set.h"
#include "quaternia/fractal/slice.h"

namespace quaternia {

// g / |g| for a gradient g; where g has no direction (zero or not finite: the orbit sits on a
// critical point), the direction from the origin to p, outward for star-shaped sets.
Vector3d normalOrOutward(const Vector3d& g, const Point3d& p);

// Whether a set of another algebra that is a quaternion set is drawn as one where its form allows
// (an octonion real form folded, octonion_fold.h; the quaternion half of the 8-component
// algebras, fractal.cpp: the SIMD lanes and the mesher then draw it), or always in its own
// algebra (the scalar reference).
enum class QuaternionPaths { kWherePossible, kNever };

class Fractal {
  public:
    Fractal(std::shared_ptr<const JuliaSet> set, Slice slice)
        : set_(std::move(set)), slice_(std::move(slice)) {}
    Fractal(QuaternionJuliaSet set, Slice slice)
        : Fractal(std::make_shared<const QuaternionJuliaSet>(std::move(set)), std::move(slice)) {}
    // Compiles fractal.formula with fractal.c in fractal.algebra, through the set and slice that
    // algebraRules() gives the algebra; throws UserError naming the bad key
    // (scene/scene_fractal.h builds the fractal of a scene).
    static Fractal fromSettings(const FractalSettings& fractal, const SliceSettings& slice,
                                QuaternionPaths paths);

    const JuliaSet& set() const { return *set_; }
    // The same, shared: for a consumer that may outlive this Fractal (the lanes' fallback).
    std::shared_ptr<const JuliaSet> sharedSet() const { return set_; }
    // The set as the implementation `Set` (null where it is another): for the fast paths that
    // take more than the interface (the lanes take the quaternions' polynomial and the bicomplex
    // duplex components).
    template <class Set>
    const Set* setAs() const {
        return dynamic_cast<const Set*>(set_.get());
    }
    const Slice& slice() const { return slice_; }
    DistanceKind distanceKind() const { return set_->distanceKind(); }
    // Where orbits surely escape (the bailout where no radius is certain).
    double escapeRadius() const { return set_->escapeRadius(); }

    // The estimate at slice().fromWorld(p), its distance scaled by the slice's step scale so
    // that a 3D step of that length cannot cross the set.
    DistanceEstimate estimate(const Point3d& p) const;
    bool contains(const Point3d& p) const { return set_->contains(slice_.fromWorld(p)); }
    // The same by the orbit alone (JuliaSet::containsByOrbit): the reference for tests.
    bool containsByOrbit(const Point3d& p) const {
        return set_->containsByOrbit(slice_.fromWorld(p));
    }
    // The least k in [k0, k1] whose sample ray.at(t0 + k step) contains() takes, or k1 + 1: the
    // samples in batches where the set's orbits run so (JuliaSet::firstInside).
    int64_t firstInsideSample(const Ray& ray, double t0, double step, int64_t k0, int64_t k1) const;
    // Whether clearance() may be positive (JuliaSet::hasClearance).
    bool hasClearance() const { return set_->hasClearance(); }
    // A proven lower bound of the 3D distance from p to the set (JuliaSet::clearance through the
    // slice's step scale, less an allowance for the slice map's rounding); 0 proves nothing.
    double clearance(const Point3d& p) const;
    // Whether excludesSegment can prove anything (JuliaSet::provesEmptySpace).
    bool provesEmptySegments() const { return set_->provesEmptySpace(); }
    // True where no point ray.at(t), t0 <= t <= t1, belongs to K_N, proven (JuliaSet::
    // excludesSegment): the slice is affine, so the segment's image is the segment between its
    // ends' images, thickened by 1e-12 (1 + |q|) for the rounding of the slice's map (a few
    // dozen operations, each of relative error 2^-53). False proves nothing.
    bool excludesSegment(const Ray& ray, double t0, double t1) const {
        return excludesTube(ray, t0, t1, 0);
    }
    // The same for every point within `radius` (world units) of that segment: a tube, whose
    // image in the algebra lies within radius / Slice::stepScale() of the segment's image in
    // every component (render/proven_cones.h proves the cones of blocks of pixels this way).
    bool excludesTube(const Ray& ray, double t0, double t1, double radius) const;
    // The part of the formula that no proof can take (JuliaSet::unprovablePart), or nothing.
    std::optional<std::string> unprovablePart() const { return set_->unprovablePart(); }
    // True where the point p (world units) is proven in K_N: the box about its image that
    // excludesTube's rounding allowance gives, iterated in interval arithmetic, stays in the
    // ball (JuliaSet::includesBox). False proves nothing.
    bool includesPoint(const Point3d& p) const;
    // Unit outward normal from the analytic Jacobian (one pass, docs/methods.md, Normals).
    Vector3d normal(const Point3d& p) const;
    // Unit normal from central differences of the potential ln|z_M|, step h: the simple
    // reference that tests hold the analytic normal to.
    Vector3d normalByDifferences(const Point3d& p, double h) const;

    // The object lies in the ball of this radius about the origin.
    double boundingRadius() const { return slice_.boundingRadius(set_->bailout()); }

  private:
    std::shared_ptr<const JuliaSet> set_;
    Slice slice_;
};

}  // namespace quaternia
