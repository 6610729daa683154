// Programs of formula_program.h evaluated in their algebra: quaternion programs through
// runProgram and runProgramWithTangents, as the renderer runs them, and the others register by
// register with products through the multiplication table, in the order written, and the
// derivative carried along (forward mode).
#include <array>
#include <cmath>
#include <complex>
#include <tuple>
#include <vector>

#include "quaternia/algebra/formula_program.h"
#include "quaternia/algebra/formula_tree.h"

namespace quaternia {
namespace {

using Complex = std::complex<double>;
using Op = Instruction::Op;

// f(w) and f'(w) on the principal branches of std::complex.
std::pair<Complex, Complex> complexFunction(FormulaFunction function, const Complex& w) {
    const Complex one(1);
    switch (function) {
        case FormulaFunction::kExp:
            return {std::exp(w), std::exp(w)};
        case FormulaFunction::kLog:
            return {std::log(w), one / w};
        case FormulaFunction::kSin:
            return {std::sin(w), std::cos(w)};
        case FormulaFunction::kCos:
            return {std::cos(w), -std::sin(w)};
        case FormulaFunction::kTan:
            return {std::tan(w), one / (std::cos(w) * std::cos(w))};
        case FormulaFunction::kSinh:
            return {std::sinh(w), std::cosh(w)};
        case FormulaFunction::kCosh:
            return {std::cosh(w), std::sinh(w)};
        case FormulaFunction::kTanh:
            return {std::tanh(w), one / (std::cosh(w) * std::cosh(w))};
        case FormulaFunction::kAsin:
            return {std::asin(w), one / std::sqrt(one - w * w)};
        case FormulaFunction::kAcos:
            return {std::acos(w), -one / std::sqrt(one - w * w)};
        case FormulaFunction::kAtan:
            return {std::atan(w), one / (one + w * w)};
        case FormulaFunction::kAsinh:
            return {std::asinh(w), one / std::sqrt(w * w + one)};
        case FormulaFunction::kAcosh:
            return {std::acosh(w), one / (std::sqrt(w - one) * std::sqrt(w + one))};
        case FormulaFunction::kAtanh:
            return {std::atanh(w), one / (one - w * w)};
        case FormulaFunction::kReciprocal:
            return {one / w, -one / (w * w)};
    }
    return {w, one};
}

Hypercomplex negated(const Hypercomplex& a) {
    return -1.0 * a;
}

// Components 0 .. 3 mapped by the 4x4 matrix m (row by row), as applyLinear.
Hypercomplex linearMap(const double* m, const Hypercomplex& a) {
    Hypercomplex q{};
    for (int r = 0; r < 4; ++r)
        q[r] =
            m[r * 4 + 0] * a[0] + m[r * 4 + 1] * a[1] + m[r * 4 + 2] * a[2] + m[r * 4 + 3] * a[3];
    return q;
}

// Runs the program into the registers `value` and, for S > 0, `slope` (register n's derivative
// in direction h[s] at slope[n * S + s]). Each direction's derivative takes the same operations
// whatever S is, so S directions at once give each the bits of S = 1.
template <int S>
void run(const FormulaProgram& program, const MultiplicationTable& table, const Hypercomplex& z,
         const Hypercomplex* h, Hypercomplex* value, Hypercomplex* slope) {
    const std::vector<Instruction>& code = program.instructions();
    const Hypercomplex* constants = program.elements().data();
    const double* factors = program.factors().data();
    for (std::size_t n = 0; n < code.size(); ++n) {
        const Instruction& i = code[n];
        const std::size_t a = std::size_t(i.a), b = std::size_t(i.b);
        // Operands an instruction lacks are -1: their slopes are never read, and their
        // addresses are not formed.
        Hypercomplex* out = slope + n * S;
        const Hypercomplex* slopeA = i.a >= 0 ? slope + a * S : slope;
        const Hypercomplex* slopeB = i.b >= 0 ? slope + b * S : slope;
        switch (i.op) {
            case Op::kZ:
                value[n] = z;
                for (int s = 0; s < S; ++s)
                    out[s] = h[s];
                break;
            case Op::kConstant:
                value[n] = constants[i.index];
                for (int s = 0; s < S; ++s)
                    out[s] = Hypercomplex{};
                break;
            case Op::kAdd:
                value[n] = value[a] + value[b];
                for (int s = 0; s < S; ++s)
                    out[s] = slopeA[s] + slopeB[s];
                break;
            case Op::kSubtract:
                value[n] = value[a] - value[b];
                for (int s = 0; s < S; ++s)
                    out[s] = slopeA[s] - slopeB[s];
                break;
            case Op::kNegate:
                value[n] = negated(value[a]);
                for (int s = 0; s < S; ++s)
                    out[s] = negated(slopeA[s]);
                break;
            case Op::kMultiply:
            case Op::kSquare: {
                // d(uv) = du v + u dv, in the order written.
                const std::size_t right = i.op == Op::kSquare ? a : b;
                const Hypercomplex* slopeRight = i.op == Op::kSquare ? slopeA : slopeB;
                for (int s = 0; s < S; ++s)
                    out[s] = table.multiply(slopeA[s], value[right]) +
                             table.multiply(value[a], slopeRight[s]);
                value[n] = table.multiply(value[a], value[right]);
                break;
            }
            case Op::kScale:
                value[n] = factors[i.index] * value[a];
                for (int s = 0; s < S; ++s)
                    out[s] = factors[i.index] * slopeA[s];
                break;
            case Op::kLinear:
                value[n] = linearMap(factors + i.index, value[a]);
                for (int s = 0; s < S; ++s)
                    out[s] = linearMap(factors + i.index, slopeA[s]);
                break;
            case Op::kPower: {
                // x^e = x (x (... x)), the derivative by the product rule at each factor.
                Hypercomplex power = realElement(1);
                std::array<Hypercomplex, std::size_t(S > 0 ? S : 1)> powerSlope{};
                for (int e = 0; e < i.index; ++e) {
                    for (int s = 0; s < S; ++s)
                        powerSlope[std::size_t(s)] =
                            table.multiply(slopeA[s], power) +
                            table.multiply(value[a], powerSlope[std::size_t(s)]);
                    power = e == 0 ? value[a] : table.multiply(value[a], power);
                }
                value[n] = power;
                for (int s = 0; s < S; ++s)
                    out[s] = powerSlope[std::size_t(s)];
                break;
            }
            case Op::kFunction:
            case Op::kRealPower: {
                // The duplex form: f applied to each complex component, and the chain rule
                // f'(A) dA likewise.
                const auto w = duplexForm(value[a]);
                const double exponent = i.op == Op::kRealPower ? factors[i.index] : 0;
                std::array<Complex, 2> f, derivative;
                for (std::size_t k = 0; k < 2; ++k) {
                    if constexpr (S == 0) {
                        // The value alone: the derivative would double the cost of sin and cos.
                        f[k] = i.op == Op::kFunction
                                   ? complexFunctionValue(FormulaFunction(i.index), w[k])
                                   : std::pow(w[k], exponent);
                        continue;
                    }
                    std::tie(f[k], derivative[k]) =
                        i.op == Op::kFunction ? complexFunction(FormulaFunction(i.index), w[k])
                                              : std::pair{std::pow(w[k], exponent),
                                                          exponent * std::pow(w[k], exponent - 1)};
                }
                value[n] = fromDuplexForm(f[0], f[1]);
                for (int s = 0; s < S; ++s) {
                    const auto dw = duplexForm(slopeA[s]);
                    out[s] = fromDuplexForm(derivative[0] * dw[0], derivative[1] * dw[1]);
                }
                break;
            }
        }
    }
}

// Registers on the stack for the usual short formulas, on the heap past that.
constexpr std::size_t kStackRegisters = 16;

struct Registers {
    explicit Registers(std::size_t count) {
        if (count > kStackRegisters) heap.resize(count);
    }
    Hypercomplex* data() { return heap.empty() ? stack.data() : heap.data(); }
    std::array<Hypercomplex, kStackRegisters> stack;  // written before read, one by one
    std::vector<Hypercomplex> heap;
};

Quaternion quaternionOf(const Hypercomplex& a) {
    return {a[0], a[1], a[2], a[3]};
}
Hypercomplex elementOf(const Quaternion& q) {
    return {q.w, q.x, q.y, q.z, 0, 0, 0, 0};
}

}  // namespace

Complex complexFunctionValue(FormulaFunction function, const Complex& w) {
    switch (function) {
        case FormulaFunction::kExp:
            return std::exp(w);
        case FormulaFunction::kSin:
            return std::sin(w);
        case FormulaFunction::kCos:
            return std::cos(w);
        case FormulaFunction::kSinh:
            return std::sinh(w);
        case FormulaFunction::kCosh:
            return std::cosh(w);
        default:
            return complexFunction(function, w).first;
    }
}

Hypercomplex evaluateInAlgebra(const FormulaProgram& program, const MultiplicationTable& table,
                               const Hypercomplex& z) {
    if (program.algebra() == Algebra::kQuaternion)
        return elementOf(program.evaluate(quaternionOf(z)));
    Registers value(program.instructions().size());
    run<0>(program, table, z, nullptr, value.data(), nullptr);
    return value.data()[program.result()];
}

template <int S>
std::pair<Hypercomplex, std::array<Hypercomplex, S>> evaluateWithDerivatives(
    const FormulaProgram& program, const MultiplicationTable& table, const Hypercomplex& z,
    const std::array<Hypercomplex, S>& h) {
    const std::size_t size = program.instructions().size();
    std::array<Hypercomplex, S> derivatives;
    if (program.algebra() == Algebra::kQuaternion) {
        std::vector<Quaternion> registers(size), tangents(size * S);
        Quaternion direction[S], derivative[S];
        for (std::size_t s = 0; s < S; ++s)
            direction[s] = quaternionOf(h[s]);
        const Quaternion p = runProgramWithTangents<S>(
            program.instructions(), program.result(), quaternionOf(z), direction, Quaternion(0),
            program.constants().data(), program.factors().data(), registers.data(), tangents.data(),
            derivative);
        for (std::size_t s = 0; s < S; ++s)
            derivatives[s] = elementOf(derivative[s]);
        return {elementOf(p), derivatives};
    }
    Registers value(size);
    std::vector<Hypercomplex> slope(size * S);
    run<S>(program, table, z, h.data(), value.data(), slope.data());
    for (std::size_t s = 0; s < S; ++s)
        derivatives[s] = slope[std::size_t(program.result()) * S + s];
    return {value.data()[program.result()], derivatives};
}

std::pair<Hypercomplex, Hypercomplex> evaluateInAlgebraWithDerivative(
    const FormulaProgram& program, const MultiplicationTable& table, const Hypercomplex& z,
    const Hypercomplex& h) {
    const auto [p, derivative] = evaluateWithDerivatives<1>(program, table, z, {h});
    return {p, derivative[0]};
}

std::pair<Hypercomplex, std::array<Hypercomplex, 3>> evaluateInAlgebraWithDerivatives(
    const FormulaProgram& program, const MultiplicationTable& table, const Hypercomplex& z,
    const std::array<Hypercomplex, 3>& h) {
    return evaluateWithDerivatives<3>(program, table, z, h);
}

}  // namespace quaternia
