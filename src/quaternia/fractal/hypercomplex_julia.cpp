#include "quaternia/fractal/hypercomplex_julia.h"

#include "quaternia/algebra/orbit_batch.h"

#include "quaternia/interval/interval_element.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>

#include "quaternia/fractal/escape_time.h"
#include "quaternia/fractal/slice.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

using Complex = std::complex<double>;

// The positive root R of m r^d - sum_{k<d} b_k r^k - r: for |z| > R, |p(z)| > |z| and the orbit
// tends to infinity (as Polynomial::escapeRadius; b[1] already holds the "+ r").
double escapeRadiusFrom(double m, const std::vector<double>& b, int d, const std::string& what) {
    auto f = [&](double r) {
        double value = m;
        for (int k = d - 1; k >= 0; --k)
            value = value * r - b[size_t(k)];
        return value;
    };
    double lo = 0, hi = 1;
    while (f(hi) < 0) {
        lo = hi;
        hi *= 2;
        if (!std::isfinite(hi))
            throw UserError("fractal.formula",
                            "fractal.formula: " + what + ": no finite escape radius");
    }
    for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
        const double mid = (lo + hi) / 2;
        (f(mid) < 0 ? lo : hi) = mid;
    }
    return hi;
}

Complex horner(const std::vector<Complex>& c, const Complex& w) {
    Complex value = 0;
    for (size_t k = c.size(); k-- > 0;)
        value = value * w + c[k];
    return value;
}
Complex hornerDerivative(const std::vector<Complex>& c, const Complex& w) {
    Complex value = 0;
    for (size_t k = c.size(); k-- > 1;)
        value = value * w + double(k) * c[k];
    return value;
}

}  // namespace

// ---- The set ----------------------------------------------------------------------------------

