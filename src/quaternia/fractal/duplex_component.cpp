#include "quaternia/fractal/duplex_component.h"

#include <algorithm>
#include <cmath>

#include "quaternia/algebra/complex_polynomial.h"
#include "quaternia/fractal/distance.h"

namespace quaternia {
namespace {

using Complex = std::complex<double>;

// Where G is read off an orbit: ln|w| then differs from d^M G by O(|w|^-1) (for |w| past the
// escape radius the Boettcher coordinate is w (1 + O(1 / |w|)) times a_d^(1 / (d - 1))).
constexpr double kPotentialRadius = 1e8;
// Orbits followed this long without reaching it count as bounded (G = 0).
constexpr int kPotentialOrbit = 4000;

// (ln r + lead) / d^m in logarithms: d^m overflows long before m reaches the orbit's cap.
double potentialAt(double logRadius, double lead, int m, int degree) {
    const double level = logRadius + lead;
    return level > 0 ? std::exp(std::log(level) - m * std::log(double(degree))) : 0.0;
}

}  // namespace

DuplexComponent::DuplexComponent(std::vector<Complex> coefficients, double escapeRadius, double rho)
    : polynomial_(std::move(coefficients)), escapeRadius_(escapeRadius), rho_(rho) {
    const std::vector<Complex>& terms = polynomial_.coefficients();
    degree_ = polynomial_.degree();
    // The duplex form's coefficients come from a discrete Fourier transform: those of the
    // degrees a formula such as z^3 + c lacks are rounding noise (1e-16), far below the rounding
    // of the iteration itself, and are left out of the majorant.
    double largest = 0;
    for (const Complex& a : terms)
        largest = std::max(largest, std::abs(a));
    binomial_ = true;
    for (size_t k = 0; k < terms.size(); ++k) {
        const double modulus = std::abs(terms[k]);
        const bool noise = modulus <= 1e-12 * largest;
        moduli_.push_back(noise ? 0.0 : modulus);
        if (k > 0 && k + 1 < terms.size() && !noise) binomial_ = false;
    }
    leadLog_ = std::log(moduli_.back()) / (degree_ - 1);
    // G at each critical point (a root of P'; Aberth-Ehrlich clusters a multiple root, whose
    // members have the same G to rounding), over-estimated by a part in 10^6.
    for (const Complex& omega : polynomialRoots(polynomial_.derivativePolynomial())) {
        Complex w = omega;
        for (int m = 0; m < kPotentialOrbit; ++m) {
            if (std::abs(w) >= kPotentialRadius) {
                criticalPotential_ =
                    std::max(criticalPotential_,
                             (1 + 1e-6) * potentialAt(std::log(std::abs(w)), leadLog_, m, degree_));
                break;
            }
            w = polynomial_.evaluate(w);
        }
    }
    // G_Q(rho): the majorant's orbit of rho (it grows: rho is past P's escape radius).
    double r = rho_;
    for (int m = 0; m < kPotentialOrbit; ++m) {
        if (r >= kPotentialRadius) {
            boundPotential_ = (1 + 1e-6) * potentialAt(std::log(r), 0.0, m, degree_);
            break;
        }
        r = majorant(r);
    }
}

double DuplexComponent::majorant(double r) const {
    double value = moduli_.back();
    for (size_t k = moduli_.size() - 1; k-- > 0;)
        value = value * r + moduli_[k];
    return value;
}

double DuplexComponent::binomialGrowthInverse(double r, double x, int degree) {
    if (!(x > 0)) return 0;
    double rPower = 1;
    for (int m = 0; m < degree; ++m)
        rPower *= r;
    const double s = std::pow(rPower + x, 1.0 / degree);
    double sum = 0, sPower = 1;
    for (int m = 0; m < degree; ++m) {
        double rest = 1;
        for (int l = 0; l < degree - 1 - m; ++l)
            rest *= r;
        sum += sPower * rest;
        sPower *= s;
    }
    return sum > 0 ? x / sum * (1 - 1e-12) : 0;
}

double DuplexComponent::pullBackLimit(int maxIterations) const {
    if (criticalPotential_ == 0) return -1;
    return maxIterations - 1 -
           std::log(boundPotential_ / criticalPotential_) / std::log(double(degree_));
}

double DuplexComponent::inverseGrowth(double r, double target) const {
    if (binomial_) return binomialGrowthInverse(r, target / moduli_.back(), degree_);
    // Q(r + e) - Q(r) grows with e from 0: bracket, then bisect, keeping the lower end.
    const double base = majorant(r);
    double low = 0, high = std::max(target, 1e-300);
    for (int k = 0; k < 2000 && majorant(r + high) - base <= target; ++k)
        high *= 2;
    for (int k = 0; k < 60; ++k) {
        const double middle = 0.5 * (low + high);
        (majorant(r + middle) - base <= target ? low : high) = middle;
    }
    return low;
}

double DuplexComponent::koebeFactor(double potential) const {
    if (criticalPotential_ == 0) return 1;
    if (!(potential > criticalPotential_)) return 0;
    // (e^G - e^G*) / (e^G - 1), in expm1 for the small potentials near the set.
    return (std::expm1(potential) - std::expm1(criticalPotential_)) / std::expm1(potential);
}

double DuplexComponent::distance(Complex w0, int maxIterations) const {
    // The orbit with its moduli and running derivative, to where G can be read (or the cap).
    std::vector<double> moduli;
    std::vector<double> slopes;  // |w'_k| = |dw_k / dw_0|
    Complex w = w0;
    double slope = 1;
    const double radiusSquared = continuationRadiusSquared<double>(degree_);
    const int cap = maxIterations + kMaxContinuation;
    for (int k = 0;; ++k) {
        moduli.push_back(std::abs(w));
        slopes.push_back(slope);
        const double r2 = std::norm(w);
        // Not past the escape radius by iterate N - 1: not certain to escape, it may be in K_N
        // (the escape-time estimate's rule, HypercomplexJuliaSet::bicomplexEstimate).
        if (k + 1 >= maxIterations && !(r2 > escapeRadius_ * escapeRadius_)) return 0;
        if (r2 >= radiusSquared || k >= cap) break;
        slope *= std::abs(polynomial_.derivative(w));
        w = polynomial_.evaluate(w);
    }
    const int m = int(moduli.size()) - 1;
    const double logRadius = std::log(moduli[size_t(m)]);
    if (!(moduli[size_t(m)] > escapeRadius_)) return 0;
    const double estimate = std::max(0.0, 0.5 * moduli[size_t(m)] * logRadius / slopes[size_t(m)]);
    if (criticalPotential_ == 0) return estimate;
    // G(w0), then the first iterate j whose potential d^j G is at least 2 G*.
    const double potential = potentialAt(logRadius, leadLog_, m, degree_);
    int j = 0;
    double level = potential;
    while (level < 2 * criticalPotential_ && j < m) {
        level *= degree_;
        ++j;
    }
    if (j == 0) return estimate * koebeFactor(potential);
    // {G <= G* / d^j} must still hold every point of K_N: G* / d^j >= G_Q(rho) / d^(N-1).
    if (j > pullBackLimit(maxIterations)) return 0;
    // The bound at w_j (the estimate there is |w'_j| times w0's), pulled back step by step.
    double bound = estimate * slopes[size_t(j)] * koebeFactor(level);
    for (int k = j - 1; k >= 0 && bound > 0; --k)
        bound = inverseGrowth(moduli[size_t(k)], bound);
    return bound;
}

}  // namespace quaternia
