#include "quaternia/interval/ball_form.h"

#include <cmath>
#include <stdexcept>
#include <vector>

#include "quaternia/interval/function_forms.h"
#include "quaternia/interval/program_on_forms-inl.h"

namespace quaternia {
namespace {

// The error bounds of segment_form.h: gamma of a product's sums, generously, and twice the unit
// roundoff for one sum.
constexpr double kGamma = 0x1p-45;
constexpr double kUlp = 0x1p-52;

double upper(double r) {
    return r * (1 + 0x1p-40) + 0x1p-1000;
}

// |a|, rounded up (a sum of squares within a few ulps, then its root).
double upperNorm(const Hypercomplex& a, int d) {
    double sum = 0;
    for (std::size_t k = 0; k < std::size_t(d); ++k)
        sum += a[k] * a[k];
    return upper(std::sqrt(sum));
}
// sum_k |a_k|, which bounds |a| and each component's rounding scale.
double absoluteSum(const Hypercomplex& a, int d) {
    double sum = 0;
    for (std::size_t k = 0; k < std::size_t(d); ++k)
        sum += std::fabs(a[k]);
    return sum;
}

// The operations of balls for the one interpreter (program_on_forms-inl.h). The algebra's
// product bound kappa (|a b| <= kappa |a| |b|, algebraArithmetic) comes through the table.
struct BallArithmetic {
    using Form = BallForm;

    static Form point(const Hypercomplex& a) { return {a, 0}; }
    static Form combined(const Form& x, const Form& y, double sign, int d) {
        Form r;
        for (std::size_t k = 0; k < std::size_t(d); ++k)
            r.centre[k] = x.centre[k] + sign * y.centre[k];
        r.radius = upper(x.radius + y.radius +
                         kUlp * (absoluteSum(x.centre, d) + absoluteSum(y.centre, d)));
        return r;
    }
    static Form sum(const Form& a, const Form& b, int d) { return combined(a, b, 1, d); }
    static Form difference(const Form& a, const Form& b, int d) { return combined(a, b, -1, d); }
    static Form negated(const Form& a, int d) { return scaled(-1, a, d); }
    static Form scaled(double s, const Form& x, int d) {
        Form r;
        for (std::size_t k = 0; k < std::size_t(d); ++k)
            r.centre[k] = s * x.centre[k];
        r.radius = upper(std::fabs(s) * (x.radius + kUlp * absoluteSum(x.centre, d)));
        return r;
    }
    // (a + u)(b + v) - a b = a v + u b + u v: at most kappa (|a| |v| + |u| |b| + |u| |v|); the
    // centre's rounding at most gamma sum_ij |a_i| |b_j| over the components.
    static Form product(const MultiplicationTable& table, const Form& x, const Form& y) {
        const int d = table.dimension();
        const double kappa = algebraArithmetic(table.algebra()).productBound;
        Form r;
        r.centre = table.multiply(x.centre, y.centre);
        const double a = upperNorm(x.centre, d), b = upperNorm(y.centre, d);
        r.radius = upper(kappa * (a * y.radius + x.radius * b + x.radius * y.radius) +
                         kGamma * absoluteSum(x.centre, d) * absoluteSum(y.centre, d));
        return r;
    }
    static Form square(const MultiplicationTable& table, const Form& x) {
        return product(table, x, x);
    }
    // Components 0 .. 3 mapped by m: the radius by m's Frobenius norm (which bounds its
    // operator norm).
    static Form linear(const double* m, const Form& x) {
        Form r;
        double frobenius = 0, rounding = 0;
        for (std::size_t row = 0; row < 4; ++row)
            for (std::size_t col = 0; col < 4; ++col) {
                const double a = m[row * 4 + col];
                r.centre[row] += a * x.centre[col];
                frobenius += a * a;
                rounding += std::fabs(a) * std::fabs(x.centre[col]);
            }
        r.radius = upper(upper(std::sqrt(frobenius)) * x.radius + kGamma * rounding);
        return r;
    }
    // Through the duplex form: each component of a bicomplex ball is a disc of radius
    // sqrt(2) r (|da|^2 + |db|^2 = 2 |dq|^2), and the image's radius is
    // sqrt((rho_a^2 + rho_b^2) / 2).
    static Form function(FormulaFunction f, const Form& x) {
        const auto& c = x.centre;
        const double disc = upper(std::sqrt(2.0) * x.radius + kUlp * absoluteSum(c, 4));
        const ComplexForm a = functionOnForm(f, {{c[0] - c[3], c[1] + c[2]}, {0, 0}, disc}),
                          b = functionOnForm(f, {{c[0] + c[3], c[1] - c[2]}, {0, 0}, disc});
        Form r;
        r.centre = {
            0.5 * (a.centre.real() + b.centre.real()), 0.5 * (a.centre.imag() + b.centre.imag()),
            0.5 * (a.centre.imag() - b.centre.imag()), 0.5 * (b.centre.real() - a.centre.real())};
        r.radius = upper(std::sqrt(0.5 * (a.radius * a.radius + b.radius * b.radius)) +
                         kUlp * (upperAbs(a.centre) + upperAbs(b.centre)));
        return r;
    }
};

}  // namespace

bool ballStaysInBall(const FormulaProgram& program, const MultiplicationTable& table,
                     const BallForm& ball, int maxIterations, double bailout) {
    thread_local std::vector<BallForm> registers;
    const int d = table.dimension();
    const double limit = bailout * (1 - 0x1p-50);  // below the bailout, past its rounding
    BallForm z = ball;
    for (int n = 0;; ++n) {
        if (!(upper(upperNorm(z.centre, d) + z.radius) <= limit)) return false;
        if (n + 1 >= maxIterations) return true;
        z = interval_forms::run<BallArithmetic>(program, table, z, registers);
    }
}

}  // namespace quaternia