HypercomplexJuliaSet::HypercomplexJuliaSet(HypercomplexFormula formula, int maxIterations,
                                           double bailout)
    : formula_(std::move(formula)),
      rules_(&algebraRules(formula_.algebra())),
      maxIterations_(maxIterations),
      intervalExtension_(!withoutIntervalExtension(formula_.program())),
      batchesOrbits_(rules_->escape != EscapeRule::kDuplexComponents &&
                     batchesOrbits(formula_.program())) {
    const std::string algebra(algebraName(formula_.algebra()));
    const int d = formula_.degree();
    if (d < 2 && !formula_.transcendental()) {
        throw UserError("fractal.formula", "fractal.formula has degree " + std::to_string(d) +
                                               ", below 2; its orbits need not escape");
    }
    if (bailout != 0 && !(bailout > 1)) {
        throw UserError("fractal.bailout",
                        "fractal.bailout must be 0 (automatic) or greater than 1, got " +
                            std::to_string(bailout));
    }
    const std::vector<double>& bound = formula_.normBound();
    if (formula_.transcendental()) {
        // Bicomplex functions (only they take them): no estimate and no Lipschitz bound on a
        // ball (poles, branch points): Algorithm 2's fixed steps alone, POV-Ray's bailout 4.
        kind_ = DistanceKind::kLipschitz;
        bailout_ = escapeRadius_ = bailout == 0 ? rules_->defaultBailout : bailout;
        if (DuplexComponentProgram::supports(formula_.program())) {
            const FormulaProgram& program = formula_.program();
            duplexPrograms_.emplace(std::array<DuplexComponentProgram, 2>{
                DuplexComponentProgram(program, 0), DuplexComponentProgram(program, 1)});
        }
        return;
    }
    kind_ = rules_->distance;
    switch (rules_->escape) {
        case EscapeRule::kMultiplicativeNorm: {
            // |top-degree part| = the product of its coefficients' norms when it is one term
            // (the norm is multiplicative); sums of top-degree terms may cancel.
            const double m = formula_.topDegreeMinimum();
            if (!(m > 0)) {
                if (bailout == 0)
                    throw UserError("fractal.bailout",
                                    "fractal.bailout: give a bailout above 1: the " + algebra +
                                        " escape radius is derived only for formulas whose "
                                        "highest degree is a single term");
                escapeRadius_ = bailout;
            } else {
                std::vector<double> b(bound.begin(), bound.begin() + d);
                b[0] = euclideanNorm(formula_.evaluate(Hypercomplex{}));
                b[1] += 1;
                escapeRadius_ = escapeRadiusFrom(m, b, d, algebra + " formula");
            }
            bailout_ = bailout == 0 ? escapeRadius_ : bailout;
            break;
        }
        case EscapeRule::kDuplexComponents: {
            bailout_ = bailout == 0 ? rules_->defaultBailout : bailout;
            // The two complex polynomials of the duplex form, from d + 1 values on a circle
            // (the discrete Fourier transform of p(r w^k) gives the coefficients times r^j).
            const int samples = d + 1;
            const double r = 1.0;
            for (auto& c : componentCoefficients_)
                c.assign(size_t(samples), Complex(0));
            const double pi = std::acos(-1.0);
            for (int k = 0; k < samples; ++k) {
                const Complex w = std::polar(r, 2 * pi * k / samples);
                const auto value = duplexForm(formula_.evaluate(fromDuplexForm(w, w)));
                for (int j = 0; j < samples; ++j) {
                    const Complex turn = std::polar(1.0, -2 * pi * j * k / samples);
                    for (int i = 0; i < 2; ++i)
                        componentCoefficients_[i][size_t(j)] += value[size_t(i)] * turn;
                }
            }
            for (int i = 0; i < 2; ++i) {
                for (auto& c : componentCoefficients_[i])
                    c /= double(samples);
                const double m = std::abs(componentCoefficients_[i][size_t(d)]) * (1 - 1e-9);
                if (!(m > 1e-12)) {
                    throw UserError("fractal.formula",
                                    "fractal.formula: the bicomplex formula's top degree cancels "
                                    "in one duplex component; its orbits need not escape");
                }
                std::vector<double> b(size_t(d), 0.0);
                for (int k = 0; k < d; ++k)
                    b[size_t(k)] =
                        std::abs(componentCoefficients_[i][size_t(k)]) * (1 + 1e-9) + 1e-12;
                b[1] += 1;
                componentEscapeRadius_[i] = escapeRadiusFrom(m, b, d, "bicomplex formula");
                // K_N gives a component at most sqrt(2) bailout: |q|^2 = (|a|^2 + |b|^2) / 2.
                components_[size_t(i)] =
                    DuplexComponent(componentCoefficients_[i], componentEscapeRadius_[i],
                                    std::sqrt(2.0) * bailout_);
            }
            escapeRadius_ = bailout_;
            break;
        }
        case EscapeRule::kNone:
            bailout_ = bailout == 0 ? rules_->defaultBailout : bailout;
            escapeRadius_ = bailout_;
            break;
    }
}

DistanceEstimate HypercomplexJuliaSet::estimate(const Hypercomplex& z0) const {
    if (kind_ == DistanceKind::kLipschitz) return lipschitzDistance(z0);
    switch (rules_->escape) {
        case EscapeRule::kDuplexComponents:
            return bicomplexEstimate(z0);
        case EscapeRule::kNone:
            return lipschitzDistance(z0);
        case EscapeRule::kMultiplicativeNorm:
            break;
    }
    return multiplicativeEstimate(z0);
}

uint64_t HypercomplexJuliaSet::tableBytes() const {
    return duplexPrograms_ ? DuplexEscapeMap::peakBytes(kEscapeMapLevel) : 0;
}

const DuplexEscapeMaps& HypercomplexJuliaSet::escapeMaps() const {
    std::call_once(escapeMapsBuilt_, [&] {
        escapeMaps_ = std::make_shared<const DuplexEscapeMaps>(*duplexPrograms_, maxIterations_,
                                                               bailout_, kEscapeMapLevel);
    });
    return *escapeMaps_;
}

double HypercomplexJuliaSet::clearance(const Hypercomplex& z0) const {
    return duplexPrograms_ ? escapeMaps().clearance(z0) : 0.0;
}

