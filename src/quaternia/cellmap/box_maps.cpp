#include "quaternia/cellmap/box_maps.h"

#include <cmath>
#include <numbers>

#include "quaternia/util/error.h"

namespace quaternia {
namespace {

struct ComplexInterval {
    Interval re, im;
};

ComplexInterval operator+(const ComplexInterval& a, const ComplexInterval& b) {
    return {a.re + b.re, a.im + b.im};
}
ComplexInterval operator*(const ComplexInterval& a, const ComplexInterval& b) {
    return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re};
}
ComplexInterval constant(std::complex<double> z) {
    return {Interval::point(z.real()), Interval::point(z.imag())};
}

// |x| over an interval.
Interval magnitude(const Interval& x) {
    return {mignitude(x), std::max(std::fabs(x.lo), std::fabs(x.hi))};
}

}  // namespace

double escapeRadiusOfModuli(const std::vector<double>& moduli) {
    const int d = int(moduli.size()) - 1;
    if (d < 2 || !(moduli.back() > 0))
        throw UserError("fractal.formula",
                        "fractal.formula: degree below 2; its orbits need not escape");
    auto f = [&](double r) {  // |a_d| r^d - sum_{k<d} |a_k| r^k - r, with outward-safe slack
        double value = moduli.back();
        for (int k = d - 1; k >= 0; --k)
            value = value * r - moduli[size_t(k)] - (k == 1 ? 1 : 0);
        return value;
    };
    double lo = 0, hi = 1;
    while (f(hi) <= 0)
        lo = hi, hi *= 2;
    for (int n = 0; n < 200 && hi - lo > 1e-15 * hi; ++n) {
        const double mid = 0.5 * (lo + hi);
        (f(mid) > 0 ? hi : lo) = mid;
    }
    // f's rounding is far below this margin at the radii of Julia sets.
    return hi * (1 + 1e-9);
}

BoxMap complexPolynomialBoxMap(std::vector<std::complex<double>> coefficients,
                               std::complex<double> origin, double rotationDegrees,
                               double escapeRadius) {
    const bool turned = rotationDegrees != 0;
    const double angle = rotationDegrees * std::numbers::pi / 180;
    const double cosine = turned ? std::cos(angle) : 1, sine = turned ? std::sin(angle) : 0;
    // The frame's points as plane points, and back: the inverse of the matrix M of the rounded
    // cosine and sine is M^T / (cos^2 + sin^2), and cos^2 + sin^2 of the rounded values is 1
    // within a few 2^-53, which the factor `drift` holds.
    const Interval drift{1 - 0x1p-48, 1 + 0x1p-48};
    auto toPlane = [=](const Interval& u, const Interval& v) -> ComplexInterval {
        if (!turned)
            return {u + Interval::point(origin.real()), v + Interval::point(origin.imag())};
        return {cosine * u - sine * v + Interval::point(origin.real()),
                sine * u + cosine * v + Interval::point(origin.imag())};
    };
    // A plane box back in the frame's coordinates.
    auto toFrame = [=](const ComplexInterval& w) {
        const ComplexInterval p{w.re - Interval::point(origin.real()),
                                w.im - Interval::point(origin.imag())};
        Box3 out{};
        if (!turned) {
            out[0] = p.re, out[1] = p.im;
        } else {
            out[0] = (cosine * p.re + sine * p.im) * drift;
            out[1] = (cosine * p.im - sine * p.re) * drift;
        }
        return out;
    };
    auto horner = [](const std::vector<std::complex<double>>& a, const ComplexInterval& z) {
        ComplexInterval w = constant(a.back());
        for (size_t k = a.size() - 1; k-- > 0;)
            w = w * z + constant(a[k]);
        return w;
    };
    BoxMap map;
    const bool square =
        coefficients.size() == 3 && coefficients[2] == 1.0 && coefficients[1] == 0.0;
    map.image = [=](const Box3& box) {
        const ComplexInterval z = toPlane(box[0], box[1]);
        ComplexInterval w;
        if (square) {
            // z^2 + c with the squares tight (interval.h, square)
            w = {quaternia::square(z.re) - quaternia::square(z.im) +
                     Interval::point(coefficients[0].real()),
                 2.0 * (z.re * z.im) + Interval::point(coefficients[0].imag())};
        } else {
            w = horner(coefficients, z);
        }
        return toFrame(w);
    };
    // f^k by the mean value form: f^k(X) lies in f^k(m) + D (X - m) for the cell's centre m and
    // D holding (f^k)' over X, the product of p' over the boxes f^j(X) (a holomorphic map's
    // difference quotient along a segment is a mean of its derivative there, which lies in the
    // convex box D). The turn of D is applied once, so the result wraps one turned square.
    std::vector<std::complex<double>> slope;
    for (size_t k = 1; k < coefficients.size(); ++k)
        slope.push_back(double(k) * coefficients[k]);
    map.iterateImage = [=](const Box3& box, int iterates) {
        const double mu = 0.5 * (box[0].lo + box[0].hi), mv = 0.5 * (box[1].lo + box[1].hi);
        ComplexInterval z = toPlane(box[0], box[1]);
        ComplexInterval m = toPlane(Interval::point(mu), Interval::point(mv));
        const ComplexInterval offset =
            toPlane(box[0] - Interval::point(mu), box[1] - Interval::point(mv));
        // toPlane added the origin to the offset too: take it off again.
        const ComplexInterval d{offset.re - Interval::point(origin.real()),
                                offset.im - Interval::point(origin.imag())};
        ComplexInterval derivative{Interval::point(1), Interval::point(0)};
        for (int j = 0; j < iterates; ++j) {
            derivative = derivative * horner(slope, z);
            z = horner(coefficients, z);
            m = horner(coefficients, m);
        }
        const ComplexInterval w = m + derivative * d;
        return toFrame(w);
    };
    map.iterates = {3};
    const double radiusSquared = roundedUp(escapeRadius * escapeRadius);
    map.escapes = [=](const Box3& box) {
        const ComplexInterval z = toPlane(box[0], box[1]);
        const double lower = lowerSquare(z.re) + lowerSquare(z.im);
        return roundedDown(lower) > radiusSquared;
    };
    return map;
}

