// The fate of one orbit z_0, z_1 = p(z_0), ... of a quaternion polynomial (complex maps are the
// case where every coefficient and z_0 lie in one plane C_u): escape, landing on a cycle, or
// convergence to an attracting cycle (seed paper section 2.2; docs/facts.md, Cycles and multipliers
// of z^2 + c).
//
// Semantics, with tol = tolerance * max(1, largest |z_k| so far) (rounding grows with the
// orbit's scale):
// - Escapes: |z_k| > p.escapeRadius() at iteration k. Certain: the orbit then tends to infinity.
// - A cycle is detected when z_k comes within tol of an earlier z_{k-n}; it is refined by
//   Newton's method on f^n(w) = w (the 4x4 Jacobian of f^n in H), its exact period is the
//   least divisor d of n with |f^d(w) - w| <= tol, and its multipliers are computed there.
// - Periodic: z_0 itself is within tol of the cycle (a fixed point when the period is 1).
// - Preperiodic (strictly): z_0 is not on the cycle but z_m is, for m > 0 the first such index.
//   A repelling or saddle cycle attracts nothing, so reaching it is landing on it. For an
//   attracting cycle, landing is told from converging by the jump: z_m is within rounding
//   (1e-3 tol) of the cycle while z_{m-1} was far from it (1e-4 of the scale) -- convergence,
//   even superattracting, cannot cover that in one step.
// - Attracted: the orbit converges to an attracting cycle and came within tol of it at
//   iteration `preperiod`.
// - Undecided: neither escape nor a cycle within maxIterations (e.g. orbits in J, or slow
//   convergence to a neutral cycle).
// `unsure` marks results that rounding could change (neutral cycles, a Newton refinement that
// failed, a multiplier within kUnsureBand of a class boundary); `note` says why.
//
// The same analysis runs in the other algebras of hypercomplex.h (analyzeHypercomplexOrbit):
// the map is the HypercomplexFormula, the Jacobian of f^n is N x N with N the algebra's
// dimension (4 or 8), built from its directional derivatives along the basis, and the class is
// that of its eigenvalues; the complex multiplier is that of the copy span{1, u} of C the
// formula maps into itself (HypercomplexFormula::complexAxis), for cycles in it, where p is
// complex-analytic and its derivative along 1 is p'(z). Escape is |z| > the set's escape
// radius (HypercomplexJuliaSet::escapeRadius): certain for octonions and bicomplex numbers,
// K_N's test for coquaternions and biquaternions, whose null elements leave no radius certain.
#pragma once

#include <array>
#include <complex>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "quaternia/algebra/complex_polynomial.h"
#include "quaternia/algebra/hypercomplex_formula.h"
#include "quaternia/algebra/polynomial.h"
#include "quaternia/dynamics/cycle.h"
#include "quaternia/fractal/distance.h"
#include "quaternia/fractal/hypercomplex_julia.h"

namespace quaternia {

enum class OrbitFate { Escapes, Periodic, Preperiodic, Attracted, Undecided };

std::string toString(OrbitFate fate);

// A cycle of a map on points `Point` of an N-dimensional algebra: Quaternion and 4 for H
// (CycleAnalysis), Hypercomplex and 4 or 8 for the others (HypercomplexCycleAnalysis).
template <typename Point, std::size_t N>
struct BasicCycleAnalysis {
    std::vector<Point> points;  // points[k + 1] = p(points[k]); points[0] is where the
                                // orbit meets the cycle
    int period() const { return int(points.size()); }
    Matrix<N> jacobian{};  // of f^n at points[0]
    std::array<std::complex<double>, N> eigenvalues{};
    Classification classInH;  // the class from the eigenvalues, in H or the algebra
    // When the coefficients and the cycle lie in one plane C_u: the complex multiplier
    // lambda = prod p'(z_k) of the restriction, in the coordinates x + y u, and its class.
    std::optional<std::complex<double>> multiplier;
    Quaternion axis = kUnitI;  // u
    Classification complexClass;
    double residual = 0;   // max over the points of |f^n(w) - w|
    bool refined = false;  // Newton converged; otherwise the points are the orbit's own
};

using CycleAnalysis = BasicCycleAnalysis<Quaternion, 4>;
template <std::size_t N>
using HypercomplexCycleAnalysis = BasicCycleAnalysis<Hypercomplex, N>;

// Multipliers, eigenvalues and classes of a cycle given by its first point (already refined).
CycleAnalysis analyzeCycle(const Polynomial& p, const Quaternion& start, int period);

struct OrbitOptions {
    int maxIterations = 1000;
    int maxPeriod = 512;      // longest period looked for
    double tolerance = 1e-9;  // relative to the orbit's scale
};

template <typename Cycle>
struct BasicOrbitResult {
    OrbitFate fate = OrbitFate::Undecided;
    int escapeIteration = -1;  // Escapes: the first k with |z_k| > escapeRadius
    int preperiod = 0;         // Preperiodic: m; Attracted: the iteration it came within tol
    std::optional<Cycle> cycle;
    // The class that governs this orbit: complex when the orbit lies in the plane of the
    // coefficients, else in H.
    Classification governingClass;
    bool unsure = false;
    std::string note;
    double escapeRadius = 0;
    double tolerance = 0;  // the absolute tolerance at the end
    int iterations = 0;    // iterates computed
};

using OrbitResult = BasicOrbitResult<CycleAnalysis>;
template <std::size_t N>
using HypercomplexOrbitResult = BasicOrbitResult<HypercomplexCycleAnalysis<N>>;

// Throws UserError (from Polynomial::escapeRadius) for a degree below 2 or a possibly
// unbounded polynomial.
OrbitResult analyzeOrbit(const Polynomial& p, const Quaternion& z0,
                         const OrbitOptions& options = {});

// The orbit of z0 under `formula` in its algebra, escaping where |z| > escapeRadius (the
// HypercomplexJuliaSet's escapeRadius()). N must be formula.dimension() (4 or 8); throws
// std::invalid_argument otherwise.
template <std::size_t N>
HypercomplexOrbitResult<N> analyzeHypercomplexOrbit(const HypercomplexFormula& formula,
                                                    double escapeRadius, const Hypercomplex& z0,
                                                    const OrbitOptions& options = {});
// The Jacobian of the formula at z: column a is the derivative along e_a (N = dimension()).
template <std::size_t N>
Matrix<N> hypercomplexJacobian(const HypercomplexFormula& formula, const Hypercomplex& z);

// The orbit of z0 (components past the algebra's dimension 0) under the map of `set` in its own
// algebra (fractal/julia_set.h), escaping beyond the set's escape radius: the one analysis
// above, whichever the algebra, through the quaternions' polynomial (QuaternionJuliaSet, as
// analyzeOrbit) or the formula's multiplication table (HypercomplexJuliaSet, as
// analyzeHypercomplexOrbit with its dimension).
using AnyOrbitResult =
    std::variant<OrbitResult, HypercomplexOrbitResult<4>, HypercomplexOrbitResult<8>>;
AnyOrbitResult analyzeOrbit(const JuliaSet& set, const Hypercomplex& z0,
                            const OrbitOptions& options = {});

// A complex polynomial as the quaternion polynomial sum a_k z^k with coefficients in C_i.
Polynomial quaternionPolynomial(const ComplexPolynomial& p);

}  // namespace quaternia
