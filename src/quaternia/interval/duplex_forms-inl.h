// The bicomplex numbers' forms in their duplex (idempotent) coordinates: a bicomplex number q =
// x0 + x1 i + x2 j + x3 k is the pair of complex numbers a = (x0 - x3) + (x1 + x2) i and
// b = (x0 + x3) + (x1 - x2) i, its product is the pair's product component by component, and
// |q|^2 = (|a|^2 + |b|^2) / 2 (fractal/duplex_component.h; Price, "An Introduction to
// Multicomplex Spaces and Functions", 1991). So the filled set is the product of the two
// components' sets, and a point near it escapes through one component while the other stays
// near its Julia set, its derivative growing. In the standard basis both spread into every
// component: the escaping one's form is widened by the other's remainder through the table's
// absolute values, and the norm's lower bound over a box that straddles 0 in each component
// is 0. In duplex coordinates the two never mix, and the escaping component alone proves the
// norm. Segments and tubes are turned into these coordinates once, before the iteration.
// Included by segment_form.cpp alone.
#pragma once

#include <cmath>
#include <cstddef>
#include <stdexcept>

#include "quaternia/interval/form_arithmetic-inl.h"

namespace quaternia::interval_forms {

// The pairs (0, 1) and (2, 3) multiplied as complex numbers: component k sums the two terms
// of its pair.
struct DuplexTable {
    static constexpr int kTerms = 2;
    int first(int k) const { return k & ~1; }
    int partner(int k, int i) const {
        const int p = k & ~1;
        return p + ((k - p) ^ (i - p));
    }
    double sign(int k, int i) const { return k == (k & ~1) && i == (k | 1) ? -1.0 : 1.0; }
};

template <int S>
struct DuplexArithmetic : FixedArithmetic<4, S> {
    using Base = FixedArithmetic<4, S>;
    using Form = typename Base::Form;
    static constexpr std::size_t kS = S;

    // The duplex coordinates (a.re, a.im, b.re, b.im) of q's components, each sum's rounding
    // returned in `rounding`.
    static std::array<double, 4> duplex(const double* x, std::array<double, 4>& rounding) {
        const std::array<double, 4> d{x[0] - x[3], x[1] + x[2], x[0] + x[3], x[1] - x[2]};
        rounding[0] += kUlp * (std::fabs(x[0]) + std::fabs(x[3]));
        rounding[1] += kUlp * (std::fabs(x[1]) + std::fabs(x[2]));
        rounding[2] += kUlp * (std::fabs(x[0]) + std::fabs(x[3]));
        rounding[3] += kUlp * (std::fabs(x[1]) + std::fabs(x[2]));
        return d;
    }
    // A box remainder of the standard components in duplex coordinates: each duplex component
    // is the sum or difference of two.
    static std::array<double, 4> duplexRadius(const double* r) {
        return {r[0] + r[3], r[1] + r[2], r[0] + r[3], r[1] + r[2]};
    }

    static Form point(const Hypercomplex& q) {
        Form r;
        std::array<double, 4> rounding{};
        r.centre = duplex(&q[0], rounding);
        r.radius = rounding;
        inflate(r.radius, 4);
        return r;
    }
    static Form product(const MultiplicationTable&, const Form& x, const Form& y) {
        return Base::productBy(DuplexTable{}, x, y);
    }
    static Form square(const MultiplicationTable& table, const Form& x) {
        return product(table, x, x);
    }
    static Form linear(const double*, const Form&) {
        throw std::logic_error("duplex forms: bicomplex programs have no linear maps");
    }

    // Each component's complex form through f directly (function_forms.h); the symbols past
    // the first join its disc.
    static Form function(FormulaFunction f, const Form& x) {
        Form r;
        for (int p = 0; p < 4; p += 2) {
            const std::size_t re = std::size_t(p), im = std::size_t(p + 1);
            double others = 0;
            for (std::size_t s = 1; s < kS; ++s)
                others += std::fabs(x.slope[s][re]) + std::fabs(x.slope[s][im]);
            const ComplexForm c = functionOnForm(
                f, ComplexForm{{x.centre[re], x.centre[im]},
                               {x.slope[0][re], x.slope[0][im]},
                               (x.radius[re] + x.radius[im] + others) * (1 + 0x1p-50)});
            r.centre[re] = c.centre.real();
            r.centre[im] = c.centre.imag();
            r.slope[0][re] = c.slope.real();
            r.slope[0][im] = c.slope.imag();
            r.radius[re] = r.radius[im] = c.radius;
        }
        return r;
    }

    // |q| = |(a, b)| / sqrt(2): outside the ball of `bailout` where the duplex form is outside
    // that of sqrt(2) bailout (rounded up).
    static double duplexBall(double bailout) { return std::sqrt(2.0) * bailout * (1 + 0x1p-50); }
    // |(a, b)| is at least |a| and at least |b|: a component that escapes proves the norm
    // whatever the other's remainder has grown to (even past every bound).
    static bool outside(const Form& z, int d, double bailout) {
        const double ball = duplexBall(bailout);
        if (Base::outside(z, d, ball)) return true;
        const SegmentForm whole = Base::widened(z);
        for (std::size_t p = 0; p < 4; p += 2) {
            SegmentForm pair;
            for (std::size_t k = 0; k < 2; ++k) {
                pair.centre[k] = whole.centre[p + k];
                pair.slope[k] = whole.slope[p + k];
                pair.radius[k] = whole.radius[p + k];
            }
            if (lowerNorm(pair, 2) > ball) return true;
        }
        return false;
    }
    // Only where both components' forms are wider than the ball: one may still escape.
    static bool hopeless(const Form& z, int, double bailout) {
        const double ball = duplexBall(bailout);
        const std::array<double, 4> m = Base::magnitudes(z);
        bool both = true;
        for (std::size_t p = 0; p < 4; p += 2) {
            bool wide = false;
            for (std::size_t k = p; k < p + 2; ++k)
                wide = wide || !(m[k] - std::fabs(z.centre[k]) + z.radius[k] <= 2 * ball);
            both = both && wide;
        }
        return both;
    }

    // A segment or tube of the standard basis in duplex coordinates.
    template <class Standard>
    static Form narrowed(const Standard& standard) {
        const Form x = Base::narrowed(standard);
        Form r;
        std::array<double, 4> rounding{};
        r.centre = duplex(x.centre.data(), rounding);
        for (std::size_t s = 0; s < kS; ++s)
            r.slope[s] = duplex(x.slope[s].data(), rounding);
        const std::array<double, 4> radius = duplexRadius(x.radius.data());
        for (std::size_t k = 0; k < 4; ++k)
            r.radius[k] = radius[k] + rounding[k];
        inflate(r.radius, 4);
        return r;
    }
    static std::vector<Form>& registers() {
        thread_local std::vector<Form> scratch;
        return scratch;
    }
};

}  // namespace quaternia::interval_forms
