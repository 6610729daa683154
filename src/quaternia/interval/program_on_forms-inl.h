// One interpreter of formula programs (algebra/formula_program.h) for the forms of this layer:
// boxes (interval_element.h) and segments in affine arithmetic (segment_form.h), and one loop
// that iterates a form until it is proven outside the bailout ball. `Arithmetic` supplies the
// form's operations as static functions: point(element), sum(a, b, d), difference(a, b, d),
// negated(a, d), product(table, a, b), square(table, a), scaled(s, a, d), linear(m, a),
// function(f, a) (a bicomplex function with a form, function_forms.h), outside(form, d, bailout)
// (proven wholly outside the ball) and hopeless(form, d, bailout) (too wide to be proven later:
// give up).
#pragma once

#include <cstddef>
#include <stdexcept>
#include <vector>

#include "quaternia/algebra/formula_program.h"
#include "quaternia/algebra/hypercomplex.h"

namespace quaternia::interval_forms {

// a^n, n >= 0, by repeated squaring: every algebra of hypercomplex.h is power-associative (the
// octonions are alternative), so x^a x^b = x^(a+b) whatever the bracketing, and squares are
// tighter than products.
template <class Arithmetic, class Form>
Form power(const MultiplicationTable& table, const Form& a, int n) {
    if (n == 0) return Arithmetic::point(realElement(1));
    Form result{}, base = a;
    bool first = true;
    for (int e = n;; e >>= 1) {
        if (e & 1) {
            result = first ? base : Arithmetic::product(table, result, base);
            first = false;
        }
        if (e == 1) return result;
        base = Arithmetic::square(table, base);
    }
}

// Encloses {p(z) : z in form}; the caller checks withoutIntervalExtension.
template <class Arithmetic, class Form>
Form run(const FormulaProgram& program, const MultiplicationTable& table, const Form& z,
         std::vector<Form>& registers) {
    using Op = Instruction::Op;
    const std::vector<Instruction>& code = program.instructions();
    if (registers.size() < code.size()) registers.resize(code.size());
    const int d = table.dimension();
    const std::vector<Hypercomplex>& constants = program.elements();
    const double* factors = program.factors().data();
    for (std::size_t n = 0; n < code.size(); ++n) {
        const Instruction& i = code[n];
        const std::size_t a = std::size_t(i.a), b = std::size_t(i.b);
        Form& out = registers[n];
        switch (i.op) {
            case Op::kZ:
                out = z;
                break;
            case Op::kConstant:
                out = Arithmetic::point(constants[std::size_t(i.index)]);
                break;
            case Op::kAdd:
                out = Arithmetic::sum(registers[a], registers[b], d);
                break;
            case Op::kSubtract:
                out = Arithmetic::difference(registers[a], registers[b], d);
                break;
            case Op::kNegate:
                out = Arithmetic::negated(registers[a], d);
                break;
            case Op::kMultiply:
                // The same register twice is the same number: its square is tighter.
                out = a == b ? Arithmetic::square(table, registers[a])
                             : Arithmetic::product(table, registers[a], registers[b]);
                break;
            case Op::kSquare:
                out = Arithmetic::square(table, registers[a]);
                break;
            case Op::kScale:
                out = Arithmetic::scaled(factors[i.index], registers[a], d);
                break;
            case Op::kLinear:
                out = Arithmetic::linear(factors + i.index, registers[a]);
                break;
            case Op::kPower:
                out = power<Arithmetic>(table, registers[a], i.index);
                break;
            case Op::kFunction:
                out = Arithmetic::function(FormulaFunction(i.index), registers[a]);
                break;
            case Op::kRealPower:
                throw std::logic_error("interval forms: no interval extension");
        }
    }
    return registers[std::size_t(program.result())];
}

// Whether some iterate z_n, n < maxIterations, of every point of the form lies outside the ball
// |z| <= bailout. False proves nothing.
template <class Arithmetic, class Form>
bool leavesBall(const FormulaProgram& program, const MultiplicationTable& table, const Form& form,
                int maxIterations, double bailout, std::vector<Form>& registers) {
    const int d = table.dimension();
    Form z = form;
    for (int n = 0;; ++n) {
        if (Arithmetic::outside(z, d, bailout)) return true;
        // A form wider than the ball's diameter is rarely proven later, and iterates only
        // widen: give up, sparing the iterations left.
        if (n + 1 >= maxIterations || Arithmetic::hopeless(z, d, bailout)) return false;
        z = run<Arithmetic>(program, table, z, registers);
    }
}

}  // namespace quaternia::interval_forms