bool HypercomplexJuliaSet::contains(const Hypercomplex& z0) const {
    if (duplexPrograms_ && escapeMaps().outside(z0)) return false;
    return containsByOrbit(z0);
}

bool HypercomplexJuliaSet::containsByOrbit(const Hypercomplex& z0) const {
    const double bailoutSquared = bailout_ * bailout_;
    if (rules_->escape == EscapeRule::kDuplexComponents &&
        (duplexPrograms_ || !formula_.transcendental())) {
        // In duplex form (the polynomials by Horner's rule, the functions by their component
        // programs): the two components never mix.
        thread_local std::vector<Complex> registers;
        auto w = duplexForm(z0);
        for (int n = 0;; ++n) {
            // |q|^2 = (|a|^2 + |b|^2) / 2
            if (0.5 * (std::norm(w[0]) + std::norm(w[1])) > bailoutSquared) return false;
            if (n + 1 >= maxIterations_) return true;
            for (size_t i = 0; i < 2; ++i)
                w[i] = duplexPrograms_ ? (*duplexPrograms_)[i].value(w[i], registers)
                                       : horner(componentCoefficients_[i], w[i]);
        }
    }
    if (batchesOrbits_) {
        // The same loop without the one-point interpreter's registers of eight components.
        return firstInsideOfBatch(formula_.program(), formula_.table(), &z0, 1, maxIterations_,
                                  bailoutSquared) == 0;
    }
    Hypercomplex z = z0;
    for (int n = 0;; ++n) {
        if (normSquared(z) > bailoutSquared) return false;
        if (n + 1 >= maxIterations_) return true;
        z = formula_.evaluate(z);
    }
}

int HypercomplexJuliaSet::firstInside(const Hypercomplex* points, int count) const {
    if (!batchesOrbits_) return JuliaSet::firstInside(points, count);
    return firstInsideOfBatch(formula_.program(), formula_.table(), points, count, maxIterations_,
                              bailout_ * bailout_);
}

DistanceEstimate HypercomplexJuliaSet::multiplicativeEstimate(const Hypercomplex& z0) const {
    // The quaternion loop (escape_time.h), with the running derivative bound P'(|z|).
    struct Map {
        const HypercomplexFormula& formula;
        Hypercomplex operator()(const Hypercomplex& z) const { return formula.evaluate(z); }
        double gainSquared(double r2) const {
            const double gain = formula.derivativeNormBound(std::sqrt(r2));
            return gain * gain;
        }
    };
    const IterationLimits limits{maxIterations_, bailout_ * bailout_, escapeRadius_ * escapeRadius_,
                                 formula_.degree(),
                                 continuationRadiusSquared<double>(formula_.degree())};
    return estimateWith(Map{formula_}, limits, z0);
}

