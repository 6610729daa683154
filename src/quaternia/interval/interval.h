// Interval arithmetic with outward rounding (Moore, Kearfott and Cloud, "Introduction to
// Interval Analysis", SIAM 2009, chapters 2 and 4): an Interval [lo, hi] stands for every real
// number between its bounds, and each operation returns an interval that holds every result of
// the operation on numbers of its operands, the rounding of the computation included. It is the
// proof behind the renderer's empty-space test (interval_element.h): where the interval image
// of a box of points lies wholly outside the bailout ball, no point of the box is in K_N.
//
// Rounding is outward by a proven error bound per operation, not by switching the FPU's
// rounding mode (which the compiler may not respect, and which the lanes cannot switch per
// lane): each bound is computed in round-to-nearest, whose error is at most half an ulp, and
// then moved outward by margin(r) = |r| 2^-51 + 2^-1021. For a normal r the margin is at
// least two ulps of r, so the bound moved by it and rounded again (half an ulp of a result at
// most twice r's ulp) still lies beyond the exact value; below 2^-970 the constant term is
// at least two ulps. Intervals are therefore a few ulps wider than the tightest, and
// Interval.OperationsEncloseTheExactResult checks each operation against exact arithmetic
// (double-double results of TwoSum and TwoProduct) on random operands. Infinite or NaN bounds
// are never proven: the tests that read intervals (lowerSquare, interval_element.h) treat them
// as undecided.
#pragma once

#include <algorithm>
#include <cmath>

namespace quaternia {

// A bound of r moved outward past r's rounding error (header comment).
inline double roundedDown(double r) {
    return r - (std::fabs(r) * 0x1p-51 + 0x1p-1021);
}
inline double roundedUp(double r) {
    return r + (std::fabs(r) * 0x1p-51 + 0x1p-1021);
}

struct Interval {
    double lo = 0, hi = 0;

    // The exact number x.
    static Interval point(double x) { return {x, x}; }
    // The least interval holding a and b, which are exact.
    static Interval hull(double a, double b) { return {std::min(a, b), std::max(a, b)}; }
    bool contains(double x) const { return lo <= x && x <= hi; }
    double width() const { return hi - lo; }
};

inline Interval operator+(const Interval& a, const Interval& b) {
    return {roundedDown(a.lo + b.lo), roundedUp(a.hi + b.hi)};
}
inline Interval operator-(const Interval& a, const Interval& b) {
    return {roundedDown(a.lo - b.hi), roundedUp(a.hi - b.lo)};
}
// Exact.
inline Interval operator-(const Interval& a) {
    return {-a.hi, -a.lo};
}
inline Interval operator*(const Interval& a, const Interval& b) {
    const double p0 = a.lo * b.lo, p1 = a.lo * b.hi, p2 = a.hi * b.lo, p3 = a.hi * b.hi;
    return {roundedDown(std::min(std::min(p0, p1), std::min(p2, p3))),
            roundedUp(std::max(std::max(p0, p1), std::max(p2, p3)))};
}
// A real factor s (exact) times a.
inline Interval operator*(double s, const Interval& a) {
    const double p0 = s * a.lo, p1 = s * a.hi;
    return {roundedDown(std::min(p0, p1)), roundedUp(std::max(p0, p1))};
}
// {x^2 : x in a}: tighter than a * a, which does not know that both factors are the same number
// (the dependency problem: [-1, 1] * [-1, 1] = [-1, 1], its square [0, 1]).
inline Interval square(const Interval& a) {
    if (a.lo >= 0) return {roundedDown(a.lo * a.lo), roundedUp(a.hi * a.hi)};
    if (a.hi <= 0) return {roundedDown(a.hi * a.hi), roundedUp(a.lo * a.lo)};
    return {0, roundedUp(std::max(a.lo * a.lo, a.hi * a.hi))};
}
// The least |x| over a (its mignitude), exact.
inline double mignitude(const Interval& a) {
    if (a.lo > 0) return a.lo;
    if (a.hi < 0) return -a.hi;
    return 0;
}
// A lower bound of x^2 over a (0 where a bound is NaN: nothing proven).
inline double lowerSquare(const Interval& a) {
    if (!(a.lo <= a.hi)) return 0;
    const double m = mignitude(a);
    return m > 0 ? std::max(0.0, roundedDown(m * m)) : 0.0;
}

}  // namespace quaternia
