// Segments of an algebra of section 2.3 in affine arithmetic with one noise symbol (de
// Figueiredo and Stolfi, "Affine arithmetic: concepts and applications", Numerical Algorithms
// 37, 2004): a SegmentForm stands for the points centre + slope e + r, e in [-1, 1] and each
// |r_k| <= radius_k, the segment from centre - slope to centre + slope thickened by a box. A ray
// segment through the slice is one such form, exactly (the slice is affine); the formula's
// program runs on it (evaluateOnSegment) keeping the first-order dependence on e exact, so that
// only second-order terms and rounding widen it. Iterated boxes (interval_element.h) cannot
// know that the points of a segment lie on a line: a box about a diagonal segment of length L in
// 4D holds every point within L / 2 of its centre along each axis, and its iterates widen by the
// whole box each time. That is why the renderer crosses empty space by segments
// (segmentLeavesBall), Knoll et al.'s finding for rays through implicit surfaces ("Fast ray
// tracing of arbitrary implicit surfaces with interval and affine arithmetic", Computer
// Graphics Forum 28(1), 2009).
//
// Products through the multiplication table: x y = (xc + xs e + xr)(yc + ys e + yr) =
// xc yc + (xs ys) e^2 + (xc ys + xs yc) e + [terms with a remainder], and e^2 = 1/2 + (e^2 -
// 1/2) with |e^2 - 1/2| <= 1/2: the centre gains (xs ys) / 2, the radius |xs ys| / 2. The terms
// with a remainder are bounded by the table's product with every sign +, applied to absolute
// values (|a| (+) r). Rounding: each centre and slope component is a sum of at most 2 d^2
// products, whose error is at most gamma_{2d^2+1} times the same sum of absolute values
// (Higham, "Accuracy and Stability of Numerical Algorithms", 2002, section 3.1), added to the
// radius; every radius, a sum of non-negative products computed in round-to-nearest, is then
// scaled by 1 + 2^-40 (more than gamma of 400 operations) and raised by 2^-1000.
#pragma once

#include <array>
#include <vector>

#include "quaternia/algebra/formula_program.h"
#include "quaternia/algebra/hypercomplex.h"

namespace quaternia {

struct SegmentForm {
    Hypercomplex centre{}, slope{};
    std::array<double, kMaxAlgebraDimension> radius{};  // each >= 0
};

// The segment from `from` to `to` thickened by `thickness` in every component (a tube about
// it; 0 for the segment alone), in the first `dimension` components.
SegmentForm segmentBetween(const Hypercomplex& from, const Hypercomplex& to, double thickness,
                           int dimension);
// Whether the form holds the point centre + slope e + r for this e (tests).
bool formContains(const SegmentForm& form, double e, const Hypercomplex& point, int dimension);
// A lower bound of |z| over every point z of the form.
double lowerNorm(const SegmentForm& form, int dimension);

// Encloses {p(z) : z in form} for a program with an interval extension (interval_element.h,
// withoutIntervalExtension), with the dependence on e kept to first order.
SegmentForm evaluateOnSegment(const FormulaProgram& program, const MultiplicationTable& table,
                              const SegmentForm& form);

// Whether no point of the form belongs to K_N of p with this bailout: some iterate z_n,
// n < maxIterations, lies wholly outside the ball |z| <= bailout for every point. False proves
// nothing (it also gives up where a remainder has grown past the ball).
bool segmentLeavesBall(const FormulaProgram& program, const MultiplicationTable& table,
                       const SegmentForm& form, int maxIterations, double bailout);

// A tube: centre + slopes[0] e_0 + slopes[1] e_1 + slopes[2] e_2 + r, each e_s in [-1, 1] and
// |r_k| <= radius_k, the segment from centre - slopes[0] to centre + slopes[0] swept over the
// parallelogram of slopes[1] and slopes[2]. A pixel's cone through the 3D slice is one such
// form (the slice is affine): its cross-section's two directions as symbols of their own keep
// their first-order dependence exact through every iterate, where a box remainder of the same
// size would grow by the absolute values of the Jacobian (up to twice as fast per iterate in
// the quaternions), so tubes about rays are proven almost as near the set as the rays alone.
// Products as for segments, each e_s^2 = 1/2 + [-1/2, 1/2] and each e_s e_t, s != t, in
// [-1, 1] bounded in the radius; functions carry the first symbol and bound the others.
struct TubeForm {
    static constexpr int kSymbols = 3;
    Hypercomplex centre{};
    std::array<Hypercomplex, kSymbols> slopes{};
    std::array<double, kMaxAlgebraDimension> radius{};  // each >= 0
};
// The segment from `from` to `to` swept over the parallelogram of +-across1 and +-across2,
// thickened by `thickness` in every component, in the first `dimension` components.
TubeForm tubeAbout(const Hypercomplex& from, const Hypercomplex& to, const Hypercomplex& across1,
                   const Hypercomplex& across2, double thickness, int dimension);
// evaluateOnSegment for a tube; and whether the tube holds the point at these e (tests).
TubeForm evaluateOnTube(const FormulaProgram& program, const MultiplicationTable& table,
                        const TubeForm& form);
bool tubeContains(const TubeForm& form, const std::array<double, TubeForm::kSymbols>& e,
                  const Hypercomplex& point, int dimension);
// segmentLeavesBall for a tube.
bool tubeLeavesBall(const FormulaProgram& program, const MultiplicationTable& table,
                    const TubeForm& form, int maxIterations, double bailout);

}  // namespace quaternia
