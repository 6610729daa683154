#include "quaternia/interval/segment_form.h"

#include "quaternia/interval/program_on_forms-inl.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>

namespace quaternia {
namespace {

using Radius = std::array<double, kMaxAlgebraDimension>;

// gamma_n = n u / (1 - n u) for the at most 2 d^2 + 1 = 129 terms of a product's component (and
// the 3d terms of a norm), rounded up generously.
constexpr double kGamma = 0x1p-45;
// Unit roundoff, twice: the error bound of one sum or product.
constexpr double kUlp = 0x1p-52;

// Every radius computed in round-to-nearest, raised past its own rounding (header comment).
void inflate(Radius& r, int d) {
    for (std::size_t k = 0; k < std::size_t(d); ++k)
        r[k] = r[k] * (1 + 0x1p-40) + 0x1p-1000;
}

// One pass over the table for the seven sums of a product (header comment), unrolled for the
// algebra's dimension.
template <int D>
SegmentForm multiplyFixed(const MultiplicationTable& table, const SegmentForm& x,
                          const SegmentForm& y) {
    std::array<double, D> xm, ym, yAll;
    for (std::size_t k = 0; k < D; ++k) {
        xm[k] = std::fabs(x.centre[k]) + std::fabs(x.slope[k]);
        ym[k] = std::fabs(y.centre[k]) + std::fabs(y.slope[k]);
        yAll[k] = ym[k] + y.radius[k];
    }
    SegmentForm r;
    for (int k = 0; k < D; ++k) {
        // Component k's seven sums in registers, by the table's output form.
        double cc = 0, ss = 0, cs = 0, sc = 0, rounding = 0, left = 0, right = 0;
        for (int i = 0; i < D; ++i) {
            const std::size_t a = std::size_t(i), b = std::size_t(table.outputPartner(k, i));
            const double sign = table.outputSign(k, i);
            cc += sign * (x.centre[a] * y.centre[b]);
            ss += sign * (x.slope[a] * y.slope[b]);
            cs += sign * (x.centre[a] * y.slope[b]);
            sc += sign * (x.slope[a] * y.centre[b]);
            rounding += xm[a] * ym[b];
            left += xm[a] * y.radius[b];
            right += x.radius[a] * yAll[b];
        }
        const std::size_t o = std::size_t(k);
        r.centre[o] = cc + 0.5 * ss;
        r.slope[o] = cs + sc;
        r.radius[o] = 0.5 * std::fabs(ss) + left + right + 3 * kGamma * rounding;
    }
    inflate(r.radius, D);
    return r;
}

SegmentForm multiply(const MultiplicationTable& table, const SegmentForm& x, const SegmentForm& y) {
    return table.dimension() == 4 ? multiplyFixed<4>(table, x, y)
                                  : multiplyFixed<kMaxAlgebraDimension>(table, x, y);
}

SegmentForm combined(const SegmentForm& x, const SegmentForm& y, double sign, int d) {
    SegmentForm r;
    for (std::size_t k = 0; k < std::size_t(d); ++k) {
        r.centre[k] = x.centre[k] + sign * y.centre[k];
        r.slope[k] = x.slope[k] + sign * y.slope[k];
        r.radius[k] = x.radius[k] + y.radius[k] +
                      kUlp * (std::fabs(x.centre[k]) + std::fabs(y.centre[k]) +
                              std::fabs(x.slope[k]) + std::fabs(y.slope[k]));
    }
    inflate(r.radius, d);
    return r;
}

SegmentForm scaled(double s, const SegmentForm& x, int d) {
    SegmentForm r;
    for (std::size_t k = 0; k < std::size_t(d); ++k) {
        r.centre[k] = s * x.centre[k];
        r.slope[k] = s * x.slope[k];
        r.radius[k] =
            std::fabs(s) * (x.radius[k] + kUlp * (std::fabs(x.centre[k]) + std::fabs(x.slope[k])));
    }
    inflate(r.radius, d);
    return r;
}

// Components 0 .. 3 mapped by the 4x4 matrix m, row by row (Instruction::Op::kLinear).
SegmentForm linearMap(const double* m, const SegmentForm& x) {
    SegmentForm r;
    for (std::size_t row = 0; row < 4; ++row)
        for (std::size_t col = 0; col < 4; ++col) {
            const double a = m[row * 4 + col];
            r.centre[row] += a * x.centre[col];
            r.slope[row] += a * x.slope[col];
            r.radius[row] +=
                std::fabs(a) *
                (x.radius[col] + kGamma * (std::fabs(x.centre[col]) + std::fabs(x.slope[col])));
        }
    inflate(r.radius, 4);
    return r;
}

// The operations of segment forms, for the one interpreter (program_on_forms-inl.h).
struct SegmentArithmetic {
    static SegmentForm point(const Hypercomplex& a) { return SegmentForm{a, {}, {}}; }
    static SegmentForm sum(const SegmentForm& a, const SegmentForm& b, int d) {
        return combined(a, b, 1, d);
    }
    static SegmentForm difference(const SegmentForm& a, const SegmentForm& b, int d) {
        return combined(a, b, -1, d);
    }
    static SegmentForm negated(const SegmentForm& a, int d) { return quaternia::scaled(-1, a, d); }
    static SegmentForm product(const MultiplicationTable& table, const SegmentForm& a,
                               const SegmentForm& b) {
        return multiply(table, a, b);
    }
    static SegmentForm square(const MultiplicationTable& table, const SegmentForm& a) {
        return multiply(table, a, a);
    }
    static SegmentForm scaled(double s, const SegmentForm& a, int d) {
        return quaternia::scaled(s, a, d);
    }
    static SegmentForm linear(const double* m, const SegmentForm& a) { return linearMap(m, a); }
    static bool outside(const SegmentForm& z, int d, double bailout) {
        return lowerNorm(z, d) > bailout;
    }
    static bool hopeless(const SegmentForm& z, int d, double bailout) {
        for (std::size_t k = 0; k < std::size_t(d); ++k)
            if (!(std::fabs(z.slope[k]) + z.radius[k] <= 2 * bailout)) return true;
        return false;
    }
};

}  // namespace

SegmentForm segmentBetween(const Hypercomplex& from, const Hypercomplex& to, double thickness,
                           int dimension) {
    SegmentForm form;
    for (std::size_t k = 0; k < std::size_t(dimension); ++k) {
        form.centre[k] = 0.5 * (from[k] + to[k]);
        form.slope[k] = 0.5 * (to[k] - from[k]);
        form.radius[k] = thickness + kUlp * (std::fabs(from[k]) + std::fabs(to[k]));
    }
    inflate(form.radius, dimension);
    return form;
}

bool formContains(const SegmentForm& form, double e, const Hypercomplex& point, int dimension) {
    for (std::size_t k = 0; k < std::size_t(dimension); ++k)
        if (!(std::fabs(point[k] - (form.centre[k] + form.slope[k] * e)) <= form.radius[k]))
            return false;
    return true;
}

double lowerNorm(const SegmentForm& form, int dimension) {
    // |c + s e|^2 is a convex quadratic in e: its least value on [-1, 1] is at -c.s / |s|^2,
    // clamped. Evaluated there, it exceeds the least value by |s|^2 (e - e0)^2 for a rounded e
    // (negligible next to the margin below), and by its own rounding.
    double ss = 0, cs = 0;
    for (std::size_t k = 0; k < std::size_t(dimension); ++k) {
        ss += form.slope[k] * form.slope[k];
        cs += form.centre[k] * form.slope[k];
    }
    const double e = ss > 0 ? std::clamp(-cs / ss, -1.0, 1.0) : 0.0;
    double squared = 0, scale = 0, remainder = 0;
    for (std::size_t k = 0; k < std::size_t(dimension); ++k) {
        const double v = form.centre[k] + form.slope[k] * e;
        squared += v * v;
        const double m = std::fabs(form.centre[k]) + std::fabs(form.slope[k]);
        scale += m * m;
        remainder += form.radius[k] * form.radius[k];
    }
    const double lowerSquared = squared - kGamma * scale - 0x1p-1000;
    if (!(lowerSquared > 0)) return 0;
    return std::sqrt(lowerSquared) * (1 - 0x1p-50) - std::sqrt(remainder) * (1 + 0x1p-50);
}

SegmentForm evaluateOnSegment(const FormulaProgram& program, const MultiplicationTable& table,
                              const SegmentForm& form, std::vector<SegmentForm>& registers) {
    return interval_forms::run<SegmentArithmetic>(program, table, form, registers);
}

bool segmentLeavesBall(const FormulaProgram& program, const MultiplicationTable& table,
                       const SegmentForm& form, int maxIterations, double bailout,
                       std::vector<SegmentForm>& registers) {
    return interval_forms::leavesBall<SegmentArithmetic>(program, table, form, maxIterations,
                                                         bailout, registers);
}

}  // namespace quaternia
