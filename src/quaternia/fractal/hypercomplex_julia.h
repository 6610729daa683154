// Julia sets in the algebras other than the quaternions (issue 16; hypercomplex.h): bicomplex
// numbers, coquaternions, biquaternions and octonions, seen through a 3D slice, for the scalar
// reference renderer (march.h), the mesher and every other consumer of Fractal.
//
// The set drawn is K_N: the points whose iterates z_0 .. z_{N-1} all have |z| <= bailout in
// the Euclidean norm of the components. What bounds a step (docs/methods.md, Other algebras):
// - octonions: the norm is multiplicative, so the quaternion estimate 0.5 |z| ln|z| / rho
//   carries over, rho the running bound P'(|z_n|) rho_n of the derivative's norm;
// - bicomplex numbers: the duplex map is an isomorphism onto C x C up to the factor sqrt(2)
//   (|q|^2 = (|a|^2 + |b|^2) / 2), so every polynomial acts as two complex polynomials and K is
//   the product K_1 x K_2 of their filled Julia sets: the distance to it is
//   sqrt(d_1^2 + d_2^2) / sqrt(2), each d_i the complex estimate (0 inside K_i);
// - coquaternions and biquaternions (null elements, no escape radius): no estimate is known.
//   A point whose orbit leaves the ball |z| <= B at iteration n keeps every point within delta
//   outside K_N if the errors e_0 = delta, e_{k+1} = P'(|z_k| + e_k) e_k stay below |z_k| - B
//   at some k >= n (P' bounds |Dp| on balls: HypercomplexFormula::normBound): a proven, if
//   short, safe distance. The renderer marches these by Algorithm 2's fixed steps, skipping
//   ahead where that distance is longer.
#pragma once

#include <array>
#include <complex>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "quaternia/algebra/hypercomplex_formula.h"
#include "quaternia/algebra/vecmath.h"
#include "quaternia/fractal/algebra_rules.h"
#include "quaternia/fractal/distance_estimate.h"
#include "quaternia/fractal/duplex_component.h"
#include "quaternia/fractal/duplex_escape_map.h"
#include "quaternia/fractal/duplex_program.h"
#include "quaternia/fractal/fractal_settings.h"
#include "quaternia/fractal/julia_set.h"

namespace quaternia {

class HypercomplexJuliaSet final : public JuliaSet {
  public:
    // bailout 0: the escape radius for octonions (their norm is multiplicative, and the
    // formula's top-degree part must be one term), 4 for bicomplex numbers (POV-Ray's), 2 for
    // coquaternions and biquaternions. Throws UserError naming fractal.formula or
    // fractal.bailout.
    HypercomplexJuliaSet(HypercomplexFormula formula, int maxIterations, double bailout);

    Algebra algebra() const override { return formula_.algebra(); }
    DistanceKind distanceKind() const override { return kind_; }
    DistanceEstimate estimate(const Hypercomplex& z0) const override;
    // Bicomplex functions with disc forms (duplex_program.h) iterate in duplex form, and first
    // ask their certified maps (duplex_escape_map.h, built on first use), whose clearance the
    // fixed-step marcher skips by.
    bool contains(const Hypercomplex& z0) const override;
    bool containsByOrbit(const Hypercomplex& z0) const override;
    // The table's arithmetic in batches (algebra/orbit_batch.h) where the orbit is the table's
    // loop: every algebra but the quaternions (their programs) and the bicomplex numbers (duplex
    // form).
    int firstInside(const Hypercomplex* points, int count) const override;
    bool hasClearance() const override { return duplexPrograms_.has_value(); }
    uint64_t tableBytes() const override;
    double clearance(const Hypercomplex& z0) const override;
    // ln|z_M| after exactly M iterations (or where it overflows), and the M the normal takes at
    // z0: the iterate where the estimate was taken or the escape iteration, at most N - 1, as
    // algebraRules() says.
    double logRadiusAfter(const Hypercomplex& z0, int iterations) const override;
    int gradientIterations(const Hypercomplex& z0) const override;
    // The gradient of |z_M|^2 along the slice's three tangents (the chain rule through Dp), M =
    // gradientIterations(z0): the normal's direction, as QuaternionJuliaSet::potentialGradient.
    std::array<double, 3> potentialGradient(
        const Hypercomplex& z0, const std::array<Hypercomplex, 3>& tangents) const override;

