// A formula compiled into a straight-line program: instruction n writes register n from the
// registers before it. The one compiler of formulas, for every algebra of hypercomplex.h: it
// works from the parse tree (formula_tree.h), not from the expanded polynomial, so the products
// are those written (left to right, parentheses honoured: what an algebra that is not
// associative needs), and it is usually far shorter than the expansion ((z + c)^12 is one sum
// and four multiplications, not 13 terms of 12 products). Equal subexpressions are computed
// once in every algebra. Where the algebra's rules allow rewriting its arithmetic
// (AlgebraArithmetic::rewritesArithmetic: the quaternions), also: constant subexpressions are
// folded, multiplications by a real number become scalings (reals are central in every algebra
// of hypercomplex.h), by 1 and 0 disappear, products with other constants become 4x4 linear
// maps, x x becomes a squaring, and powers go by repeated squaring (power-associativity makes
// every bracketing of x^n equal). The other algebras keep every operation as written, z^n as
// z (z (... z)), so that their results stay bit for bit what they were.
//
// The norm and derivative bounds of a program are a separate pass over it (program_bounds.h).
//
// A quaternion program serves every element type: runProgram() is a template over it, for the
// scalar reference (Quaternion) and for SIMD lanes (QuaternionT of Highway vectors), whose caller
// converts the constants and scale factors once. Programs of the other algebras run through
// their multiplication table (evaluateInAlgebra, below).
#pragma once

#include <array>
#include <complex>
#include <cstdint>
#include <utility>
#include <vector>

#include "quaternia/algebra/formula.h"
#include "quaternia/algebra/formula_tree.h"
#include "quaternia/algebra/hypercomplex.h"
#include "quaternia/algebra/quaternion.h"

namespace quaternia {

struct Instruction {
    enum class Op : std::uint8_t {
        kZ,         // the point z
        kConstant,  // constants()[index]
        kAdd,       // a + b
        kSubtract,  // a - b
        kNegate,    // -a
        kMultiply,  // a b, in that order
        kSquare,    // a a
        kScale,     // a times the real factors()[index]
        // The linear map of a whose 4x4 matrix, row by row, is factors()[index .. index + 15]:
        // products with constants on either side, q a and a q, composed (q a r is one map).
        kLinear,
        // a^index as a (a (... a)), a^0 = 1: the algebras whose arithmetic is kept as written.
        kPower,
        kFunction,   // the FormulaFunction `index` of a, through the duplex form (bicomplex)
        kRealPower,  // a to the real power factors()[index], likewise
    };
    Op op = Op::kZ;
    std::int32_t a = -1, b = -1;  // operand registers, earlier than this one
    std::int32_t index = -1;      // kConstant, kScale, kLinear, kPower, kFunction, kRealPower
};

class FormulaProgram {
  public:
    // The formula in `algebra`, with c (all of the algebra's components) for the name c. The
    // formula's constants, written with 1, i, j and k, are components 0 .. 3 (for the
    // 8-component algebras, of the quaternion half a of a + b h or (a, b)). Throws FormulaError
    // at a function or real power where the algebra has none. A formula without terms is 0.
    static FormulaProgram compile(const Formula& formula, Algebra algebra, const Hypercomplex& c);
    // The quaternion program, with the scene's fractal.c folded in as a constant.
    static FormulaProgram compile(const Formula& formula, const Quaternion& c);
    // The same for an expanded quaternion polynomial, term by term (a0 z a1 ... z ak, left to
    // right): for polynomials that come without their formula.
    static FormulaProgram fromPolynomial(const Polynomial& polynomial);

    Algebra algebra() const { return algebra_; }
    const std::vector<Instruction>& instructions() const { return instructions_; }
    // Every constant the compiler made, in the order made: the formula's own in the order
    // written (left operand first), each followed by those folded from it. Kept where folding
    // or a linear map has absorbed them, so that the analysis (program_bounds.h, complexAxis)
    // sees every constant of the formula.
    const std::vector<Hypercomplex>& elements() const { return elements_; }
    // The same, components 0 .. 3: what the quaternion runners read.
    const std::vector<Quaternion>& constants() const { return constants_; }
    const std::vector<double>& factors() const { return factors_; }
    // The register that holds p(z) (not always the last: a formula such as "c + z*0" ends early).
    int result() const { return result_; }
    // Instructions of each kind, for statistics and tests.
    int count(Instruction::Op op) const;

    // p(z) of a quaternion program, through runProgram with Quaternion registers.
    Quaternion evaluate(const Quaternion& z) const;

  private:
    // Keeps the instructions that `result` needs, renumbered.
    static FormulaProgram assemble(Algebra algebra, const std::vector<Instruction>& all,
                                   std::vector<Hypercomplex> elements, std::vector<double> factors,
                                   int result);

    Algebra algebra_ = Algebra::kQuaternion;
    std::vector<Instruction> instructions_;
    std::vector<Hypercomplex> elements_;
    std::vector<Quaternion> constants_;
    std::vector<double> factors_;
    int result_ = 0;
};

// p(z) of a program in its algebra, products through `table` (the program's algebra's), and
// with the derivative Dp(z)[h] (forward mode: each register carries its value and its
// derivative; d(uv) = du v + u dv in the order written). Quaternion programs run through
// runProgram and runProgramWithTangents, as the renderer runs them (formula_program_evaluate.cpp).
Hypercomplex evaluateInAlgebra(const FormulaProgram& program, const MultiplicationTable& table,
                               const Hypercomplex& z);
std::pair<Hypercomplex, Hypercomplex> evaluateInAlgebraWithDerivative(
    const FormulaProgram& program, const MultiplicationTable& table, const Hypercomplex& z,
    const Hypercomplex& h);
// The same along three directions at once (the normal's tangents): p(z) computed once, each
// derivative bit for bit evaluateInAlgebraWithDerivative's.
std::pair<Hypercomplex, std::array<Hypercomplex, 3>> evaluateInAlgebraWithDerivatives(
    const FormulaProgram& program, const MultiplicationTable& table, const Hypercomplex& z,
    const std::array<Hypercomplex, 3>& h);

// f(w) on std::complex's principal branch: what a bicomplex program's kFunction applies to each
// duplex component (without the derivative, which would double the cost of sin and cos).
std::complex<double> complexFunctionValue(FormulaFunction function, const std::complex<double>& w);

// runProgram and runProgramWithTangents for real components (the lane code includes the file
// again in each SIMD target's namespace, as quaternion.h's arithmetic).
#include "quaternia/algebra/formula_program_run-inl.h"  // IWYU pragma: export

}  // namespace quaternia
