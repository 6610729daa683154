// What an escape-time estimate returns (DistanceEstimate), and the pieces every estimate in
// every algebra shares: the continuation past the bailout, the distance of an uncertain escape,
// the estimate of a point of K_N and the smooth escape count (distance.h tells what is proven).
#pragma once

#include <algorithm>
#include <cmath>

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

// The continuous escape count n + 1 - log_d(ln|z_n|) of an orbit that has |z_n|^2 = radiusSquared
// after n iterations, far outside the set: the renormalised iteration count (Vepstas 1997;
// Peitgen, Richter 1986), continuous in z_0 because ln|z_{n+1}| ~ d ln|z_n| there. Degrees
// below 2 count as 2.
double smoothEscapeCount(int n, double radiusSquared, int degree);

}  // namespace quaternia
