// Iteration of a quaternion polynomial (Def. 2.1 of the seed paper), membership in the filled
// Julia set K_N, and the distance estimate d = 0.5 |z_n| ln|z_n| / |z'_n| (Hart, Sandin,
// Kauffman 1989).
//
// What is proven and what is not:
// - z^2 + c: d is a lower bound of the distance to K near the set (Dang, Kauffman, Sandin 2002),
//   and |z'| is carried exactly as a scalar, |z'_{n+1}| = 2 |z_n| |z'_n|, equal in norm to the
//   quaternion product 2 z z'. The same 0.5 serves z^d + c with |z'| <- d |z|^(d-1) |z'|.
// - Any other polynomial: |z'| is replaced by rho_{n+1} = P'(|z_n|) rho_n, P(r) the sum of the
//   coefficient-norm products times r^degree, which bounds the operator norm of the Jacobian of
//   f^n from above, so d can only shrink: a conservative estimate, but no theorem makes it a
//   lower bound of the distance (tests check it against sampled grids instead).
// - The estimate is of the distance to K. The drawn set is K_N (N iterations), which contains K
//   and a thin shell K_N \ K of points escaping after N: a step may end inside that shell, where
//   the marcher stops (membership is tested at every step), but a shell thinner than the
//   confirmation step can be crossed. The shell vanishes as N grows.
// - Far from the set d overshoots (c = 0: 0.5 r ln r > r - 1 beyond r = 4.92): marching starts
//   on the bounding sphere.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <optional>

#include "quaternia/algebra/formula_program.h"
#include "quaternia/algebra/polynomial.h"
#include "quaternia/algebra/quaternion.h"
#include "quaternia/fractal/distance_estimate.h"
#include "quaternia/fractal/julia_set.h"

namespace quaternia {

// The highest degree d of s z^d + c that the SIMD lanes take (LaneFractal::from); higher
// degrees use the scalar path.
inline constexpr int kMaxLaneDegree = 16;

// The filled Julia set K_N of p: points whose iterates z_0 .. z_{N-1} all satisfy |z| <= bailout
// (POV-Ray's convention, tests/data/reference), N = max_iterations. The quaternions' JuliaSet
// (julia_set.h): its methods of points of H are the interface's at points whose components past
// the fourth are 0.
class QuaternionJuliaSet final : public JuliaSet {
  public:
    // bailout 0 selects the polynomial's certified escape radius; a positive bailout must exceed
    // 1 so that ln|z| > 0 at escape. Throws UserError naming fractal.formula or fractal.bailout.
    // `program` computes the same polynomial for the SIMD lanes (from the formula as written);
    // without one, it is compiled from the expansion term by term.
    QuaternionJuliaSet(Polynomial polynomial, int maxIterations, double bailout,
                       std::shared_ptr<const FormulaProgram> program = nullptr);

    DistanceEstimate estimate(const Quaternion& z0) const;
    bool contains(const Quaternion& z0) const;

    // The gradient of |z_M|^2 with respect to the 3 directions whose images in H are `tangents`
    // (the columns of the slice's Jacobian), with M the iteration count that estimate() reaches:
    // a normal of the level sets of the potential, from one pass through the Jacobians of p.
    std::array<double, 3> potentialGradient(const Quaternion& z0,
                                            const std::array<Quaternion, 3>& tangents) const;

    // ln|z_M| after exactly M iterations, and the M that potentialGradient() differentiates at
    // z0: for checking the analytic gradient against finite differences.
    double logRadiusAfter(const Quaternion& z0, int iterations) const;
    int gradientIterations(const Quaternion& z0) const;

    // The JuliaSet interface.
    Algebra algebra() const override { return Algebra::kQuaternion; }
    DistanceKind distanceKind() const override { return DistanceKind::kEstimate; }
    DistanceEstimate estimate(const Hypercomplex& z0) const override {
        return estimate(quaternionOf(z0));
    }
    bool contains(const Hypercomplex& z0) const override { return contains(quaternionOf(z0)); }
    double logRadiusAfter(const Hypercomplex& z0, int iterations) const override {
        return logRadiusAfter(quaternionOf(z0), iterations);
    }
    int gradientIterations(const Hypercomplex& z0) const override {
        return gradientIterations(quaternionOf(z0));
    }
    std::array<double, 3> potentialGradient(
        const Hypercomplex& z0, const std::array<Hypercomplex, 3>& tangents) const override {
        return potentialGradient(
            quaternionOf(z0),
            {quaternionOf(tangents[0]), quaternionOf(tangents[1]), quaternionOf(tangents[2])});
    }

    // The proofs of interval/ (JuliaSet) iterate the program; the renderer does not cross by
    // them (provesEmptySpace stays false: the estimate marches), the certificates do.
    bool hasIntervalExtension() const override { return intervalExtension_; }

    const Polynomial& polynomial() const { return polynomial_; }
    const FormulaProgram& program() const override { return *program_; }
    int maxIterations() const override { return maxIterations_; }
    double escapeRadius() const override { return escapeRadius_; }  // certified: |z| > R escapes
    double bailout() const override { return bailout_; }            // membership radius
    double boundingRadius() const { return bailout_; }              // K_N lies in this ball

  private:
    static Quaternion quaternionOf(const Hypercomplex& q) { return {q[0], q[1], q[2], q[3]}; }
    Quaternion derivative(const Quaternion& z, const Quaternion& h) const;  // Dp(z)[h]

    Polynomial polynomial_;
    std::shared_ptr<const FormulaProgram> program_;
    std::optional<PowerForm> power_;
    int maxIterations_;
    double escapeRadius_;
    double bailout_;
    int degree_;
    double estimateRadiusSquared_;  // where the continuation stops
    bool intervalExtension_;        // !withoutIntervalExtension(program)
};

}  // namespace quaternia