DistanceEstimate HypercomplexJuliaSet::bicomplexEstimate(const Hypercomplex& z0) const {
    // Membership in K_N by the norm of q, |q|^2 = (|a|^2 + |b|^2) / 2; the distance to
    // K = K_1 x K_2 from the two complex orbits (a, b), each followed with its derivative until
    // it is far outside its escape radius.
    DistanceEstimate result;
    const double bailoutSquared = bailout_ * bailout_;
    const std::array<Complex, 2> start = duplexForm(z0);
    std::array<Complex, 2> w = start, slope = {Complex(1), Complex(1)};
    auto step = [&](size_t i) {
        slope[i] *= hornerDerivative(componentCoefficients_[i], w[i]);
        w[i] = horner(componentCoefficients_[i], w[i]);
    };
    double q2 = 0.5 * (std::norm(w[0]) + std::norm(w[1])), trap2 = q2;
    int n = 0;
    while (q2 <= bailoutSquared) {
        if (n + 1 >= maxIterations_) return insideEstimate(std::sqrt(trap2), maxIterations_);
        step(0), step(1);
        q2 = 0.5 * (std::norm(w[0]) + std::norm(w[1]));
        trap2 = std::min(trap2, q2);
        ++n;
    }
    result.trap = std::sqrt(trap2);
    result.escapeIteration = n;
    result.smoothIteration = smoothEscapeCount(n, q2, formula_.degree());
    const double estimateRadiusSquared = continuationRadiusSquared<double>(formula_.degree());
    double distanceSquared = 0;  // of the duplex point to K_1 x K_2
    bool componentEscaped = false;
    int iterations = n;
    for (size_t i = 0; i < 2; ++i) {
        // A component not beyond its escape radius by iteration N counts as in K_i (distance 0);
        // one beyond it escapes for certain and is followed to where its estimate is accurate.
        const double R2 = componentEscapeRadius_[i] * componentEscapeRadius_[i];
        int k = n, extra = 0;
        while (extra < kMaxContinuation) {
            const double r2 = std::norm(w[i]);
            if (r2 > R2 ? r2 >= estimateRadiusSquared : k + 1 >= maxIterations_) break;
            step(i);
            ++k, ++extra;
        }
        iterations = std::max(iterations, k);
        const double r2 = std::norm(w[i]);
        componentEscaped = componentEscaped || r2 > R2;
        if (r2 > R2 && !components_[i].connected()) {
            // A disconnected K_i: the estimate is no bound near the escaping critical points'
            // preimages (duplex_component.h).
            const double d = components_[i].distance(start[i], maxIterations_);
            distanceSquared += d * d;
        } else if (r2 > R2) {
            const double d =
                std::max(0.0, 0.25 * std::sqrt(r2) / std::abs(slope[i]) * std::log(r2));
            distanceSquared += d * d;
        }
    }
    result.iterations = iterations;
    // |D(q)| = sqrt(2) |q|: the duplex distance over sqrt(2). Where neither component is seen
    // to escape (a bailout below their escape radii), the Lipschitz distance still holds. (A
    // disconnected component's bound can be 0 beside an escape: a point that close to K_N is
    // left to the march's membership steps, as the lanes leave it.)
    result.distance =
        componentEscaped ? std::sqrt(0.5 * distanceSquared) : lipschitzDistance(z0).distance;
    return result;
}

DistanceEstimate HypercomplexJuliaSet::lipschitzDistance(const Hypercomplex& z0) const {
    // A point w_0 within delta of z_0 has |w_k - z_k| <= e_k with e_0 = delta and
    // e_{k+1} = P'(|z_k| + e_k) e_k: the segment from z_k to w_k lies in the ball of radius
    // |z_k| + e_k, where P' bounds |Dp| (HypercomplexFormula::normBound). So w escapes (is outside
    // K_N) as soon as |z_k| - e_k > B for some k < N. The largest such delta is found from the
    // first-order gains prod P'(|z_j|), halved until the exact recursion confirms it.
    DistanceEstimate result;
    const double bailoutSquared = bailout_ * bailout_;
    std::array<double, kLipschitzOrbit> radius;  // |z_k|, written as the orbit goes
    Hypercomplex z = z0;
    double r2 = normSquared(z), trap2 = r2;
    int n = 0;
    radius[0] = std::sqrt(r2);
    while (r2 <= bailoutSquared) {
        if (n + 1 >= maxIterations_ || n + 1 >= int(kLipschitzOrbit)) {
            result.inside = n + 1 >= maxIterations_;
            result.trap = std::sqrt(trap2);
            result.escapeIteration = result.iterations = n + 1;
            result.smoothIteration = n + 1;
            return result;  // inside K_N (or an orbit too long to bound: distance 0)
        }
        z = formula_.evaluate(z);
        r2 = normSquared(z);
        trap2 = std::min(trap2, r2);
        radius[size_t(++n)] = std::sqrt(r2);
    }
    result.trap = std::sqrt(trap2);
    result.escapeIteration = n;
    result.smoothIteration = smoothEscapeCount(n, std::max(r2, 1.0 + 1e-9), formula_.degree());
    // A few more iterates (still below N) may escape by a wider margin.
    int last = n;
    for (; last + 1 < maxIterations_ && last + 1 < int(kLipschitzOrbit) && last < n + 3; ++last) {
        const Hypercomplex next = formula_.evaluate(z);
        const double next2 = normSquared(next);
        if (!(next2 < 1e200)) break;
        z = next;
        radius[size_t(last + 1)] = std::sqrt(next2);
    }
    result.iterations = last;
    if (formula_.transcendental()) return result;  // distance 0: no bound to take
    auto escapesWithin = [&](double delta) {
        double e = delta;
        for (int k = 0; k <= last; ++k) {
            if (k >= n && radius[size_t(k)] - e > bailout_) return true;
            e *= formula_.derivativeNormBound(radius[size_t(k)] + e);
            if (!std::isfinite(e)) return false;
        }
        return false;
    };
    double gain = 1, delta = 0;
    for (int k = 0; k <= last; ++k) {
        if (k >= n) delta = std::max(delta, (radius[size_t(k)] - bailout_) / gain);
        gain *= formula_.derivativeNormBound(radius[size_t(k)]);
    }
    for (int halving = 0; halving < 40 && delta > 0; ++halving, delta *= 0.5)
        if (escapesWithin(delta)) break;
    result.distance = escapesWithin(delta) ? delta : 0.0;
    return result;
}

