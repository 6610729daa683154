// The arithmetic of affine forms (segment_form.h) for the one interpreter
// (program_on_forms-inl.h): forms of D components and S noise symbols held in registers of the
// algebra's own size, products by the multiplication table, and the ball tests of leavesBall.
// Shared by the standard basis (segment_form.cpp) and the bicomplex numbers' duplex form
// (duplex_forms-inl.h). Included by those two files alone.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

#include "quaternia/interval/function_forms.h"
#include "quaternia/interval/segment_form.h"

namespace quaternia::interval_forms {

// gamma_n = n u / (1 - n u) for the at most 2 d^2 + 1 = 129 terms of a product's component (and
// the 3d terms of a norm), rounded up generously.
constexpr double kGamma = 0x1p-45;
// Unit roundoff, twice: the error bound of one sum or product.
constexpr double kUlp = 0x1p-52;

// An algebra's table by output (MultiplicationTable::outputPartner): component k of a product
// sums kTerms terms sign(k, i) a_i b_partner(k, i), i from first(k).
template <int D>
struct TableByOutput {
    static constexpr int kTerms = D;
    const MultiplicationTable& table;
    int first(int) const { return 0; }
    int partner(int k, int i) const { return table.outputPartner(k, i); }
    double sign(int k, int i) const { return table.outputSign(k, i); }
};

// A form of D components and S noise symbols, for the iteration: registers of the algebra's
// own size (a quaternion segment is a third of SegmentForm's bytes). S = 1: a segment
// (SegmentForm); S = 3: a tube (TubeForm).
template <int D, int S>
struct Fixed {
    std::array<double, D> centre{};
    std::array<std::array<double, D>, S> slope{};
    std::array<double, D> radius{};
};

// Every radius computed in round-to-nearest, raised past its own rounding (header comment).
template <std::size_t N>
void inflate(std::array<double, N>& r, int d) {
    for (std::size_t k = 0; k < std::size_t(d); ++k)
        r[k] = r[k] * (1 + 0x1p-40) + 0x1p-1000;
}

// The operations of forms of D components and S symbols, for the one interpreter
// (program_on_forms-inl.h); the interpreter's d is D.
template <int D, int S>
struct FixedArithmetic {
    using Form = Fixed<D, S>;
    static constexpr std::size_t kD = D, kS = S;

    static Form point(const Hypercomplex& a) {
        Form r;
        for (std::size_t k = 0; k < kD; ++k)
            r.centre[k] = a[k];
        return r;
    }

    // |centre| + the |slope|s, per component: the form's reach without its remainder.
    static std::array<double, D> magnitudes(const Form& x) {
        std::array<double, D> m;
        for (std::size_t k = 0; k < kD; ++k) {
            m[k] = std::fabs(x.centre[k]);
            for (std::size_t s = 0; s < kS; ++s)
                m[k] += std::fabs(x.slope[s][k]);
        }
        return m;
    }

    // Component o of a product from its sums: the centre's, each symbol's square's (e_s^2 =
    // 1/2 + [-1/2, 1/2], half of it in the centre and half in the radius) and first-order
    // terms, and the rest of the radius.
    static void setComponent(Form& r, std::size_t o, double cc, const std::array<double, S>& ss,
                             const std::array<double, S>& cs, double radius) {
        double half = 0, halfMagnitude = 0;
        for (std::size_t s = 0; s < kS; ++s) {
            half += 0.5 * ss[s];
            halfMagnitude += 0.5 * std::fabs(ss[s]);
            r.slope[s][o] = cs[s];
        }
        r.centre[o] = cc + half;
        r.radius[o] = halfMagnitude + radius;
    }

