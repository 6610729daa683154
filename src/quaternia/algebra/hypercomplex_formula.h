// A formula (formula.h) evaluated in one of the algebras of hypercomplex.h: the parse tree made
// a straight-line list of operations whose products go through the algebra's multiplication
// table, in the order written (left to right, parentheses honoured), which is what an algebra
// that is not associative (the octonions) needs; powers multiply on the left, z (z (... z)),
// equal to every other bracketing in these power-associative algebras.
//
// The formula's constants are written with 1, i, j and k: they are components 0 .. 3 of the
// algebra (for the 8-component algebras, of the quaternion half a of a + b h or (a, b)); the
// name c stands for the scene's c with all of the algebra's components.
//
// normBound() bounds |p(z)| by a polynomial in |z| (Euclidean norms of the components):
// |a b| <= kappa |a| |b| with the algebra's productBound() kappa, and sums by the triangle
// inequality, so P(r) = sum_k bound[k] r^k >= |p(z)| for |z| = r, and P'(r) bounds the operator
// norm of the derivative Dp(z) (docs/methods.md, Other algebras).
#pragma once

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "quaternia/algebra/formula.h"
#include "quaternia/algebra/hypercomplex.h"

namespace quaternia {

// kappa with |a b| <= kappa |a| |b| for all a, b: 1 where the norm is multiplicative
// (quaternions, octonions), sqrt(2) for the bicomplex numbers (duplex form: |q|^2 is half the
// sum of the two complex norms squared), the biquaternions (Cauchy-Schwarz on the quaternion
// halves) and the coquaternions (2x2 real matrices, whose Frobenius norm is sqrt(2) |q| and
// submultiplicative). Each is attained.
double productBound(Algebra algebra);

class HypercomplexFormula {
  public:
    // Throws UserError("fractal.formula", ...) for a formula without terms.
    HypercomplexFormula(const Formula& formula, Algebra algebra, const Hypercomplex& c);

    Algebra algebra() const { return algebra_; }
    int dimension() const { return dimension_; }
    int degree() const { return degree_; }

    Hypercomplex evaluate(const Hypercomplex& z) const;
    // p(z) and its derivative Dp(z)[h] in direction h, together (forward mode: each operation
    // carries its value and its derivative; d(uv) = du v + u dv in the order written).
    std::pair<Hypercomplex, Hypercomplex> evaluateWithDerivative(const Hypercomplex& z,
                                                                 const Hypercomplex& h) const;

    // Whether the formula has functions or real powers (bicomplex only): then no norm bound
    // holds (normBound, derivativeNormBound and topDegreeMinimum mean nothing), and degree() is
    // taken as 2 for colouring.
    bool transcendental() const { return transcendental_; }

    // A unit u of span{i, j, k} with u^2 = -1 in the algebra such that every constant of the
    // formula (c included, where it appears) lies in span{1, u} (to inPlane's tolerance, its
    // components 4 .. 7 exactly 0); i where every constant is real. span{1, u} is then a copy
    // of C that the formula maps into itself, where it acts as the same formula does on
    // span{1, u} in H: the complex polynomial of the quaternion expansion (complex_polynomial.h,
    // restrictToComplexPlane). Nothing for transcendental formulas, or where no such u exists.
    std::optional<Quaternion> complexAxis() const;

    // P's coefficients, lowest degree first (size degree() + 1).
    const std::vector<double>& normBound() const { return normBound_; }
    // P'(r): a bound of the operator norm of Dp(z) for |z| <= r.
    double derivativeNormBound(double r) const;
    // Where the norm is multiplicative (productBound 1): m <= |p_d(u)| for every unit u, p_d the
    // top-degree part, certified from the tree (exact for a single top-degree term, the product
    // of its coefficients' norms; top-degree sums m_a - B_b, which may be 0). 0 otherwise.
    double topDegreeMinimum() const { return topDegreeMinimum_; }

  private:
    struct Operation {
        enum class Kind : std::uint8_t {
            kZ,
            kConstant,
            kSum,
            kDifference,
            kProduct,
            kNegate,
            kPower,
            kFunction,  // a FormulaFunction of a, component by component in duplex form
            kRealPower  // a ^ real, likewise
        };
        Kind kind = Kind::kZ;
        std::int32_t a = -1, b = -1;  // operand registers
        // kConstant: index into constants_; kPower: the exponent; kFunction: the function
        std::int32_t value = 0;
        double real = 0;  // kRealPower: the exponent
    };
    int compile(const FormulaNode& node, const Hypercomplex& c);
    // Runs the operations into the registers `value` (and `slope`, the derivative in direction
    // h, where kSlope).
    template <bool kSlope>
    void run(const Hypercomplex& z, const Hypercomplex& h, Hypercomplex* value,
             Hypercomplex* slope) const;

    Algebra algebra_;
    int dimension_;
    const MultiplicationTable* table_;
    std::vector<Operation> operations_;  // register n is written by operation n
    std::vector<Hypercomplex> constants_;
    std::vector<std::vector<double>> bounds_;  // per register: its norm-bound polynomial
    std::vector<int> degrees_;
    std::vector<double> topMinima_;  // per register: the lower bound of its top-degree part
    double topDegreeMinimum_ = 0;
    bool transcendental_ = false;
    std::vector<double> normBound_;
    int degree_ = 0;
};

}  // namespace quaternia
