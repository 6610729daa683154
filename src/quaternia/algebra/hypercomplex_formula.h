// A formula (formula.h) in one of the algebras of hypercomplex.h, as the hypercomplex Julia
// sets use it: the one program of the formula compiler (formula_program.h) for that algebra,
// its analysis (program_bounds.h: norm bounds, degree, complex axis) and the algebra's
// multiplication table, held together. Products follow the table in the order written (left
// to right, parentheses honoured), which is what an algebra that is not associative (the
// octonions) needs; powers multiply on the left, z (z (... z)), equal to every other bracketing
// in these power-associative algebras (the quaternions, whose program is rewritten, excepted).
//
// The formula's constants are written with 1, i, j and k: they are components 0 .. 3 of the
// algebra (for the 8-component algebras, of the quaternion half a of a + b h or (a, b)); the
// name c stands for the scene's c with all of the algebra's components.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "quaternia/algebra/formula.h"
#include "quaternia/algebra/formula_program.h"
#include "quaternia/algebra/hypercomplex.h"
#include "quaternia/algebra/program_bounds.h"

namespace quaternia {

class HypercomplexFormula {
  public:
    // Throws UserError("fractal.formula", ...) for a formula without terms, FormulaError for a
    // function or real power outside the bicomplex numbers.
    HypercomplexFormula(const Formula& formula, Algebra algebra, const Hypercomplex& c);

    Algebra algebra() const { return program_.algebra(); }
    int dimension() const { return table_->dimension(); }
    const MultiplicationTable& table() const { return *table_; }
    int degree() const { return bounds_.degree; }
    const FormulaProgram& program() const { return program_; }

    Hypercomplex evaluate(const Hypercomplex& z) const {
        return evaluateInAlgebra(program_, *table_, z);
    }
    // p(z) and its derivative Dp(z)[h] in direction h, together (forward mode).
    std::pair<Hypercomplex, Hypercomplex> evaluateWithDerivative(const Hypercomplex& z,
                                                                 const Hypercomplex& h) const {
        return evaluateInAlgebraWithDerivative(program_, *table_, z, h);
    }
    // The same along three directions, p(z) computed once.
    std::pair<Hypercomplex, std::array<Hypercomplex, 3>> evaluateWithDerivatives(
        const Hypercomplex& z, const std::array<Hypercomplex, 3>& h) const {
        return evaluateInAlgebraWithDerivatives(program_, *table_, z, h);
    }

    // The analysis of program_bounds.h, whose comments say what each means.
    bool transcendental() const { return bounds_.transcendental; }
    std::optional<Quaternion> complexAxis() const { return bounds_.complexAxis; }
    const std::vector<double>& normBound() const { return bounds_.normBound; }
    double derivativeNormBound(double r) const { return bounds_.derivativeNormBound(r); }
    double topDegreeMinimum() const { return bounds_.topDegreeMinimum; }

  private:
    FormulaProgram program_;
    ProgramBounds bounds_;
    const MultiplicationTable* table_;
};

}  // namespace quaternia
