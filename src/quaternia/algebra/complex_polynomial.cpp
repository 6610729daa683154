#include "quaternia/algebra/complex_polynomial.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace quaternia {
namespace {

// Relative tolerance for "these imaginary parts are parallel": coefficients come from decimal
// text, so exact parallelism is the case to recognise, up to rounding.
constexpr double kPlaneTolerance = 1e-12;

Quaternion imaginaryPart(const Quaternion& q) {
    return {0, q.x, q.y, q.z};
}

}  // namespace

ComplexPolynomial::ComplexPolynomial(std::vector<Complex> coefficients)
    : coefficients_(std::move(coefficients)) {
    while (coefficients_.size() > 1 && coefficients_.back() == Complex(0))
        coefficients_.pop_back();
    if (coefficients_.empty()) coefficients_.push_back(0);
}

Complex ComplexPolynomial::evaluate(Complex z) const {
    Complex sum = 0;
    for (auto a = coefficients_.rbegin(); a != coefficients_.rend(); ++a)
        sum = sum * z + *a;
    return sum;
}

Complex ComplexPolynomial::derivative(Complex z) const {
    Complex sum = 0;
    for (int k = degree(); k >= 1; --k)
        sum = sum * z + double(k) * coefficients_[k];
    return sum;
}

ComplexPolynomial ComplexPolynomial::derivativePolynomial() const {
    std::vector<Complex> d;
    for (int k = 1; k <= degree(); ++k)
        d.push_back(double(k) * coefficients_[k]);
    return ComplexPolynomial(d.empty() ? std::vector<Complex>{0} : d);
}

Quaternion planeAxis(const Quaternion& q) {
    double n = imaginaryNorm(q);
    if (n > 1e-150 && n < 1e150) return imaginaryPart(q) / n;
    // The squares under- or overflow (a coefficient of 1e-228 found by fuzzing got the axis i
    // whatever its direction): scaled by the largest component first.
    const double largest = std::max({std::abs(q.x), std::abs(q.y), std::abs(q.z)});
    if (largest == 0) return kUnitI;
    const Quaternion scaled = imaginaryPart(q) / largest;
    return scaled / imaginaryNorm(scaled);
}

bool inPlane(const Quaternion& q, const Quaternion& axis) {
    // Above 1e150 the squares could overflow, and inf <= inf took a coefficient of 1e306 j to be
    // in the plane C_i (found by fuzzing); the test is relative there, so scaling keeps it.
    const double largest = std::max({std::abs(q.w), std::abs(q.x), std::abs(q.y), std::abs(q.z)});
    if (largest > 1e150 && std::isfinite(largest)) return inPlane(q / largest, axis);
    Quaternion v = imaginaryPart(q);
    Quaternion off = v - axis * dot(v, axis);
    return norm(off) <= kPlaneTolerance * std::max(1.0, norm(q));
}

std::optional<ComplexRestriction> restrictToComplexPlane(const Polynomial& p) {
    // The first coefficient with an imaginary part fixes the plane; all others must lie in it.
    Quaternion axis = [&] {
        for (const Term& term : p.terms()) {
            for (const Quaternion& a : term.coefficients) {
                if (imaginaryNorm(a) > 0) return planeAxis(a);
            }
        }
        return kUnitI;
    }();
    ComplexRestriction restriction{ComplexPolynomial(), axis};
    std::vector<Complex> coefficients(std::max(1, p.degree() + 1));
    for (const Term& term : p.terms()) {
        Complex product = 1;
        for (const Quaternion& a : term.coefficients) {
            if (!inPlane(a, axis)) return std::nullopt;
            product *= restriction.toComplex(a);
        }
        coefficients[term.degree()] += product;
    }
    restriction.polynomial = ComplexPolynomial(std::move(coefficients));
    return restriction;
}

std::vector<Complex> aberthRoots(int count, const std::function<Complex(Complex)>& newtonRatio,
                                 double initialRadius, double tolerance, int maxIterations) {
    std::vector<Complex> z(count);
    // Points on a circle, turned by an irrational angle so that no start sits on a symmetry
    // axis of a real polynomial (where iterates could stay stuck).
    for (int k = 0; k < count; ++k) {
        z[k] = std::polar(initialRadius, 2 * std::numbers::pi * (k + 0.25) / count + 0.4);
    }
    std::vector<bool> converged(count, false);
    for (int iteration = 0; iteration < maxIterations; ++iteration) {
        bool all = true;
        for (int k = 0; k < count; ++k) {
            if (converged[k]) continue;
            Complex ratio = newtonRatio(z[k]);
            Complex repulsion = 0;
            for (int j = 0; j < count; ++j) {
                if (j != k) repulsion += 1.0 / (z[k] - z[j]);
            }
            Complex correction = ratio / (1.0 - ratio * repulsion);
            if (!std::isfinite(correction.real()) || !std::isfinite(correction.imag())) {
                correction = 0;
            }
            z[k] -= correction;
            if (std::abs(correction) <= tolerance * std::max(1.0, std::abs(z[k]))) {
                converged[k] = true;
            } else {
                all = false;
            }
        }
        if (all) break;
    }
    return z;
}

std::vector<Complex> polynomialRoots(const ComplexPolynomial& p) {
    const int d = p.degree();
    if (d < 1) return {};
    // Cauchy's bound: every root has |z| <= 1 + max |a_k / a_d|.
    double bound = 0;
    for (int k = 0; k < d; ++k)
        bound = std::max(bound, std::abs(p.coefficients()[k]));
    bound = 1 + bound / std::abs(p.coefficients()[d]);
    return aberthRoots(
        d, [&](Complex z) { return p.evaluate(z) / p.derivative(z); }, 0.5 * bound);
}

}  // namespace quaternia
