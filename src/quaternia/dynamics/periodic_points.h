// All periodic points of period n of a complex polynomial f of degree d >= 2: the roots of
// h_n = prod over k | n of (f^k(z) - z)^mu(n/k) (mu the Moebius function), which has degree
// sum over k | n of mu(n/k) d^k and whose roots are the points of exact period n (the lower
// periods divided out), found all at once by Aberth-Ehrlich and grouped into cycles.
// docs/facts.md, Periodic points, and Cycles and multipliers of z^2 + c for what the tests check.
#pragma once

#include <complex>
#include <cstdint>
#include <vector>

#include "quaternia/algebra/complex_polynomial.h"
#include "quaternia/dynamics/cycle.h"

namespace quaternia {

// The most periodic points `periodicPoints` looks for: d^n is limited to this. Aberth-Ehrlich
// costs count^2 per sweep and needs more sweeps as the count grows: period 10 of z^2 + c
// (990 points) takes seconds, and each period more doubles the count and so more than
// quadruples the time.
inline constexpr int64_t kMaxPeriodicPoints = 1024;

// sum over k | n of mu(n/k) d^k: the number of points of exact period n, with multiplicity.
// Requires n >= 1 and d^n <= kMaxPeriodicPoints.
int64_t periodicPointCount(int degree, int period);

struct PeriodicCycle {
    // points[k + 1] = f(points[k]) (matched to the computed roots), starting at the point of
    // least modulus.
    std::vector<Complex> points;
    // The exact period: the requested n, or less where a parabolic bifurcation makes the points
    // of period n coincide with a cycle of lower period (e.g. the 2-cycle at c = -3/4, which
    // collapses onto the fixed point -1/2); then `degenerate` is set.
    int period = 0;
    bool degenerate = false;
    int multiplicity = 1;  // a multiple root of h_n (the double fixed point 1/2 at c = 1/4)
    Complex multiplier;    // prod f'(points[k]) over the n points
    Classification classification;
    double residual = 0;   // max |f^n(z) - z| over the points
    bool complete = true;  // every image f(z) matched one of the roots
};

struct PeriodicPoints {
    int period = 0;
    int64_t count = 0;                  // deg h_n
    std::vector<PeriodicCycle> cycles;  // sorted by the real, then imaginary part of points[0]
};

// Throws UserError("period", ...) for n < 1, d < 2 or d^n > kMaxPeriodicPoints.
PeriodicPoints periodicPoints(const ComplexPolynomial& f, int period);

}  // namespace quaternia
