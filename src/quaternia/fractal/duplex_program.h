// A bicomplex formula on one duplex component (issue 42). Every operation of the bicomplex
// numbers (sums, products, powers, exp, sin, ...) acts on the duplex form (a, b) (hypercomplex.h,
// duplexForm) component by component, so the formula is two complex maps f_1, f_2: the program
// with every constant replaced by its duplex component. This runs such a map on two kinds of
// number:
// - Complex: the value, the bicomplex orbit's reference arithmetic (HypercomplexJuliaSet iterates
//   the functions' orbits this way, as it iterates the polynomials' by Horner's rule);
// - Disc: a centre and a radius enclosing the image of a disc (Taylor's theorem with a bound of
//   |f''|: interval/function_forms.h; products (c + u)(d + v) add |c| |v| + |d| |u| + |u v|),
//   every rounding of the centre covered: the proofs of duplex_escape_map.h.
#pragma once

#include <complex>
#include <vector>

#include "quaternia/algebra/formula_program.h"

namespace quaternia {

struct ComplexDisc {
    std::complex<double> centre;
    double radius = 0;
};

class DuplexComponentProgram {
  public:
    DuplexComponentProgram() = default;
    // Component `component` (0 or 1) of a bicomplex program that supports() takes.
    DuplexComponentProgram(const FormulaProgram& program, int component);

    // Whether every operation of `program` runs here: a bicomplex program whose functions have
    // disc forms (exp, sin, cos, sinh, cosh), without real powers.
    static bool supports(const FormulaProgram& program);

    // f(w); registers are scratch (one per instruction, resized here).
    std::complex<double> value(std::complex<double> w,
                               std::vector<std::complex<double>>& registers) const;
    ComplexDisc disc(ComplexDisc w, std::vector<ComplexDisc>& registers) const;

    // Everything the map depends on, as numbers: equal signatures, equal maps (the escape maps'
    // cache, duplex_escape_map.h).
    std::vector<double> signature() const;

  private:
    template <class Number, class Arithmetic>
    Number run(const Number& z, std::vector<Number>& registers, const Arithmetic& arithmetic) const;

    std::vector<Instruction> code_;
    std::vector<std::complex<double>> constants_;  // the program's constants' component
    std::vector<double> constantError_;            // the rounding of each one's duplex form
    std::vector<double> factors_;
    int result_ = 0;
};

}  // namespace quaternia
