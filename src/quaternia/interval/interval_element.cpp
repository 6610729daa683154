#include "quaternia/interval/interval_element.h"

#include <cmath>
#include <cstddef>
#include <stdexcept>

namespace quaternia {
namespace {

using Op = Instruction::Op;

IntervalElement negated(const IntervalElement& a) {
    IntervalElement r;
    for (std::size_t i = 0; i < r.size(); ++i)
        r[i] = -a[i];
    return r;
}

IntervalElement sum(const IntervalElement& a, const IntervalElement& b, int dimension) {
    IntervalElement r;
    for (std::size_t i = 0; i < std::size_t(dimension); ++i)
        r[i] = a[i] + b[i];
    return r;
}

IntervalElement difference(const IntervalElement& a, const IntervalElement& b, int dimension) {
    IntervalElement r;
    for (std::size_t i = 0; i < std::size_t(dimension); ++i)
        r[i] = a[i] - b[i];
    return r;
}

IntervalElement scaled(double s, const IntervalElement& a, int dimension) {
    IntervalElement r;
    for (std::size_t i = 0; i < std::size_t(dimension); ++i)
        r[i] = s * a[i];
    return r;
}

// Components 0 .. 3 mapped by the 4x4 matrix m, row by row (Instruction::Op::kLinear).
IntervalElement linearMap(const double* m, const IntervalElement& a) {
    IntervalElement r;
    for (std::size_t row = 0; row < 4; ++row)
        r[row] = m[row * 4] * a[0] + m[row * 4 + 1] * a[1] + m[row * 4 + 2] * a[2] +
                 m[row * 4 + 3] * a[3];
    return r;
}

// a^n, n >= 0, by repeated squaring: every algebra of hypercomplex.h is power-associative (the
// octonions are alternative), so x^a x^b = x^(a+b) whatever the bracketing, and squares are
// tighter than products.
IntervalElement power(const MultiplicationTable& table, const IntervalElement& a, int n) {
    if (n == 0) return pointBox(realElement(1));
    IntervalElement result{}, base = a;
    bool first = true;
    for (int e = n;; e >>= 1) {
        if (e & 1) {
            result = first ? base : multiply(table, result, base);
            first = false;
        }
        if (e == 1) return result;
        base = square(table, base);
    }
}

}  // namespace

IntervalElement pointBox(const Hypercomplex& a) {
    IntervalElement box;
    for (std::size_t i = 0; i < box.size(); ++i)
        box[i] = Interval::point(a[i]);
    return box;
}

bool boxContains(const IntervalElement& box, const Hypercomplex& a, int dimension) {
    for (std::size_t i = 0; i < std::size_t(dimension); ++i)
        if (!box[i].contains(a[i])) return false;
    return true;
}

IntervalElement multiply(const MultiplicationTable& table, const IntervalElement& a,
                         const IntervalElement& b) {
    const int d = table.dimension();
    IntervalElement r{};
    for (int i = 0; i < d; ++i)
        for (int j = 0; j < d; ++j) {
            const BasisProduct p = table.product(i, j);
            const Interval term = a[std::size_t(i)] * b[std::size_t(j)];
            Interval& out = r[std::size_t(p.index)];
            out = p.sign > 0 ? out + term : out - term;
        }
    return r;
}

IntervalElement square(const MultiplicationTable& table, const IntervalElement& a) {
    const int d = table.dimension();
    IntervalElement r{};
    for (int i = 0; i < d; ++i) {
        const BasisProduct p = table.product(i, i);
        const Interval term = quaternia::square(a[std::size_t(i)]);
        Interval& out = r[std::size_t(p.index)];
        out = p.sign > 0 ? out + term : out - term;
        for (int j = i + 1; j < d; ++j) {
            const BasisProduct ij = table.product(i, j), ji = table.product(j, i);
            const Interval term2 = a[std::size_t(i)] * a[std::size_t(j)];
            if (ij.index == ji.index) {
                // a_i a_j (e_i e_j + e_j e_i): twice the product, or nothing where they
                // anticommute (exactly: the two real products are equal).
                const int coefficient = ij.sign + ji.sign;
                if (coefficient == 0) continue;
                Interval& o = r[std::size_t(ij.index)];
                o = o + double(coefficient) * term2;
                continue;
            }
            Interval& o1 = r[std::size_t(ij.index)];
            o1 = ij.sign > 0 ? o1 + term2 : o1 - term2;
            Interval& o2 = r[std::size_t(ji.index)];
            o2 = ji.sign > 0 ? o2 + term2 : o2 - term2;
        }
    }
    return r;
}

double lowerNormSquared(const IntervalElement& a, int dimension) {
    double sum = 0;
    for (std::size_t i = 0; i < std::size_t(dimension); ++i)
        sum = roundedDown(sum + lowerSquare(a[i]));
    return std::max(0.0, sum);
}

std::optional<std::string> withoutIntervalExtension(const FormulaProgram& program) {
    for (const Instruction& i : program.instructions()) {
        if (i.op == Op::kFunction) return std::string("a function");
        if (i.op == Op::kRealPower) return std::string("a real power");
    }
    return std::nullopt;
}

IntervalElement evaluateOnBox(const FormulaProgram& program, const MultiplicationTable& table,
                              const IntervalElement& box, std::vector<IntervalElement>& registers) {
    const std::vector<Instruction>& code = program.instructions();
    if (registers.size() < code.size()) registers.resize(code.size());
    const int d = table.dimension();
    const std::vector<Hypercomplex>& constants = program.elements();
    const double* factors = program.factors().data();
    for (std::size_t n = 0; n < code.size(); ++n) {
        const Instruction& i = code[n];
        const std::size_t a = std::size_t(i.a), b = std::size_t(i.b);
        IntervalElement& out = registers[n];
        switch (i.op) {
            case Op::kZ:
                out = box;
                break;
            case Op::kConstant:
                out = pointBox(constants[std::size_t(i.index)]);
                break;
            case Op::kAdd:
                out = sum(registers[a], registers[b], d);
                break;
            case Op::kSubtract:
                out = difference(registers[a], registers[b], d);
                break;
            case Op::kNegate:
                out = negated(registers[a]);
                break;
            case Op::kMultiply:
                // The same register twice is the same number: its square is tighter.
                out = a == b ? square(table, registers[a])
                             : multiply(table, registers[a], registers[b]);
                break;
            case Op::kSquare:
                out = square(table, registers[a]);
                break;
            case Op::kScale:
                out = scaled(factors[i.index], registers[a], d);
                break;
            case Op::kLinear:
                out = linearMap(factors + i.index, registers[a]);
                break;
            case Op::kPower:
                out = power(table, registers[a], i.index);
                break;
            case Op::kFunction:
            case Op::kRealPower:
                throw std::logic_error("evaluateOnBox: no interval extension");
        }
    }
    return registers[std::size_t(program.result())];
}

bool boxLeavesBall(const FormulaProgram& program, const MultiplicationTable& table,
                   const IntervalElement& box, int maxIterations, double bailout,
                   std::vector<IntervalElement>& registers) {
    const int d = table.dimension();
    const double bailoutSquared = bailout * bailout;
    IntervalElement z = box;
    for (int n = 0;; ++n) {
        if (lowerNormSquared(z, d) > bailoutSquared) return true;
        if (n + 1 >= maxIterations) return false;
        // A box wider than the ball holds points inside it, and iterates only widen: give up
        // (false proves nothing), sparing the iterations left.
        for (std::size_t k = 0; k < std::size_t(d); ++k)
            if (!(z[k].width() <= 2 * bailout)) return false;
        z = evaluateOnBox(program, table, z, registers);
        // Past an overflow the next iterate's bounds would be NaN: decide on this one.
        for (std::size_t k = 0; k < std::size_t(d); ++k)
            if (!std::isfinite(z[k].lo) || !std::isfinite(z[k].hi))
                return lowerNormSquared(z, d) > bailoutSquared;
    }
}

}  // namespace quaternia