BoxMap reducedPolynomialBoxMap(std::vector<double> coefficients, double realConstant,
                               double imaginaryConstant, double escapeRadius) {
    BoxMap map;
    const bool square = coefficients.size() == 3 && coefficients[2] == 1.0 &&
                        coefficients[1] == 0.0 && coefficients[0] == 0.0;
    map.image = [=](const Box3& box) {
        const Interval& x = box[0];
        const Interval& a = box[1];
        const Interval r{std::max(0.0, box[2].lo), box[2].hi};
        Interval P, Y;
        if (square) {
            P = quaternia::square(x) - quaternia::square(a) - quaternia::square(r);
            Y = 2.0 * x;
        } else {
            // Horner on zeta = x + i rho with zeta^k = X + i rho Y: multiplying by zeta gives
            // (x X - u Y, X + x Y), u = rho^2 (header comment).
            const Interval u = quaternia::square(a) + quaternia::square(r);
            P = Interval::point(coefficients.back());
            Y = Interval::point(0);
            for (size_t k = coefficients.size() - 1; k-- > 0;) {
                const Interval nextP = x * P - u * Y + Interval::point(coefficients[k]);
                Y = P + x * Y;
                P = nextP;
            }
        }
        Box3 out;
        out[0] = P + Interval::point(realConstant);
        out[1] = Y * a + Interval::point(imaginaryConstant);
        out[2] = magnitude(Y) * r;
        out[2].lo = std::max(0.0, out[2].lo);
        return out;
    };
    const double radiusSquared = roundedUp(escapeRadius * escapeRadius);
    map.escapes = [=](const Box3& box) {
        const Interval r{std::max(0.0, box[2].lo), box[2].hi};
        const double lower = lowerSquare(box[0]) + lowerSquare(box[1]) + lowerSquare(r);
        return roundedDown(lower) > radiusSquared;
    };
    return map;
}

std::array<double, 3> reducedPolynomialStep(const std::vector<double>& coefficients,
                                            double realConstant, double imaginaryConstant,
                                            const std::array<double, 3>& xar) {
    const double x = xar[0], a = xar[1], r = xar[2];
    const double u = a * a + r * r;
    double P = coefficients.back(), Y = 0;
    for (size_t k = coefficients.size() - 1; k-- > 0;) {
        const double nextP = x * P - u * Y + coefficients[k];
        Y = P + x * Y;
        P = nextP;
    }
    return {P + realConstant, Y * a + imaginaryConstant, std::fabs(Y) * r};
}

}  // namespace quaternia
