#include "quaternia/interval/segment_form.h"

#include "quaternia/interval/function_forms.h"
#include "quaternia/interval/program_on_forms-inl.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>

namespace quaternia {
namespace {

// gamma_n = n u / (1 - n u) for the at most 2 d^2 + 1 = 129 terms of a product's component (and
// the 3d terms of a norm), rounded up generously.
constexpr double kGamma = 0x1p-45;
// Unit roundoff, twice: the error bound of one sum or product.
constexpr double kUlp = 0x1p-52;

// A segment form of D components, for the iteration: registers of the algebra's own size (a
// quaternion form is a third of SegmentForm's bytes).
template <int D>
struct Fixed {
    std::array<double, D> centre{}, slope{}, radius{};
};

// Every radius computed in round-to-nearest, raised past its own rounding (header comment).
template <std::size_t N>
void inflate(std::array<double, N>& r, int d) {
    for (std::size_t k = 0; k < std::size_t(d); ++k)
        r[k] = r[k] * (1 + 0x1p-40) + 0x1p-1000;
}

// The operations of segment forms of D components, for the one interpreter
// (program_on_forms-inl.h); the interpreter's d is D.
template <int D>
struct FixedArithmetic {
    using Form = Fixed<D>;
    static constexpr std::size_t kD = D;

    static Form point(const Hypercomplex& a) {
        Form r;
        for (std::size_t k = 0; k < kD; ++k)
            r.centre[k] = a[k];
        return r;
    }

    // One pass over the table for the seven sums of a product (header comment).
    static Form product(const MultiplicationTable& table, const Form& x, const Form& y) {
        std::array<double, D> xm, ym, yAll;
        for (std::size_t k = 0; k < kD; ++k) {
            xm[k] = std::fabs(x.centre[k]) + std::fabs(x.slope[k]);
            ym[k] = std::fabs(y.centre[k]) + std::fabs(y.slope[k]);
            yAll[k] = ym[k] + y.radius[k];
        }
        Form r;
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
    static Form square(const MultiplicationTable& table, const Form& x) {
        return product(table, x, x);
    }

    static Form combined(const Form& x, const Form& y, double sign) {
        Form r;
        for (std::size_t k = 0; k < kD; ++k) {
            r.centre[k] = x.centre[k] + sign * y.centre[k];
            r.slope[k] = x.slope[k] + sign * y.slope[k];
            r.radius[k] = x.radius[k] + y.radius[k] +
                          kUlp * (std::fabs(x.centre[k]) + std::fabs(y.centre[k]) +
                                  std::fabs(x.slope[k]) + std::fabs(y.slope[k]));
        }
        inflate(r.radius, D);
        return r;
    }
    static Form sum(const Form& a, const Form& b, int) { return combined(a, b, 1); }
    static Form difference(const Form& a, const Form& b, int) { return combined(a, b, -1); }

    static Form scaled(double s, const Form& x, int) {
        Form r;
        for (std::size_t k = 0; k < kD; ++k) {
            r.centre[k] = s * x.centre[k];
            r.slope[k] = s * x.slope[k];
            r.radius[k] = std::fabs(s) *
                          (x.radius[k] + kUlp * (std::fabs(x.centre[k]) + std::fabs(x.slope[k])));
        }
        inflate(r.radius, D);
        return r;
    }
    static Form negated(const Form& a, int d) { return scaled(-1, a, d); }

    // Components 0 .. 3 mapped by the 4x4 matrix m, row by row (Instruction::Op::kLinear).
    static Form linear(const double* m, const Form& x) {
        Form r;
        for (std::size_t row = 0; row < 4; ++row) {
            for (std::size_t col = 0; col < 4; ++col) {
                const double a = m[row * 4 + col];
                r.centre[row] += a * x.centre[col];
                r.slope[row] += a * x.slope[col];
                r.radius[row] +=
                    std::fabs(a) *
                    (x.radius[col] + kGamma * (std::fabs(x.centre[col]) + std::fabs(x.slope[col])));
            }
        }
        inflate(r.radius, 4);
        return r;
    }

    // Through the duplex form (function_forms.h): a bicomplex form's two complex components,
    // and back; only the bicomplex numbers take functions.
    static Form function(FormulaFunction f, const Form& x) {
        if constexpr (D != 4) {
            throw std::logic_error("segment forms: functions are bicomplex");
        } else {
            // duplexForm: ((x0 - x3) + (x1 + x2) i, (x0 + x3) + (x1 - x2) i); each sum's rounding
            // in the disc's radius.
            auto component = [&](double sign) {
                const double rounding = kUlp * (std::fabs(x.centre[0]) + std::fabs(x.centre[3]) +
                                                std::fabs(x.centre[1]) + std::fabs(x.centre[2]) +
                                                std::fabs(x.slope[0]) + std::fabs(x.slope[3]) +
                                                std::fabs(x.slope[1]) + std::fabs(x.slope[2]));
                return ComplexForm{
                    {x.centre[0] - sign * x.centre[3], x.centre[1] + sign * x.centre[2]},
                    {x.slope[0] - sign * x.slope[3], x.slope[1] + sign * x.slope[2]},
                    (x.radius[0] + x.radius[1] + x.radius[2] + x.radius[3] + rounding) *
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
            r.slope = {
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
        double farthest = 0;
        for (std::size_t k = 0; k < kD; ++k) {
            const double m = std::fabs(z.centre[k]) + std::fabs(z.slope[k]) + z.radius[k];
            farthest += m * m;
        }
        if (farthest < 0.99 * bailout * bailout) return false;
        return lowerNorm(widened(z), D) > bailout;
    }
    static bool hopeless(const Form& z, int, double bailout) {
        for (std::size_t k = 0; k < kD; ++k)
            if (!(std::fabs(z.slope[k]) + z.radius[k] <= 2 * bailout)) return true;
        return false;
    }

    // The first D components of each part, from one kind of form to the other.
    template <class To, class From>
    static To converted(const From& form) {
        To r;
        for (std::size_t k = 0; k < kD; ++k) {
            r.centre[k] = form.centre[k];
            r.slope[k] = form.slope[k];
            r.radius[k] = form.radius[k];
        }
        return r;
    }
    static Form narrowed(const SegmentForm& form) { return converted<Form>(form); }
    static SegmentForm widened(const Form& form) { return converted<SegmentForm>(form); }
    // Each thread's registers for the interpreter: the marchers test many segments from every
    // thread.
    static std::vector<Form>& registers() {
        thread_local std::vector<Form> scratch;
        return scratch;
    }
};

// f(arithmetic) with the forms of the algebra's dimension (4 or 8).
template <class F>
auto withDimension(int d, F&& f) {
    if (d == 4) return f(FixedArithmetic<4>{});
    if (d == kMaxAlgebraDimension) return f(FixedArithmetic<kMaxAlgebraDimension>{});
    throw std::logic_error("segment forms: algebras have 4 or 8 components");
}

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
                              const SegmentForm& form) {
    return withDimension(table.dimension(), [&](auto arithmetic) {
        using A = decltype(arithmetic);
        return A::widened(
            interval_forms::run<A>(program, table, A::narrowed(form), A::registers()));
    });
}

bool segmentLeavesBall(const FormulaProgram& program, const MultiplicationTable& table,
                       const SegmentForm& form, int maxIterations, double bailout) {
    return withDimension(table.dimension(), [&](auto arithmetic) {
        using A = decltype(arithmetic);
        return interval_forms::leavesBall<A>(program, table, A::narrowed(form), maxIterations,
                                             bailout, A::registers());
    });
}

}  // namespace quaternia
