#include "quaternia/fractal/distance.h"

#include <algorithm>
#include <cmath>

#include "quaternia/fractal/escape_time.h"
#include "quaternia/interval/interval_element.h"
#include "quaternia/util/error.h"

namespace quaternia {

#include "quaternia/fractal/julia_steps-inl.h"  // the iteration formulas, shared with the lanes

namespace {

Quaternion power(const Quaternion& z, int degree) {
    Quaternion result = z;
    for (int k = 1; k < degree; ++k)
        result = result * z;
    return result;
}

// One form of polynomial as the hot loops see it: the map, and the squared gain of the running
// derivative norm, (|z'_{n+1}| / |z'_n|)^2 at |z_n|^2 = r2. Carrying |z'|^2 saves a square root
// per iteration; each form is a separate instantiation so that the map is inlined.
struct QuadraticMap {  // s z^2 + c
    Quaternion c;
    double s;
    Quaternion operator()(const Quaternion& z) const { return quadraticStep(z, s, c); }
    double gainSquared(double r2) const { return 4 * s * s * r2; }
};
struct PowerMap {  // s z^d + c
    Quaternion c;
    double s;
    int d;
    Quaternion operator()(const Quaternion& z) const { return power(z, d) * s + c; }
    double gainSquared(double r2) const {
        double g = s * s * d * d;
        for (int k = 1; k < d; ++k)
            g *= r2;
        return g;
    }
};
struct GeneralMap {  // any eq. 2.10 polynomial, with the bound P'(|z|) on the derivative
    const Polynomial* p;
    Quaternion operator()(const Quaternion& z) const { return p->evaluate(z); }
    double gainSquared(double r2) const {
        double g = p->derivativeNormBound(std::sqrt(r2));
        return g * g;
    }
};

template <typename Map>
bool containsWith(const Map& map, const IterationLimits& limits, const Quaternion& z0) {
    Quaternion z = z0;
    if (normSquared(z) > limits.bailoutSquared) return false;
    for (int n = 1; n < limits.maxIterations; ++n) {
        z = map(z);
        if (normSquared(z) > limits.bailoutSquared) return false;
    }
    return true;
}

// Calls f with the map of the polynomial's form.
template <typename F>
auto withMap(const std::optional<PowerForm>& power, const Polynomial& polynomial, F f) {
    if (power && power->degree == 2) return f(QuadraticMap{power->constant, power->scale});
    if (power) return f(PowerMap{power->constant, power->scale, power->degree});
    return f(GeneralMap{&polynomial});
}

}  // namespace

double smoothEscapeCount(int n, double radiusSquared, int degree) {
    double d = std::max(2, degree);
    return n + 1 - std::log(std::max(1e-12, 0.5 * std::log(radiusSquared))) / std::log(d);
}

QuaternionJuliaSet::QuaternionJuliaSet(Polynomial polynomial, int maxIterations, double bailout,
                                       std::shared_ptr<const FormulaProgram> program)
    : polynomial_(std::move(polynomial)),
      program_(program ? std::move(program)
                       : std::make_shared<const FormulaProgram>(
                             FormulaProgram::fromPolynomial(polynomial_))),
      power_(polynomial_.powerForm()),
      maxIterations_(maxIterations),
      escapeRadius_(polynomial_.escapeRadius()),
      degree_(polynomial_.degree()),
      intervalExtension_(!withoutIntervalExtension(*program_)) {
    if (bailout != 0 && !(bailout > 1)) {
        throw UserError("fractal.bailout",
                        "fractal.bailout must be 0 (automatic) or greater than 1, got " +
                            std::to_string(bailout));
    }
    bailout_ = bailout == 0 ? escapeRadius_ : bailout;
    estimateRadiusSquared_ = continuationRadiusSquared<double>(degree_);
}

Quaternion QuaternionJuliaSet::derivative(const Quaternion& z, const Quaternion& h) const {
    if (power_ && power_->degree == 2) return quadraticDerivative(z, h, power_->scale);
    return polynomial_.derivative(z, h);
}

DistanceEstimate QuaternionJuliaSet::estimate(const Quaternion& z0) const {
    IterationLimits limits{maxIterations_, bailout_ * bailout_, escapeRadius_ * escapeRadius_,
                           degree_, estimateRadiusSquared_};
    return withMap(power_, polynomial_,
                   [&](const auto& map) { return estimateWith(map, limits, z0); });
}

bool QuaternionJuliaSet::contains(const Quaternion& z0) const {
    IterationLimits limits{maxIterations_, bailout_ * bailout_, escapeRadius_ * escapeRadius_,
                           degree_, estimateRadiusSquared_};
    return withMap(power_, polynomial_,
                   [&](const auto& map) { return containsWith(map, limits, z0); });
}

double QuaternionJuliaSet::logRadiusAfter(const Quaternion& z0, int iterations) const {
    return withMap(power_, polynomial_, [&](const auto& map) {
        Quaternion z = z0;
        for (int n = 0; n < iterations; ++n)
            z = map(z);
        return 0.5 * std::log(normSquared(z));
    });
}

int QuaternionJuliaSet::gradientIterations(const Quaternion& z0) const {
    DistanceEstimate e = estimate(z0);
    return e.inside ? maxIterations_ - 1 : e.iterations;
}

std::array<double, 3> QuaternionJuliaSet::potentialGradient(
    const Quaternion& z0, const std::array<Quaternion, 3>& tangents) const {
    // The same iterations as estimate(), carrying the three tangents through the Jacobian of p
    // at each iterate: the chain rule for d z_M / d x_a.
    const int iterations = gradientIterations(z0);
    Quaternion z = z0;
    std::array<Quaternion, 3> t = tangents;
    withMap(power_, polynomial_, [&](const auto& map) {
        for (int n = 0; n < iterations; ++n) {
            for (auto& tangent : t)
                tangent = derivative(z, tangent);
            z = map(z);
            // Only the direction matters: rescale together before the tangents overflow.
            double largest = std::max({normSquared(t[0]), normSquared(t[1]), normSquared(t[2])});
            if (largest > 1e200) {
                for (auto& tangent : t)
                    tangent *= 1e-100;
            }
        }
        return 0;
    });
    return {dot(z, t[0]), dot(z, t[1]), dot(z, t[2])};
}

}  // namespace quaternia
