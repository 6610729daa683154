#include "quaternia/interval/segment_form.h"

#include "quaternia/interval/duplex_forms-inl.h"
#include "quaternia/interval/form_arithmetic-inl.h"
#include "quaternia/interval/program_on_forms-inl.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <utility>

namespace quaternia {
namespace {

using interval_forms::DuplexArithmetic;
using interval_forms::FixedArithmetic;
using interval_forms::inflate;
using interval_forms::kGamma;
using interval_forms::kUlp;

// f(arithmetic) with the forms of the algebra's dimension (4 or 8).
template <int S = 1, class F>
auto withDimension(int d, F&& f) {
    if (d == 4) return f(FixedArithmetic<4, S>{});
    if (d == kMaxAlgebraDimension) return f(FixedArithmetic<kMaxAlgebraDimension, S>{});
    throw std::logic_error("segment forms: algebras have 4 or 8 components");
}

// f(arithmetic) with the forms of the table's algebra: 4 or 8 components, the bicomplex
// numbers in their duplex coordinates (duplex_forms-inl.h).
template <int S = 1, class F>
auto withArithmetic(const MultiplicationTable& table, F&& f) {
    if (table.algebra() == Algebra::kBicomplex) return f(DuplexArithmetic<S>{});
    return withDimension<S>(table.dimension(), std::forward<F>(f));
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
    return withArithmetic(table, [&](auto arithmetic) {
        using A = decltype(arithmetic);
        return interval_forms::leavesBall<A>(program, table, A::narrowed(form), maxIterations,
                                             bailout, A::registers());
    });
}

TubeForm tubeAbout(const Hypercomplex& from, const Hypercomplex& to, const Hypercomplex& across1,
                   const Hypercomplex& across2, double thickness, int dimension) {
    TubeForm form;
    for (std::size_t k = 0; k < std::size_t(dimension); ++k) {
        form.centre[k] = 0.5 * (from[k] + to[k]);
        form.slopes[0][k] = 0.5 * (to[k] - from[k]);
        form.slopes[1][k] = across1[k];
        form.slopes[2][k] = across2[k];
        form.radius[k] = thickness + kUlp * (std::fabs(from[k]) + std::fabs(to[k]));
    }
    inflate(form.radius, dimension);
    return form;
}

TubeForm evaluateOnTube(const FormulaProgram& program, const MultiplicationTable& table,
                        const TubeForm& form) {
    return withDimension<TubeForm::kSymbols>(table.dimension(), [&](auto arithmetic) {
        using A = decltype(arithmetic);
        const auto image =
            interval_forms::run<A>(program, table, A::narrowed(form), A::registers());
        TubeForm r;
        for (std::size_t k = 0; k < A::kD; ++k) {
            r.centre[k] = image.centre[k];
            for (std::size_t s = 0; s < A::kS; ++s)
                r.slopes[s][k] = image.slope[s][k];
            r.radius[k] = image.radius[k];
        }
        return r;
    });
}

bool tubeContains(const TubeForm& form, const std::array<double, TubeForm::kSymbols>& e,
                  const Hypercomplex& point, int dimension) {
    for (std::size_t k = 0; k < std::size_t(dimension); ++k) {
        double value = form.centre[k];
        for (std::size_t s = 0; s < e.size(); ++s)
            value += form.slopes[s][k] * e[s];
        if (!(std::fabs(point[k] - value) <= form.radius[k])) return false;
    }
    return true;
}

bool tubeLeavesBall(const FormulaProgram& program, const MultiplicationTable& table,
                    const TubeForm& form, int maxIterations, double bailout) {
    return withArithmetic<TubeForm::kSymbols>(table, [&](auto arithmetic) {
        using A = decltype(arithmetic);
        return interval_forms::leavesBall<A>(program, table, A::narrowed(form), maxIterations,
                                             bailout, A::registers());
    });
}

}  // namespace quaternia
