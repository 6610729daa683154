// The filled Julia set K_N of a formula in one of the algebras of section 2.3 (algebra/
// hypercomplex.h): the one interface through which every consumer (Fractal, and with it the
// marchers, shading, the mesher, the planes and the explorer) asks for membership, distances and
// normals, at points of the algebra. Which implementation draws an algebra, and with which
// estimate, escape radius and bailout, is decided once, by the algebra's row of
// algebraRules() (algebra_rules.h):
// - QuaternionJuliaSet (distance.h): the quaternions, from the formula multiplied out, with the
//   fast forms s z^d + c that the SIMD lanes share;
// - HypercomplexJuliaSet (hypercomplex_julia.h): the other algebras, from the formula evaluated
//   through the algebra's multiplication table.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "quaternia/algebra/formula_program.h"
#include "quaternia/algebra/hypercomplex.h"
#include "quaternia/fractal/distance_estimate.h"
#include "quaternia/interval/segment_form.h"

namespace quaternia {

// How a set's distance relates to the true distance to K_N.
enum class DistanceKind {
    kEstimate,  // the escape-time estimate (quaternions, octonions, bicomplex numbers)
    kLipschitz  // a proven lower bound, often far below the distance: march by fixed steps
};

class JuliaSet {
  public:
    virtual ~JuliaSet() = default;

    virtual Algebra algebra() const = 0;
    // What estimate() returns: an estimate to march by, or a proven but short distance that the
    // renderer combines with Algorithm 2's fixed steps.
    virtual DistanceKind distanceKind() const = 0;
    // The estimate at z0 (components past the algebra's dimension are 0).
    virtual DistanceEstimate estimate(const Hypercomplex& z0) const = 0;
    virtual bool contains(const Hypercomplex& z0) const = 0;
    // The same by following the orbit alone, whatever else contains() may consult (the
    // certified maps of DuplexEscapeMaps): the reference the fast answers are tested against.
    virtual bool containsByOrbit(const Hypercomplex& z0) const { return contains(z0); }
    // The index of the first of points[0 .. count) that contains() takes, or count if none: each
    // decided as contains() decides it. Sets whose orbits run in lanes (algebra/orbit_batch.h)
    // test several points at once.
    virtual int firstInside(const Hypercomplex* points, int count) const {
        for (int i = 0; i < count; ++i)
            if (contains(points[i])) return i;
        return count;
    }
    // Whether clearance() may be positive: a proven lower bound of the distance to K_N that is a
    // lookup, far cheaper than an orbit, for the fixed-step marcher to skip the samples within it
    // (render/march.h, firstSampleInside).
    virtual bool hasClearance() const { return false; }
    // A lower bound of |z0 - y| over y in K_N (0 proves nothing).
    virtual double clearance(const Hypercomplex& /*z0*/) const { return 0; }
    // ln|z_M| after exactly M iterations (or where it overflows): the potential whose gradient is
    // the normal; and the M the normal takes at z0.
    virtual double logRadiusAfter(const Hypercomplex& z0, int iterations) const = 0;
    virtual int gradientIterations(const Hypercomplex& z0) const = 0;
    // The gradient of |z_M|^2 along the three directions whose images in the algebra are
    // `tangents` (the slice's), M = gradientIterations(z0): a normal of the potential's level
    // sets, from one pass through the Jacobians of p.
    virtual std::array<double, 3> potentialGradient(
        const Hypercomplex& z0, const std::array<Hypercomplex, 3>& tangents) const = 0;

    // Whether the fixed-step marcher crosses empty space by excludesSegment (render/march.h,
    // firstSampleInside): the sets marched by fixed steps whose formula has an interval
    // extension (interval/interval_element.h). The sets marched by their estimate answer false,
    // though their proofs below work as well (the certificates use them).
    virtual bool provesEmptySpace() const { return false; }
    // The map as the proofs iterate it: its program in the algebra's multiplication table, and
    // whether it has an interval extension (interval/interval_element.h; kept by the set, as
    // the renderer asks on every segment).
    virtual const FormulaProgram& program() const = 0;
    virtual bool hasIntervalExtension() const = 0;
    // The part of the formula with no interval extension, named for a one-line refusal ("the
    // function log"); nothing where excludesSegment and includesBox can prove.
    std::optional<std::string> unprovablePart() const;
    // True where no point within `thickness` (in every component) of the segment from `from` to
    // `to` (points of the algebra) belongs to K_N, proven by iterating the segment in affine
    // arithmetic (interval/segment_form.h); false proves nothing.
    bool excludesSegment(const Hypercomplex& from, const Hypercomplex& to, double thickness) const;
    // The same for every point of a tube (interval/segment_form.h, tubeLeavesBall).
    bool excludesTube(const TubeForm& tube) const;
    // True where every point within `radius` (in every component) of `centre` belongs to K_N,
    // proven by iterating the ball about that box (interval/ball_form.h), then the box
    // (interval/interval_element.h, boxStaysInBall); false proves nothing.
    bool includesBox(const Hypercomplex& centre, double radius) const;

    // The memory the set's tables take at most while they are built, lazily, by the first render
    // that asks (the bicomplex functions' escape maps): for the commands to check against their
    // budget before the work starts.
    virtual uint64_t tableBytes() const { return 0; }

    virtual int maxIterations() const = 0;
    // Membership radius: K_N lies in the ball of this radius.
    virtual double bailout() const = 0;
    // Where orbits are certain to escape (the bailout where no radius is certain).
    virtual double escapeRadius() const = 0;
};

}  // namespace quaternia