    // One pass over the table for the sums of a product (header comment): with several symbols
    // each e_s^2 = 1/2 + [-1/2, 1/2] as for one, and each e_s e_t (s != t) in [-1, 1], its
    // bound in the radius.
    static Form product(const MultiplicationTable& table, const Form& x, const Form& y) {
        return productBy(TableByOutput<D>{table}, x, y);
    }
    template <class Table>
    static Form productBy(const Table& table, const Form& x, const Form& y) {
        const std::array<double, D> xm = magnitudes(x), ym = magnitudes(y);
        std::array<double, D> yAll;
        for (std::size_t k = 0; k < kD; ++k)
            yAll[k] = ym[k] + y.radius[k];
        Form r;
        for (int k = 0; k < D; ++k) {
            // Component k's sums in registers, by the table's output form.
            double cc = 0, rounding = 0, left = 0, right = 0, cross = 0;
            std::array<double, S> ss{}, cs{};
            for (int term = 0; term < Table::kTerms; ++term) {
                const int i = table.first(k) + term;
                const std::size_t a = std::size_t(i), b = std::size_t(table.partner(k, i));
                const double sign = table.sign(k, i);
                cc += sign * (x.centre[a] * y.centre[b]);
                for (std::size_t s = 0; s < kS; ++s) {
                    ss[s] += sign * (x.slope[s][a] * y.slope[s][b]);
                    cs[s] += sign * (x.centre[a] * y.slope[s][b] + x.slope[s][a] * y.centre[b]);
                    for (std::size_t t = 0; t < kS; ++t)
                        if (t != s) cross += std::fabs(x.slope[s][a] * y.slope[t][b]);
                }
                rounding += xm[a] * ym[b];
                left += xm[a] * y.radius[b];
                right += x.radius[a] * yAll[b];
            }
            setComponent(r, std::size_t(k), cc, ss, cs,
                         cross + left + right + 3 * kGamma * rounding);
        }
        inflate(r.radius, D);
        return r;
    }
    // x x by the table's symmetry: in every algebra here e_i e_j = +-e_j e_i, so component k's
    // terms pair up, x_i x_j with x_j x_i (partner(k, j) = i). For the same point the two are
    // equal reals: a pair of equal signs is one term twice, a pair of opposite signs cancels
    // exactly and adds nothing, not even its remainder (the product of two forms would count
    // both terms' remainders). Otherwise the terms are product()'s.
    static Form square(const MultiplicationTable& table, const Form& x) {
        const TableByOutput<D> byOutput{table};
        const std::array<double, D> xm = magnitudes(x);
        std::array<double, D> xAll;
        for (std::size_t k = 0; k < kD; ++k)
            xAll[k] = xm[k] + x.radius[k];
        Form r;
        for (int k = 0; k < D; ++k) {
            double cc = 0, rounding = 0, remainder = 0, cross = 0;
            std::array<double, S> ss{}, cs{};
            for (int i = 0; i < D; ++i) {
                const int j = byOutput.partner(k, i);
                if (j < i) continue;  // counted with its pair
                double weight = byOutput.sign(k, i);
                if (j != i) {
                    if (byOutput.sign(k, j) != weight) continue;  // x_i x_j - x_j x_i = 0
                    weight *= 2;
                }
                const std::size_t a = std::size_t(i), b = std::size_t(j);
                const double w = std::fabs(weight);
                cc += weight * (x.centre[a] * x.centre[b]);
                for (std::size_t s = 0; s < kS; ++s) {
                    ss[s] += weight * (x.slope[s][a] * x.slope[s][b]);
                    cs[s] += weight * (x.centre[a] * x.slope[s][b] + x.slope[s][a] * x.centre[b]);
                    for (std::size_t t = 0; t < kS; ++t)
                        if (t != s) cross += w * std::fabs(x.slope[s][a] * x.slope[t][b]);
                }
                rounding += w * (xm[a] * xm[b]);
                // product()'s left and right: (c + s e) r' + r (c' + s' e + r').
                remainder += w * (xm[a] * x.radius[b] + x.radius[a] * xAll[b]);
            }
            setComponent(r, std::size_t(k), cc, ss, cs, cross + remainder + 3 * kGamma * rounding);
        }
        inflate(r.radius, D);
        return r;
    }

    static Form combined(const Form& x, const Form& y, double sign) {
        Form r;
        for (std::size_t k = 0; k < kD; ++k) {
            r.centre[k] = x.centre[k] + sign * y.centre[k];
            double reach = std::fabs(x.centre[k]) + std::fabs(y.centre[k]);
            for (std::size_t s = 0; s < kS; ++s) {
                r.slope[s][k] = x.slope[s][k] + sign * y.slope[s][k];
                reach += std::fabs(x.slope[s][k]) + std::fabs(y.slope[s][k]);
            }
            r.radius[k] = x.radius[k] + y.radius[k] + kUlp * reach;
        }
        inflate(r.radius, D);
        return r;
    }
    static Form sum(const Form& a, const Form& b, int) { return combined(a, b, 1); }
    static Form difference(const Form& a, const Form& b, int) { return combined(a, b, -1); }

    static Form scaled(double f, const Form& x, int) {
        const std::array<double, D> m = magnitudes(x);
        Form r;
        for (std::size_t k = 0; k < kD; ++k) {
            r.centre[k] = f * x.centre[k];
            for (std::size_t s = 0; s < kS; ++s)
                r.slope[s][k] = f * x.slope[s][k];
            r.radius[k] = std::fabs(f) * (x.radius[k] + kUlp * m[k]);
        }
        inflate(r.radius, D);
        return r;
    }
    static Form negated(const Form& a, int d) { return scaled(-1, a, d); }

    // Components 0 .. 3 mapped by the 4x4 matrix m, row by row (Instruction::Op::kLinear).
    static Form linear(const double* m, const Form& x) {
        const std::array<double, D> reach = magnitudes(x);
        Form r;
        for (std::size_t row = 0; row < 4; ++row) {
            for (std::size_t col = 0; col < 4; ++col) {
                const double a = m[row * 4 + col];
                r.centre[row] += a * x.centre[col];
                for (std::size_t s = 0; s < kS; ++s)
                    r.slope[s][row] += a * x.slope[s][col];
                r.radius[row] += std::fabs(a) * (x.radius[col] + kGamma * reach[col]);
            }
        }
        inflate(r.radius, 4);
        return r;
    }

