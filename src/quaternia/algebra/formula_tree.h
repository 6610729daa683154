// The parsed expression tree of a formula (formula.h): what the parser builds, the expansion
// multiplies out into a Polynomial, and formula_program.h compiles into a straight-line program
// that keeps the tree's products as written (so also for algebras that are not associative).
#pragma once

#include <memory>
#include <optional>
#include <string_view>

#include "quaternia/algebra/quaternion.h"

namespace quaternia {

// The functions of POV-Ray's hypercomplex julia_fractal, for the bicomplex numbers only (applied
// through the duplex form, component by component: formula_program_evaluate.cpp). The
// polynomial algebras refuse them (Formula::expand, FormulaProgram::compile).
enum class FormulaFunction {
    kExp,
    kLog,
    kSin,
    kCos,
    kTan,
    kSinh,
    kCosh,
    kTanh,
    kAsin,
    kAcos,
    kAtan,
    kAsinh,
    kAcosh,
    kAtanh,
    kReciprocal
};
std::optional<FormulaFunction> formulaFunctionNamed(std::string_view name);
std::string_view formulaFunctionName(FormulaFunction function);

struct FormulaNode {
    enum class Kind {
        kConstant,
        kZ,
        kC,
        kSum,
        kDifference,
        kProduct,
        kNegate,
        kPower,
        kFunction,   // function(left)
        kRealPower,  // left ^ realExponent: an exponent that is not a non-negative integer
    };
    Kind kind = Kind::kConstant;
    Quaternion value;                                  // kConstant
    int exponent = 0;                                  // kPower
    double realExponent = 0;                           // kRealPower
    FormulaFunction function = FormulaFunction::kExp;  // kFunction
    int column = 0;                                    // kFunction, kRealPower: where written
    std::unique_ptr<const FormulaNode> left, right;  // kNegate, kPower, kFunction, kRealPower: left
};

// Throws FormulaError at the node's column: functions and real powers are the bicomplex
// numbers' only.
[[noreturn]] void refuseTranscendental(const FormulaNode& node);

// The first function or real power in the tree (nullptr if none): what only the bicomplex
// numbers evaluate.
const FormulaNode* firstTranscendental(const FormulaNode* node);

}  // namespace quaternia
