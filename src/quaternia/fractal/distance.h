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

namespace quaternia {

struct DistanceEstimate {
    double distance = 0;      // lower-bound estimate in H; 0 for a point of K_N
    bool inside = false;      // |z_n| <= bailout for every n < max_iterations
    int escapeIteration = 0;  // first n with |z_n| > bailout (max_iterations when inside)
    int iterations = 0;       // polynomial evaluations done, continuation included (for statistics)
    double trap = 0;          // min over the orbit of |z_n|: an orbit trap for colouring
    double smoothIteration = 0;  // continuous escape count, for colouring
};

// The estimate is evaluated once |z| passes 1e4 or after kMaxContinuation iterations past the
// bailout, whichever comes first: its relative error falls like 1 / ln|z| (Hart et al.). For
// high degrees the radius shrinks so that one more step, |z|^(2d), stays finite in T.
inline constexpr int kMaxContinuation = 64;
template <class T>
double continuationRadiusSquared(int degree) {
    const double largest = sizeof(T) == sizeof(float) ? 1e30 : 1e300;
    return std::min(sizeof(T) == sizeof(float) ? 1e4 : 1e8,
                    std::pow(largest, 1.0 / std::max(1, degree)));
}

// The estimate of a point whose orbit passed the bailout B (|z_n|^2 = r2 > B^2) but not the
// certified escape radius, where a bailout below that radius leaves escape uncertain: the orbit
// may come back, so the point lies outside K_N (it failed the test at n) but not necessarily
// far from it, and 0.5 |z| ln|z| / |z'|, the distance to the limit set K = {G = 0} of an orbit
// that escapes for good, is no bound on the distance to K_N there: near points of K_N whose
// orbits return it overshot by many times (a set with |c| = 1.39 and bailout 1.69, whose escape
// radius is 1.80: 0.29 where K_N lay 0.196 ahead). K_N lies in {q : |f^n(q)| <= B}, and to first
// order a step h changes z_n by at most |z'_n| |h| (|z'_n| bounds the derivative's norm), so
// the distance to that set is at least (|z_n| - B) / |z'_n| to first order; half of it, as the
// escaping estimate takes half of G / |grad G|.
inline double uncertainEscapeDistance(double r2, double bailoutSquared, double derivativeSquared) {
    return std::max(
        0.0, 0.5 * (std::sqrt(r2) - std::sqrt(bailoutSquared)) / std::sqrt(derivativeSquared));
}

// The estimate of a point of K_N whose orbit came no nearer the origin than `trap`.
inline DistanceEstimate insideEstimate(double trap, int maxIterations) {
    DistanceEstimate result;
    result.inside = true;
    result.trap = trap;
    result.escapeIteration = result.iterations = maxIterations;
    result.smoothIteration = maxIterations;
    return result;
}

// The highest degree d of s z^d + c that the SIMD lanes take (LaneFractal::from); higher
// degrees use the scalar path.
inline constexpr int kMaxLaneDegree = 16;

// The continuous escape count n + 1 - log_d(ln|z_n|) of an orbit that has |z_n|^2 = radiusSquared
// after n iterations, far outside the set: the renormalised iteration count (Vepstas 1997;
// Peitgen, Richter 1986), continuous in z_0 because ln|z_{n+1}| ~ d ln|z_n| there. Degrees
// below 2 count as 2.
double smoothEscapeCount(int n, double radiusSquared, int degree);

// The filled Julia set K_N of p: points whose iterates z_0 .. z_{N-1} all satisfy |z| <= bailout
// (POV-Ray's convention, tests/data/reference), N = max_iterations.
class JuliaSet {
  public:
    // bailout 0 selects the polynomial's certified escape radius; a positive bailout must exceed
    // 1 so that ln|z| > 0 at escape. Throws UserError naming fractal.formula or fractal.bailout.
    // `program` computes the same polynomial for the SIMD lanes (from the formula as written);
    // without one, it is compiled from the expansion term by term.
    JuliaSet(Polynomial polynomial, int maxIterations, double bailout,
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

    const Polynomial& polynomial() const { return polynomial_; }
    const FormulaProgram& program() const { return *program_; }
    int maxIterations() const { return maxIterations_; }
    double escapeRadius() const { return escapeRadius_; }  // certified: |z| > R escapes
    double bailout() const { return bailout_; }            // membership radius
    double boundingRadius() const { return bailout_; }     // K_N lies in this ball

  private:
    Quaternion derivative(const Quaternion& z, const Quaternion& h) const;  // Dp(z)[h]

    Polynomial polynomial_;
    std::shared_ptr<const FormulaProgram> program_;
    std::optional<PowerForm> power_;
    int maxIterations_;
    double escapeRadius_;
    double bailout_;
    int degree_;
    double estimateRadiusSquared_;  // where the continuation stops
};

}  // namespace quaternia
