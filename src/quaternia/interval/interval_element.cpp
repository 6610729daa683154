#include "quaternia/interval/interval_element.h"

#include "quaternia/interval/function_forms.h"

#include "quaternia/interval/program_on_forms-inl.h"

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

// The operations of boxes, for the one interpreter (program_on_forms-inl.h).
struct BoxArithmetic {
    static IntervalElement point(const Hypercomplex& a) { return pointBox(a); }
    static IntervalElement sum(const IntervalElement& a, const IntervalElement& b, int d) {
        return quaternia::sum(a, b, d);
    }
    static IntervalElement difference(const IntervalElement& a, const IntervalElement& b, int d) {
        return quaternia::difference(a, b, d);
    }
    static IntervalElement negated(const IntervalElement& a, int) { return quaternia::negated(a); }
    static IntervalElement product(const MultiplicationTable& table, const IntervalElement& a,
                                   const IntervalElement& b) {
        return multiply(table, a, b);
    }
    static IntervalElement square(const MultiplicationTable& table, const IntervalElement& a) {
        return quaternia::square(table, a);
    }
    static IntervalElement scaled(double s, const IntervalElement& a, int d) {
        return quaternia::scaled(s, a, d);
    }
    static IntervalElement linear(const double* m, const IntervalElement& a) {
        return linearMap(m, a);
    }
    // Through the duplex form (function_forms.h): each component's box as a disc about its
    // centre, and back.
    static IntervalElement function(FormulaFunction f, const IntervalElement& x) {
        const Interval re[2] = {x[0] - x[3], x[0] + x[3]}, im[2] = {x[1] + x[2], x[1] - x[2]};
        Interval imageRe[2], imageIm[2];
        for (std::size_t k = 0; k < 2; ++k) {
            const double midRe = 0.5 * (re[k].lo + re[k].hi), midIm = 0.5 * (im[k].lo + im[k].hi);
            const double halfRe = std::max(midRe - re[k].lo, re[k].hi - midRe);
            const double halfIm = std::max(midIm - im[k].lo, im[k].hi - midIm);
            const ComplexForm image =
                functionOnForm(f, {{midRe, midIm}, {}, roundedUp(upperAbs({halfRe, halfIm}))});
            imageRe[k] = Interval{roundedDown(image.centre.real() - image.radius),
                                  roundedUp(image.centre.real() + image.radius)};
            imageIm[k] = Interval{roundedDown(image.centre.imag() - image.radius),
                                  roundedUp(image.centre.imag() + image.radius)};
        }
        // fromDuplexForm: ((a + b) / 2, (a' + b') / 2, (a' - b') / 2, (b - a) / 2).
        IntervalElement r = pointBox(Hypercomplex{});
        r[0] = 0.5 * (imageRe[0] + imageRe[1]);
        r[1] = 0.5 * (imageIm[0] + imageIm[1]);
        r[2] = 0.5 * (imageIm[0] - imageIm[1]);
        r[3] = 0.5 * (imageRe[1] - imageRe[0]);
        return r;
    }
    static bool outside(const IntervalElement& z, int d, double bailout) {
        return lowerNormSquared(z, d) > bailout * bailout;
    }
    static bool hopeless(const IntervalElement& z, int d, double bailout) {
        for (std::size_t k = 0; k < std::size_t(d); ++k)
            if (!(z[k].width() <= 2 * bailout)) return true;
        return false;
    }
};

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
        if (i.op == Op::kFunction && !hasFunctionForm(FormulaFunction(i.index)))
            return "the function " + std::string(formulaFunctionName(FormulaFunction(i.index)));
        if (i.op == Op::kRealPower) return std::string("a real power");
    }
    return std::nullopt;
}

IntervalElement evaluateOnBox(const FormulaProgram& program, const MultiplicationTable& table,
                              const IntervalElement& box, std::vector<IntervalElement>& registers) {
    return interval_forms::run<BoxArithmetic>(program, table, box, registers);
}

bool boxLeavesBall(const FormulaProgram& program, const MultiplicationTable& table,
                   const IntervalElement& box, int maxIterations, double bailout,
                   std::vector<IntervalElement>& registers) {
    return interval_forms::leavesBall<BoxArithmetic>(program, table, box, maxIterations, bailout,
                                                     registers);
}

double upperNormSquared(const IntervalElement& a, int dimension) {
    double sum = 0;
    for (std::size_t i = 0; i < std::size_t(dimension); ++i) {
        const double m = std::max(std::fabs(a[i].lo), std::fabs(a[i].hi));
        // NaN bounds prove nothing: the sum is made infinite.
        if (!(a[i].lo <= a[i].hi)) return HUGE_VAL;
        sum = roundedUp(sum + roundedUp(m * m));
    }
    return std::isfinite(sum) ? sum : HUGE_VAL;
}

bool boxStaysInBall(const FormulaProgram& program, const MultiplicationTable& table,
                    const IntervalElement& box, int maxIterations, double bailout,
                    std::vector<IntervalElement>& registers) {
    const int d = table.dimension();
    // bailout^2 rounded down: the bound must lie below the exact square.
    const double ballSquared = roundedDown(bailout * bailout);
    IntervalElement z = box;
    for (int n = 0;; ++n) {
        if (!(upperNormSquared(z, d) <= ballSquared)) return false;
        if (n + 1 >= maxIterations) return true;
        z = evaluateOnBox(program, table, z, registers);
    }
}

bool boxAboutStaysInBall(const FormulaProgram& program, const MultiplicationTable& table,
                         const Hypercomplex& centre, double radius, int maxIterations,
                         double bailout) {
    thread_local std::vector<IntervalElement> registers;
    IntervalElement box;
    for (std::size_t i = 0; i < std::size_t(table.dimension()); ++i)
        box[i] = {roundedDown(centre[i] - radius), roundedUp(centre[i] + radius)};
    return boxStaysInBall(program, table, box, maxIterations, bailout, registers);
}

}  // namespace quaternia