double HypercomplexJuliaSet::logRadiusAfter(const Hypercomplex& z0, int iterations) const {
    Hypercomplex z = z0;
    for (int n = 0; n < iterations; ++n) {
        const Hypercomplex next = formula_.evaluate(z);
        if (!std::isfinite(normSquared(next))) break;
        z = next;
    }
    return 0.5 * std::log(normSquared(z));
}

int HypercomplexJuliaSet::gradientIterations(const Hypercomplex& z0) const {
    const DistanceEstimate e = estimate(z0);
    if (e.inside) return maxIterations_ - 1;
    // Octonions as the quaternions (QuaternionJuliaSet::gradientIterations): the iterate where the
    // estimate was taken, so that the quaternion paths that draw octonion real forms (the SIMD
    // lanes through the fold, octonion_fold.h) shade alike.
    if (rules_->gradientAtEstimate) return e.iterations;
    return std::min(e.escapeIteration, maxIterations_ - 1);
}

std::array<double, 3> HypercomplexJuliaSet::potentialGradient(
    const Hypercomplex& z0, const std::array<Hypercomplex, 3>& tangents) const {
    const int iterations = std::max(1, gradientIterations(z0));
    Hypercomplex z = z0;
    std::array<Hypercomplex, 3> t = tangents;
    for (int n = 0; n < iterations; ++n) {
        const auto [next, slopes] = formula_.evaluateWithDerivatives(z, t);
        t = slopes;
        if (!std::isfinite(normSquared(next))) break;
        z = next;
        const double largest = std::max({normSquared(t[0]), normSquared(t[1]), normSquared(t[2])});
        if (largest > 1e200) {
            for (auto& tangent : t)
                tangent = 1e-100 * tangent;
        }
    }
    return {dotProduct(z, t[0]), dotProduct(z, t[1]), dotProduct(z, t[2])};
}

std::shared_ptr<const HypercomplexJuliaSet> hypercomplexJuliaSetOf(const FractalSettings& fractal) {
    const Algebra algebra = fractal.algebra;
    const Quaternion& c4 = fractal.c;
    Hypercomplex c{c4.w, c4.x, c4.y, c4.z, 0, 0, 0, 0};
    if (algebraDimension(algebra) == 8)
        for (size_t n = 0; n < 4; ++n)
            c[4 + n] = fractal.cUpper[n];
    HypercomplexFormula formula = [&] {
        try {
            return HypercomplexFormula(Formula::parse(fractal.formula), algebra, c);
        } catch (const FormulaError& e) {
            throw UserError("fractal.formula", std::string("fractal.formula: ") + e.what());
        }
    }();
    return std::make_shared<const HypercomplexJuliaSet>(std::move(formula), fractal.maxIterations,
                                                        fractal.bailout);
}

}  // namespace quaternia
