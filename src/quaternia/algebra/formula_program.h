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
    };
    Op op = Op::kZ;
    std::int32_t a = -1, b = -1;  // operand registers, earlier than this one
    std::int32_t index = -1;      // kConstant, kScale
};

class FormulaProgram {
  public:
    // c is the scene's fractal.c, folded in as a constant.
    static FormulaProgram compile(const Formula& formula, const Quaternion& c);

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
    std::vector<Instruction> instructions_;
    std::vector<Quaternion> constants_;
    std::vector<double> factors_;
    int result_ = 0;
};

// Runs `code` at z with `registers` (at least code.size() of them): `constants` and `factors` are
// the program's, converted to Element and Real. Returns register `result`.
template <class Element, class Real>
Element runProgram(const std::vector<Instruction>& code, int result, const Element& z,
                   const Element* constants, const Real* factors, Element* registers) {
    using Op = Instruction::Op;
    for (std::size_t n = 0; n < code.size(); ++n) {
        const Instruction& i = code[n];
        switch (i.op) {
            case Op::kZ:
                registers[n] = z;
                break;
            case Op::kConstant:
                registers[n] = constants[i.index];
                break;
            case Op::kAdd:
                registers[n] = registers[i.a] + registers[i.b];
                break;
            case Op::kSubtract:
                registers[n] = registers[i.a] - registers[i.b];
                break;
            case Op::kNegate:
                registers[n] = -registers[i.a];
                break;
            case Op::kMultiply:
                registers[n] = registers[i.a] * registers[i.b];
                break;
            case Op::kSquare:
                registers[n] = square(registers[i.a]);
                break;
            case Op::kScale:
                registers[n] = registers[i.a] * factors[i.index];
                break;
        }
    }
    return registers[result];
}

// runProgram with the directional derivatives Dp(z)[h_m] along M tangents h_m, by the product
// rule in the order written (d(ab) = da b + a db: the factors do not commute), as the analytic
// normals and the Jacobians of orbits need them. `tangentRegisters` holds M per register;
// `zero` is the element 0 (lane vectors have no default value).
template <int M, class Element, class Real>
Element runProgramWithTangents(const std::vector<Instruction>& code, int result, const Element& z,
                               const Element (&h)[M], const Element& zero, const Element* constants,
                               const Real* factors, Element* registers,
                               Element (*tangentRegisters)[M], Element (&derivative)[M]) {
    using Op = Instruction::Op;
    for (std::size_t n = 0; n < code.size(); ++n) {
        const Instruction& i = code[n];
        Element(&t)[M] = tangentRegisters[n];
        switch (i.op) {
            case Op::kZ:
                registers[n] = z;
                for (int m = 0; m < M; ++m)
                    t[m] = h[m];
                break;
            case Op::kConstant:
                registers[n] = constants[i.index];
                for (int m = 0; m < M; ++m)
                    t[m] = zero;
                break;
            case Op::kAdd:
                registers[n] = registers[i.a] + registers[i.b];
                for (int m = 0; m < M; ++m)
                    t[m] = tangentRegisters[i.a][m] + tangentRegisters[i.b][m];
                break;
            case Op::kSubtract:
                registers[n] = registers[i.a] - registers[i.b];
                for (int m = 0; m < M; ++m)
                    t[m] = tangentRegisters[i.a][m] - tangentRegisters[i.b][m];
                break;
            case Op::kNegate:
                registers[n] = -registers[i.a];
                for (int m = 0; m < M; ++m)
                    t[m] = -tangentRegisters[i.a][m];
                break;
            case Op::kMultiply:
            case Op::kSquare: {
                const int b = i.op == Op::kSquare ? i.a : i.b;
                registers[n] =
                    i.op == Op::kSquare ? square(registers[i.a]) : registers[i.a] * registers[b];
                for (int m = 0; m < M; ++m)
                    t[m] = tangentRegisters[i.a][m] * registers[b] +
                           registers[i.a] * tangentRegisters[b][m];
                break;
            }
            case Op::kScale:
                registers[n] = registers[i.a] * factors[i.index];
                for (int m = 0; m < M; ++m)
                    t[m] = tangentRegisters[i.a][m] * factors[i.index];
                break;
        }
    }
    for (int m = 0; m < M; ++m)
        derivative[m] = tangentRegisters[result][m];
    return registers[result];
}

}  // namespace quaternia
