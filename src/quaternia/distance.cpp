#include "distance.h"

#include <algorithm>
#include <cmath>

#include "util/error.h"

namespace quaternia {
namespace {

// The estimate is evaluated once |z| passes this radius (or the continuation budget runs out):
// its relative error falls like 1 / ln|z| (Hart et al.), and 1e4 keeps z^d far from overflow.
constexpr double kEstimateRadiusSquared = 1e8;
constexpr int kMaxContinuation = 64;

Quaternion power(const Quaternion& z, int degree) {
    Quaternion result = z;
    for (int k = 1; k < degree; ++k)
        result = result * z;
    return result;
}

}  // namespace

JuliaSet::JuliaSet(Polynomial polynomial, int maxIterations, double bailout)
    : polynomial_(std::move(polynomial)),
      power_(polynomial_.powerForm()),
      maxIterations_(maxIterations),
      escapeRadius_(polynomial_.escapeRadius()),
      degree_(polynomial_.degree()) {
    if (bailout != 0 && !(bailout > 1)) {
        throw UserError("fractal.bailout",
                        "fractal.bailout must be 0 (automatic) or greater than 1, got " +
                            std::to_string(bailout));
    }
    bailout_ = bailout == 0 ? escapeRadius_ : bailout;
}

Quaternion JuliaSet::step(const Quaternion& z) const {
    if (power_) {
        Quaternion zd = power_->degree == 2 ? square(z) : power(z, power_->degree);
        return zd * power_->scale + power_->constant;
    }
    return polynomial_.evaluate(z);
}

double JuliaSet::derivativeGain(double r) const {
    if (power_) {
        // s d r^(d-1), without pow() in the common quadratic case.
        double gain = std::abs(power_->scale) * power_->degree;
        return power_->degree == 2 ? gain * r : gain * std::pow(r, power_->degree - 1);
    }
    return polynomial_.derivativeNormBound(r);
}

Quaternion JuliaSet::derivative(const Quaternion& z, const Quaternion& h) const {
    if (power_ && power_->degree == 2) return (z * h + h * z) * power_->scale;
    return polynomial_.derivative(z, h);
}

bool JuliaSet::continues(double normSquared, int extra, bool certain) const {
    return certain && normSquared < kEstimateRadiusSquared && extra < kMaxContinuation;
}

DistanceEstimate JuliaSet::estimate(const Quaternion& z0) const {
    DistanceEstimate result;
    const double bailoutSquared = bailout_ * bailout_;
    Quaternion z = z0;
    double derivativeNorm = 1;
    double r2 = normSquared(z);
    double trap2 = r2;
    int n = 0;  // z = z_n; the iterates z_0 .. z_{N-1} are tested
    while (r2 <= bailoutSquared) {
        if (n + 1 >= maxIterations_) {
            result.inside = true;
            result.trap = std::sqrt(trap2);
            result.escapeIteration = result.iterations = maxIterations_;
            result.smoothIteration = maxIterations_;
            return result;
        }
        derivativeNorm *= derivativeGain(std::sqrt(r2));
        z = step(z);
        r2 = normSquared(z);
        trap2 = std::min(trap2, r2);
        ++n;
    }
    result.trap = std::sqrt(trap2);
    result.escapeIteration = n;
    // Escape beyond the certified radius is final, so iterating on cannot change membership.
    bool certain = r2 > escapeRadius_ * escapeRadius_;
    int extra = 0;
    for (; continues(r2, extra, certain); ++extra) {
        derivativeNorm *= derivativeGain(std::sqrt(r2));
        z = step(z);
        r2 = normSquared(z);
    }
    double r = std::sqrt(r2);
    result.iterations = n + extra;
    result.distance = std::max(0.0, 0.5 * r * std::log(r) / derivativeNorm);
    // Continuous escape count (renormalised iteration count) for colouring.
    double d = std::max(2, degree_);
    result.smoothIteration = n + extra + 1 - std::log(std::max(1e-12, std::log(r))) / std::log(d);
    return result;
}

bool JuliaSet::contains(const Quaternion& z0) const {
    const double bailoutSquared = bailout_ * bailout_;
    Quaternion z = z0;
    if (normSquared(z) > bailoutSquared) return false;
    for (int n = 1; n < maxIterations_; ++n) {
        z = step(z);
        if (normSquared(z) > bailoutSquared) return false;
    }
    return true;
}

double JuliaSet::logRadiusAfter(const Quaternion& z0, int iterations) const {
    Quaternion z = z0;
    for (int n = 0; n < iterations; ++n)
        z = step(z);
    return 0.5 * std::log(normSquared(z));
}

int JuliaSet::gradientIterations(const Quaternion& z0) const {
    DistanceEstimate e = estimate(z0);
    return e.inside ? maxIterations_ - 1 : e.iterations;
}

std::array<double, 3> JuliaSet::potentialGradient(const Quaternion& z0,
                                                  const std::array<Quaternion, 3>& tangents) const {
    const double bailoutSquared = bailout_ * bailout_;
    Quaternion z = z0;
    std::array<Quaternion, 3> t = tangents;
    auto advance = [&] {
        for (auto& tangent : t)
            tangent = derivative(z, tangent);
        z = step(z);
        // Only the direction matters: rescale together before the tangents overflow.
        double largest = std::max({normSquared(t[0]), normSquared(t[1]), normSquared(t[2])});
        if (largest > 1e200) {
            for (auto& tangent : t)
                tangent *= 1e-100;
        }
        return normSquared(z);
    };
    // The same iterations as estimate(): up to the escape, then the certain continuation.
    double r2 = normSquared(z);
    for (int n = 0; r2 <= bailoutSquared && n + 1 < maxIterations_; ++n)
        r2 = advance();
    if (r2 > bailoutSquared) {
        bool certain = r2 > escapeRadius_ * escapeRadius_;
        for (int extra = 0; continues(r2, extra, certain); ++extra)
            r2 = advance();
    }
    return {dot(z, t[0]), dot(z, t[1]), dot(z, t[2])};
}

}  // namespace quaternia