    // Every formula but the bicomplex functions without a form (log, tan, ...) and real powers:
    // segments are iterated through the program and the multiplication table (interval/
    // segment_form.h, segmentLeavesBall; exp, sin, cos, sinh and cosh by function_forms.h).
    bool provesEmptySpace() const override { return intervalExtension_; }
    const FormulaProgram& program() const override { return formula_.program(); }
    bool hasIntervalExtension() const override { return intervalExtension_; }

    const HypercomplexFormula& formula() const { return formula_; }
    int maxIterations() const override { return maxIterations_; }
    double bailout() const override { return bailout_; }
    // K_N lies in the ball of radius bailout.
    double boundingRadius() const { return bailout_; }
    // Where orbits are certain to escape (octonions; the bailout for the other algebras).
    double escapeRadius() const override { return escapeRadius_; }
    // Bicomplex polynomials: duplex component i's complex polynomial (coefficients, lowest
    // degree first) and its escape radius; empty and 0 for functions and the other algebras.
    const std::vector<std::complex<double>>& componentCoefficients(size_t i) const {
        return componentCoefficients_[i];
    }
    double componentEscapeRadius(size_t i) const { return componentEscapeRadius_[i]; }
    // Bicomplex polynomials: duplex component i with its distance bound (duplex_component.h).
    const DuplexComponent& component(size_t i) const { return components_[i]; }

  private:
    // The estimate where the norm is multiplicative (octonions): the quaternions' loop with the
    // formula's derivative bound.
    DistanceEstimate multiplicativeEstimate(const Hypercomplex& z0) const;
    DistanceEstimate bicomplexEstimate(const Hypercomplex& z0) const;
    // A proven distance to K_N from the orbit's escape and the Lipschitz bounds of p along it
    // (header comment, docs/methods.md); orbits are followed at most kLipschitzOrbit iterates.
    static constexpr size_t kLipschitzOrbit = 256;
    // The escape maps' finest cells: 2^11 per axis of the square |Re w|, |Im w| <= sqrt(2) B.
    static constexpr int kEscapeMapLevel = 11;
    DistanceEstimate lipschitzDistance(const Hypercomplex& z0) const;

    HypercomplexFormula formula_;
    const AlgebraRules* rules_;
    int maxIterations_;
    double bailout_;
    double escapeRadius_;
    DistanceKind kind_;
    bool intervalExtension_ = false;
    bool batchesOrbits_ = false;  // firstInside by orbit_batch.h
    // bicomplex: the two complex polynomials of the duplex form (coefficients, lowest degree
    // first) and their escape radii
    std::array<std::vector<std::complex<double>>, 2> componentCoefficients_;
    std::array<double, 2> componentEscapeRadius_ = {0, 0};
    std::array<DuplexComponent, 2> components_;
    // Bicomplex functions whose operations all have disc forms: their orbits in duplex form, and
    // the certified maps of both components, built once, on first use (a render's threads share
    // them).
    std::optional<std::array<DuplexComponentProgram, 2>> duplexPrograms_;
    const DuplexEscapeMaps& escapeMaps() const;
    mutable std::once_flag escapeMapsBuilt_;
    mutable std::shared_ptr<const DuplexEscapeMaps> escapeMaps_;
};

// The set of fractal.formula with fractal.c in fractal.algebra, through the multiplication table
// (any algebra, the quaternions too). Throws UserError naming fractal.formula or fractal.bailout.
std::shared_ptr<const HypercomplexJuliaSet> hypercomplexJuliaSetOf(const FractalSettings& fractal);

}  // namespace quaternia