    // Through the duplex form (function_forms.h): a bicomplex form's two complex components,
    // and back; only the bicomplex numbers take functions. The first symbol is carried
    // through to first order; the others join the remainder (a disc holds them).
    static Form function(FormulaFunction f, const Form& x) {
        if constexpr (D != 4) {
            throw std::logic_error("segment forms: functions are bicomplex");
        } else {
            double others = 0;  // the symbols past the first, in the disc's radius
            for (std::size_t s = 1; s < kS; ++s)
                for (std::size_t k = 0; k < 4; ++k)
                    others += std::fabs(x.slope[s][k]);
            const auto& c = x.centre;
            const auto& v = x.slope[0];
            // duplexForm: ((x0 - x3) + (x1 + x2) i, (x0 + x3) + (x1 - x2) i); each sum's rounding
            // in the disc's radius.
            auto component = [&](double sign) {
                const double rounding =
                    kUlp * (std::fabs(c[0]) + std::fabs(c[3]) + std::fabs(c[1]) + std::fabs(c[2]) +
                            std::fabs(v[0]) + std::fabs(v[3]) + std::fabs(v[1]) + std::fabs(v[2]));
                return ComplexForm{
                    {c[0] - sign * c[3], c[1] + sign * c[2]},
                    {v[0] - sign * v[3], v[1] + sign * v[2]},
                    (x.radius[0] + x.radius[1] + x.radius[2] + x.radius[3] + others + rounding) *
                        (1 + 0x1p-50)};
            };
            const ComplexForm a = functionOnForm(f, component(1)),
                              b = functionOnForm(f, component(-1));
            // fromDuplexForm: ((a + b) / 2, (a' + b') / 2, (a' - b') / 2, (b - a) / 2), each
            // component within (rho_a + rho_b) / 2 of its form.
            Form r;
            r.centre = {0.5 * (a.centre.real() + b.centre.real()),
                        0.5 * (a.centre.imag() + b.centre.imag()),
                        0.5 * (a.centre.imag() - b.centre.imag()),
                        0.5 * (b.centre.real() - a.centre.real())};
            r.slope[0] = {
                0.5 * (a.slope.real() + b.slope.real()), 0.5 * (a.slope.imag() + b.slope.imag()),
                0.5 * (a.slope.imag() - b.slope.imag()), 0.5 * (b.slope.real() - a.slope.real())};
            const double rounding = kUlp * (upperAbs(a.centre) + upperAbs(b.centre) +
                                            upperAbs(a.slope) + upperAbs(b.slope));
            for (std::size_t k = 0; k < 4; ++k)
                r.radius[k] = 0.5 * (a.radius + b.radius) + rounding;
            inflate(r.radius, 4);
            return r;
        }
    }

    static bool outside(const Form& z, int, double bailout) {
        // Most iterates lie partly inside the ball: where even the farthest corner of the form's
        // box does (with a margin for rounding), lowerNorm's exact minimum is not needed.
        const std::array<double, D> m = magnitudes(z);
        double farthest = 0;
        for (std::size_t k = 0; k < kD; ++k)
            farthest += (m[k] + z.radius[k]) * (m[k] + z.radius[k]);
        if (farthest < 0.99 * bailout * bailout) return false;
        return lowerNorm(widened(z), D) > bailout;
    }
    static bool hopeless(const Form& z, int, double bailout) {
        const std::array<double, D> m = magnitudes(z);
        for (std::size_t k = 0; k < kD; ++k)
            if (!(m[k] - std::fabs(z.centre[k]) + z.radius[k] <= 2 * bailout)) return true;
        return false;
    }

    // The first D components of a SegmentForm, and back: a form of more symbols is widened to
    // one whose remainder holds the symbols past the first (lowerNorm's exact minimum is over
    // the first symbol alone).
    static Form narrowed(const SegmentForm& form) {
        Form r;
        for (std::size_t k = 0; k < kD; ++k) {
            r.centre[k] = form.centre[k];
            r.slope[0][k] = form.slope[k];
            r.radius[k] = form.radius[k];
        }
        return r;
    }
    static Form narrowed(const TubeForm& form) {
        static_assert(S == TubeForm::kSymbols);
        Form r;
        for (std::size_t k = 0; k < kD; ++k) {
            r.centre[k] = form.centre[k];
            for (std::size_t s = 0; s < kS; ++s)
                r.slope[s][k] = form.slopes[s][k];
            r.radius[k] = form.radius[k];
        }
        return r;
    }
    static SegmentForm widened(const Form& form) {
        SegmentForm r;
        for (std::size_t k = 0; k < kD; ++k) {
            r.centre[k] = form.centre[k];
            r.slope[k] = form.slope[0][k];
            double others = form.radius[k];
            for (std::size_t s = 1; s < kS; ++s)
                others += std::fabs(form.slope[s][k]);
            r.radius[k] = kS > 1 ? others * (1 + 0x1p-50) : others;
        }
        return r;
    }
    // Each thread's registers for the interpreter: the marchers test many segments from every
    // thread.
    static std::vector<Form>& registers() {
        thread_local std::vector<Form> scratch;
        return scratch;
    }
};

}  // namespace quaternia::interval_forms
