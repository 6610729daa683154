#include "quaternia/algebra/hypercomplex_formula.h"

#include "quaternia/util/error.h"

namespace quaternia {
namespace {

FormulaProgram compiledWithTerms(const Formula& formula, Algebra algebra, const Hypercomplex& c) {
    if (formula.root() == nullptr)
        throw UserError("fractal.formula", "fractal.formula: the formula has no terms");
    return FormulaProgram::compile(formula, algebra, c);
}

}  // namespace

HypercomplexFormula::HypercomplexFormula(const Formula& formula, Algebra algebra,
                                         const Hypercomplex& c)
    : program_(compiledWithTerms(formula, algebra, c)),
      bounds_(analyzeProgram(program_)),
      table_(&MultiplicationTable::of(algebra)) {}

}  // namespace quaternia
