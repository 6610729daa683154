#include "quaternia/fractal/duplex_program.h"

#include <algorithm>
#include <cmath>

#include "quaternia/algebra/hypercomplex.h"
#include "quaternia/interval/function_forms.h"

namespace quaternia {
namespace {

using Complex = std::complex<double>;
using Op = Instruction::Op;

// Relative rounding allowed per operation on a disc's centre (a few ulps, generously).
constexpr double kRelative = 0x1p-50;

// Without std::complex's recovery of NaN products (__muldc3): the values are finite or the orbit
// has escaped long before.
Complex multiply(Complex a, Complex b) {
    return {a.real() * b.real() - a.imag() * b.imag(), a.real() * b.imag() + a.imag() * b.real()};
}

struct ValueArithmetic {
    Complex constant(Complex c, double) const { return c; }
    Complex add(Complex a, Complex b) const { return a + b; }
    Complex subtract(Complex a, Complex b) const { return a - b; }
    Complex negate(Complex a) const { return -a; }
    Complex multiply(Complex a, Complex b) const { return quaternia::multiply(a, b); }
    Complex scale(double s, Complex a) const { return s * a; }
    Complex function(FormulaFunction f, Complex a) const { return complexFunctionValue(f, a); }
    Complex one() const { return Complex(1); }
};

struct DiscArithmetic {
    ComplexDisc constant(Complex c, double error) const { return {c, error}; }
    ComplexDisc add(const ComplexDisc& a, const ComplexDisc& b) const {
        return sum(a.centre + b.centre, a, b);
    }
    ComplexDisc subtract(const ComplexDisc& a, const ComplexDisc& b) const {
        return sum(a.centre - b.centre, a, b);
    }
    ComplexDisc negate(const ComplexDisc& a) const { return {-a.centre, a.radius}; }
    ComplexDisc multiply(const ComplexDisc& x, const ComplexDisc& y) const {
        // (c + u)(d + v) = cd + c v + d u + u v, and cd's rounding.
        const double ax = upperAbs(x.centre), ay = upperAbs(y.centre);
        return {quaternia::multiply(x.centre, y.centre),
                (ax * y.radius + ay * x.radius + x.radius * y.radius + 2 * kRelative * ax * ay) *
                        (1 + kRelative) +
                    0x1p-1000};
    }
    ComplexDisc scale(double s, const ComplexDisc& a) const {
        return {s * a.centre,
                std::fabs(s) * (a.radius * (1 + kRelative) + kRelative * upperAbs(a.centre))};
    }
    ComplexDisc function(FormulaFunction f, const ComplexDisc& a) const {
        const ComplexForm image = functionOnForm(f, ComplexForm{a.centre, Complex(0), a.radius});
        return {image.centre, image.radius};
    }
    ComplexDisc one() const { return {Complex(1), 0}; }

  private:
    static ComplexDisc sum(Complex centre, const ComplexDisc& a, const ComplexDisc& b) {
        return {centre, (a.radius + b.radius) * (1 + kRelative) +
                            kRelative * (upperAbs(a.centre) + upperAbs(b.centre))};
    }
};

}  // namespace

bool DuplexComponentProgram::supports(const FormulaProgram& program) {
    if (program.algebra() != Algebra::kBicomplex) return false;
    for (const Instruction& i : program.instructions()) {
        if (i.op == Op::kLinear || i.op == Op::kRealPower) return false;
        if (i.op == Op::kFunction && !hasFunctionForm(FormulaFunction(i.index))) return false;
    }
    return true;
}

DuplexComponentProgram::DuplexComponentProgram(const FormulaProgram& program, int component)
    : code_(program.instructions()), factors_(program.factors()), result_(program.result()) {
    for (const Hypercomplex& e : program.elements()) {
        constants_.push_back(duplexForm(e)[size_t(component)]);
        // duplexForm adds or subtracts two components: half an ulp of their sum, generously.
        constantError_.push_back(
            0x1p-52 * (std::fabs(e[0]) + std::fabs(e[1]) + std::fabs(e[2]) + std::fabs(e[3])));
    }
}

template <class Number, class Arithmetic>
Number DuplexComponentProgram::run(const Number& z, std::vector<Number>& r,
                                   const Arithmetic& arithmetic) const {
    r.resize(code_.size());
    for (size_t n = 0; n < code_.size(); ++n) {
        const Instruction& i = code_[n];
        const Number& a = r[size_t(std::max(i.a, 0))];
        const Number& b = r[size_t(std::max(i.b, 0))];
        switch (i.op) {
            case Op::kZ:
                r[n] = z;
                break;
            case Op::kConstant:
                r[n] = arithmetic.constant(constants_[size_t(i.index)],
                                           constantError_[size_t(i.index)]);
                break;
            case Op::kAdd:
                r[n] = arithmetic.add(a, b);
                break;
            case Op::kSubtract:
                r[n] = arithmetic.subtract(a, b);
                break;
            case Op::kNegate:
                r[n] = arithmetic.negate(a);
                break;
            case Op::kMultiply:
                r[n] = arithmetic.multiply(a, b);
                break;
            case Op::kSquare:
                r[n] = arithmetic.multiply(a, a);
                break;
            case Op::kPower: {
                // a^e = a (a (... a)), as the bicomplex programs write it.
                Number power = arithmetic.one();
                for (int e = 0; e < i.index; ++e)
                    power = e == 0 ? a : arithmetic.multiply(a, power);
                r[n] = power;
                break;
            }
            case Op::kScale:
                r[n] = arithmetic.scale(factors_[size_t(i.index)], a);
                break;
            case Op::kFunction:
                r[n] = arithmetic.function(FormulaFunction(i.index), a);
                break;
            case Op::kLinear:
            case Op::kRealPower:
                r[n] = arithmetic.function(FormulaFunction::kLog, a);  // NaN: supports() refuses
                break;
        }
    }
    return r[size_t(result_)];
}

std::vector<double> DuplexComponentProgram::signature() const {
    std::vector<double> s;
    for (const Instruction& i : code_)
        s.insert(s.end(), {double(i.op), double(i.a), double(i.b), double(i.index)});
    for (size_t k = 0; k < constants_.size(); ++k)
        s.insert(s.end(), {constants_[k].real(), constants_[k].imag(), constantError_[k]});
    s.insert(s.end(), factors_.begin(), factors_.end());
    s.push_back(double(result_));
    return s;
}

Complex DuplexComponentProgram::value(Complex w, std::vector<Complex>& registers) const {
    return run(w, registers, ValueArithmetic{});
}

ComplexDisc DuplexComponentProgram::disc(ComplexDisc w, std::vector<ComplexDisc>& registers) const {
    return run(w, registers, DiscArithmetic{});
}

}  // namespace quaternia
