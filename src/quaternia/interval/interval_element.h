// Boxes of an algebra of section 2.3 (algebra/hypercomplex.h) in interval arithmetic
// (interval.h): an IntervalElement holds an interval per component, and stands for every
// element whose components lie in them. The product follows the algebra's multiplication table
// (every algebra: quaternions, bicomplex numbers, coquaternions, biquaternions, octonions), a
// formula's program runs on boxes (evaluateOnBox), and boxLeavesBall decides, by iterating a
// box, that none of its points belongs to K_N: the renderer's proven test of empty space for the
// algebras that have no distance estimate (docs/methods.md, Other algebras).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "quaternia/algebra/element.h"
#include "quaternia/algebra/formula_program.h"
#include "quaternia/algebra/hypercomplex.h"
#include "quaternia/interval/interval.h"

namespace quaternia {

using IntervalElement = Element<Interval, kMaxAlgebraDimension>;

// The box of the single element a (exact).
IntervalElement pointBox(const Hypercomplex& a);
// Whether every element of the box (its first `dimension` components) contains a's.
bool boxContains(const IntervalElement& box, const Hypercomplex& a, int dimension);

// Encloses {a b : a in A, b in B}, summed as the table says (sum_ij sign(i, j) a_i b_j
// e_index(i, j)).
IntervalElement multiply(const MultiplicationTable& table, const IntervalElement& a,
                         const IntervalElement& b);
// Encloses {a a : a in A}: the products a_i a_i as squares and a_i a_j + a_j a_i (i < j) as one
// product, which a general product of two boxes cannot know are of the same numbers.
IntervalElement square(const MultiplicationTable& table, const IntervalElement& a);
// A lower bound of |a|^2 over the box (the Euclidean norm of the components).
double lowerNormSquared(const IntervalElement& a, int dimension);

// The part of a program with no interval extension yet (a real power, or a function other than
// exp, sin, cos, sinh and cosh: function_forms.h), named for a one-line refusal ("the function
// log", "a real power"); nothing where the whole program has one.
std::optional<std::string> withoutIntervalExtension(const FormulaProgram& program);

// Encloses {p(z) : z in box} for a program with an interval extension (the caller checks
// withoutIntervalExtension). `registers` is scratch space, resized as needed, so that a caller
// iterating many boxes allocates once.
IntervalElement evaluateOnBox(const FormulaProgram& program, const MultiplicationTable& table,
                              const IntervalElement& box, std::vector<IntervalElement>& registers);

// Whether no point of the box belongs to K_N of p with this bailout: some iterate z_n,
// n < maxIterations (those the membership test reads: z_0 .. z_{N-1}), lies wholly outside the
// ball |z| <= bailout for every z_0 in the box. False proves nothing.
bool boxLeavesBall(const FormulaProgram& program, const MultiplicationTable& table,
                   const IntervalElement& box, int maxIterations, double bailout,
                   std::vector<IntervalElement>& registers);

// An upper bound of |a|^2 over the box (infinity where a bound is not finite).
double upperNormSquared(const IntervalElement& a, int dimension);
// Whether every point of the box belongs to K_N of p with this bailout: every iterate z_n,
// n < maxIterations, lies wholly inside the ball |z| <= bailout for every z_0 in the box (the
// same iterates as boxLeavesBall). False proves nothing. For a box about a single point (the
// rounding of where it was computed), the proof that the point is in K_N (render/
// pixel_certificate.h's certain hits).
bool boxStaysInBall(const FormulaProgram& program, const MultiplicationTable& table,
                    const IntervalElement& box, int maxIterations, double bailout,
                    std::vector<IntervalElement>& registers);
// boxStaysInBall for the box of every element within `radius` of `centre` in each of the
// table's components (thread-local scratch).
bool boxAboutStaysInBall(const FormulaProgram& program, const MultiplicationTable& table,
                         const Hypercomplex& centre, double radius, int maxIterations,
                         double bailout);

}  // namespace quaternia
