// The parsed expression tree of a formula (formula.h): what the parser builds, the expansion
// multiplies out into a Polynomial, and formula_program.h compiles into a straight-line program
// that keeps the tree's products as written (so also for algebras that are not associative).
#pragma once

#include <memory>

#include "quaternia/algebra/quaternion.h"

namespace quaternia {

struct FormulaNode {
    enum class Kind { kConstant, kZ, kC, kSum, kDifference, kProduct, kNegate, kPower };
    Kind kind = Kind::kConstant;
    Quaternion value;                                // kConstant
    int exponent = 0;                                // kPower
    std::unique_ptr<const FormulaNode> left, right;  // kNegate and kPower use only left
};

}  // namespace quaternia
