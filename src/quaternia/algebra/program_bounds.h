// The analysis of a compiled formula (formula_program.h): what the hypercomplex Julia sets need
// to know of p beyond its values, found by one pass over the program's registers.
//
// normBound bounds |p(z)| by a polynomial in |z| (Euclidean norms of the components): |a b| <=
// kappa |a| |b| with the algebra's product bound kappa (hypercomplex.h, AlgebraArithmetic), |r a| =
// |r| |a| for a real r, and sums by the triangle inequality, so P(r) = sum_k bound[k] r^k >=
// |p(z)| for |z| = r, and P'(r) bounds the operator norm of the derivative Dp(z)
// (docs/methods.md, Other algebras). A program whose products are kept as written (every
// algebra but the quaternions) gives, register by register, the bounds of the formula's tree.
#pragma once

#include <optional>
#include <vector>

#include "quaternia/algebra/formula_program.h"
#include "quaternia/algebra/hypercomplex.h"
#include "quaternia/algebra/quaternion.h"

namespace quaternia {

// kappa with |a b| <= kappa |a| |b| for all a, b: algebraArithmetic(algebra).productBound.
double productBound(Algebra algebra);

struct ProgramBounds {
    // The degree of p; 2 for transcendental programs (for colouring).
    int degree = 0;
    // Whether the program has functions or real powers (bicomplex only): then no norm bound
    // holds (normBound, derivativeNormBound and topDegreeMinimum mean nothing).
    bool transcendental = false;
    // P's coefficients, lowest degree first (size degree + 1).
    std::vector<double> normBound;
    // Where the norm is multiplicative: m <= |p_d(u)| for every unit u, p_d the top-degree part,
    // certified register by register (exact for a single top-degree term, the product of its
    // coefficients' norms; top-degree sums m_a - B_b, which may be 0). 0 otherwise.
    double topDegreeMinimum = 0;
    // A unit u of span{i, j, k} with u^2 = -1 in the algebra such that every constant of the
    // formula (c included, where it appears) lies in span{1, u} (to inPlane's tolerance, its
    // components 4 .. 7 exactly 0); u is the first such constant's direction, i where every
    // constant is real. span{1, u} is then a copy of C that the formula maps into itself, where
    // it acts as the same formula does on span{1, u} in H: the complex polynomial of the
    // quaternion expansion (complex_polynomial.h, restrictToComplexPlane). Nothing for
    // transcendental programs, or where no such u exists.
    std::optional<Quaternion> complexAxis;

    // P'(r): a bound of the operator norm of Dp(z) for |z| <= r.
    double derivativeNormBound(double r) const;
};

ProgramBounds analyzeProgram(const FormulaProgram& program);

}  // namespace quaternia
