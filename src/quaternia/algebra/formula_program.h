// A formula compiled into a straight-line program: instruction n writes register n from the
// registers before it. It is compiled from the parse tree (formula_tree.h), not from the expanded
// polynomial, so the products are those written (left to right, parentheses honoured: what an
// algebra that is not associative needs), and it is usually far shorter than the expansion
// ((z + c)^12 is one sum and four multiplications, not 13 terms of 12 products). On the way:
// constant subexpressions are folded, equal subexpressions computed once, multiplications by a
// real number become scalings (reals are central in every algebra of hypercomplex.h), by 1 and
// 0 disappear, x x becomes a squaring, and powers go by repeated squaring (power-associativity
// makes every bracketing of x^n equal).
//
// One program serves every element type: runProgram() is a template over it, for the scalar
// reference (Quaternion) and for SIMD lanes (QuaternionT of Highway vectors), whose caller
// converts the constants and scale factors once.
#pragma once

#include <cstdint>
#include <vector>

#include "quaternia/algebra/formula.h"
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
    };
    Op op = Op::kZ;
    std::int32_t a = -1, b = -1;  // operand registers, earlier than this one
    std::int32_t index = -1;      // kConstant, kScale, kLinear
};

class FormulaProgram {
  public:
    // c is the scene's fractal.c, folded in as a constant.
    static FormulaProgram compile(const Formula& formula, const Quaternion& c);
    // The same for an expanded polynomial, term by term (a0 z a1 ... z ak, left to right): for
    // polynomials that come without their formula.
    static FormulaProgram fromPolynomial(const Polynomial& polynomial);

    const std::vector<Instruction>& instructions() const { return instructions_; }
    const std::vector<Quaternion>& constants() const { return constants_; }
    const std::vector<double>& factors() const { return factors_; }
    // The register that holds p(z) (not always the last: a formula such as "c + z*0" ends early).
    int result() const { return result_; }
    // Instructions of each kind, for statistics and tests.
    int count(Instruction::Op op) const;

    // p(z), through runProgram with Quaternion registers.
    Quaternion evaluate(const Quaternion& z) const;

  private:
    // Keeps the instructions that `result` needs, renumbered.
    static FormulaProgram assemble(const std::vector<Instruction>& all,
                                   std::vector<Quaternion> constants, std::vector<double> factors,
                                   int result);

    std::vector<Instruction> instructions_;
    std::vector<Quaternion> constants_;
    std::vector<double> factors_;
    int result_ = 0;
};

// runProgram and runProgramWithTangents for real components (the lane code includes the file
// again in each SIMD target's namespace, as quaternion.h's arithmetic).
#include "quaternia/algebra/formula_program_run-inl.h"  // IWYU pragma: export

}  // namespace quaternia
