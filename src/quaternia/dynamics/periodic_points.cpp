#include "quaternia/dynamics/periodic_points.h"

#include <algorithm>
#include <cmath>

#include "quaternia/dynamics/orbit.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

int moebius(int n) {
    int result = 1;
    for (int p = 2; p * p <= n; ++p) {
        if (n % p != 0) continue;
        n /= p;
        if (n % p == 0) return 0;
        result = -result;
    }
    return n > 1 ? -result : result;
}

// A point z_k of the orbit counts as huge once |z_k| passes this: f^k(z) - z and (f^k)' then
// overflow within a few steps, and g_k'/g_k is d^(k - j) (f^j)'/f^j to relative 1/|z_j|.
constexpr double kHuge = 1e100;

// f/f' of h_n: 1 / sum over k | n of mu(n/k) g_k'(z) / g_k(z), with g_k(z) = f^k(z) - z,
// computed by iterating f (docs/facts.md, Periodic points; no coefficients of h_n needed).
Complex newtonRatio(const ComplexPolynomial& f, const std::vector<int>& mu, Complex z) {
    const int n = int(mu.size()) - 1;
    Complex w = z, dw = 1, logDerivative = 0, sum = 0;
    bool huge = false;
    for (int k = 1; k <= n; ++k) {
        if (!huge) {
            dw *= f.derivative(w);
            w = f.evaluate(w);
            if (std::abs(w) > kHuge) {
                huge = true;
                logDerivative = dw / w;
            }
        } else {
            logDerivative *= double(f.degree());
        }
        if (mu[k] != 0) sum += double(mu[k]) * (huge ? logDerivative : (dw - 1.0) / (w - z));
    }
    return 1.0 / sum;
}

Complex iterate(const ComplexPolynomial& f, Complex z, int n) {
    for (int k = 0; k < n; ++k)
        z = f.evaluate(z);
    return z;
}

// Follows each unassigned root through f, matching every image to the nearest unassigned root.
std::vector<PeriodicCycle> groupIntoCycles(const ComplexPolynomial& f,
                                           const std::vector<Complex>& roots, int n,
                                           double matchTolerance) {
    std::vector<bool> used(roots.size(), false);
    std::vector<PeriodicCycle> cycles;
    for (std::size_t first = 0; first < roots.size(); ++first) {
        if (used[first]) continue;
        used[first] = true;
        PeriodicCycle cycle;
        cycle.points.push_back(roots[first]);
        for (int k = 1; k < n; ++k) {
            Complex image = f.evaluate(cycle.points.back());
            std::size_t best = roots.size();
            for (std::size_t j = 0; j < roots.size(); ++j) {
                if (!used[j] && (best == roots.size() ||
                                 std::abs(roots[j] - image) < std::abs(roots[best] - image))) {
                    best = j;
                }
            }
            if (best < roots.size() && std::abs(roots[best] - image) <= matchTolerance) {
                used[best] = true;
                cycle.points.push_back(roots[best]);
            } else {
                cycle.complete = false;
                cycle.points.push_back(image);
            }
        }
        cycles.push_back(std::move(cycle));
    }
    return cycles;
}

// Points of period n coincide only at a parabolic bifurcation: when they collapse onto a cycle
// of period d, its multiplier is an (n/d)-th root of unity; when two cycles of period n merge,
// their multiplier is 1. There the roots are multiple, and only accurate to about the cube root
// of rounding (g_n = f^n(z) - z has a triple root at the collapse of a 2-cycle), so coincidence
// is judged with this looser tolerance, and only where the multiplier says it can happen.
constexpr double kParabolicMatch = 1e-4, kRootOfUnity = 1e-3;

Complex multiplierOf(const ComplexPolynomial& f, const std::vector<Complex>& points, int count) {
    Complex multiplier = 1;
    for (int k = 0; k < count; ++k)
        multiplier *= f.derivative(points[k]);
    return multiplier;
}

void measure(const ComplexPolynomial& f, PeriodicCycle& cycle) {
    const int n = int(cycle.points.size());
    cycle.multiplier = multiplierOf(f, cycle.points, n);
    cycle.residual = 0;
    for (Complex z : cycle.points)
        cycle.residual = std::max(cycle.residual, std::abs(iterate(f, z, n) - z));
    cycle.classification = classifyMultiplier(cycle.multiplier);
}

// A cycle of period n collapsed onto one of period d: the cluster of roots around each point
// of the d-cycle is replaced by its centroid (accurate where the single roots are not), then
// polished by Newton on f^d(z) = z, a simple root unless the d-cycle's multiplier is 1.
void collapse(const ComplexPolynomial& f, PeriodicCycle& cycle, int d) {
    const int n = int(cycle.points.size());
    Complex w = 0;
    for (int k = 0; k < n; k += d)
        w += cycle.points[k];
    w /= double(n / d);
    for (int step = 0; step < 8; ++step) {
        Complex z = w, dz = 1;
        for (int k = 0; k < d; ++k) {
            dz *= f.derivative(z);
            z = f.evaluate(z);
        }
        if (std::abs(dz - 1.0) <= kRootOfUnity) break;
        w -= (z - w) / (dz - 1.0);
    }
    for (int k = 0; k < n; ++k)
        cycle.points[k] = k % d == 0 ? w : f.evaluate(cycle.points[k - 1]);
}

void describe(const ComplexPolynomial& f, PeriodicCycle& cycle, int n, double scale) {
    auto least = std::min_element(cycle.points.begin(), cycle.points.end(),
                                  [](Complex a, Complex b) { return std::abs(a) < std::abs(b); });
    std::rotate(cycle.points.begin(), least, cycle.points.end());
    cycle.period = n;
    for (int d = 1; d < n; ++d) {
        if (n % d != 0 || std::abs(cycle.points[d] - cycle.points[0]) > kParabolicMatch * scale) {
            continue;
        }
        if (std::abs(std::pow(multiplierOf(f, cycle.points, d), n / d) - 1.0) <= kRootOfUnity) {
            cycle.period = d;
            cycle.degenerate = true;
            collapse(f, cycle, d);
            break;
        }
    }
    measure(f, cycle);
}

// Merges a repeated cycle (a multiple root of h_n) into `into`: each point becomes the centroid
// of the cluster, which is accurate where the single roots are only to sqrt(rounding).
void merge(const ComplexPolynomial& f, PeriodicCycle& into, const PeriodicCycle& other) {
    for (Complex& z : into.points) {
        Complex nearest = *std::min_element(
            other.points.begin(), other.points.end(),
            [&](Complex a, Complex b) { return std::abs(a - z) < std::abs(b - z); });
        z = (z * double(into.multiplicity) + nearest) / double(into.multiplicity + 1);
    }
    ++into.multiplicity;
    measure(f, into);
}

bool sameCycle(const PeriodicCycle& a, const PeriodicCycle& b, double matchTolerance,
               double scale) {
    if (std::abs(a.multiplier - 1.0) <= kRootOfUnity &&
        std::abs(b.multiplier - 1.0) <= kRootOfUnity) {
        matchTolerance = kParabolicMatch * scale;
    }
    return std::all_of(a.points.begin(), a.points.end(), [&](Complex z) {
        return std::any_of(b.points.begin(), b.points.end(),
                           [&](Complex w) { return std::abs(z - w) <= matchTolerance; });
    });
}

}  // namespace

int64_t periodicPointCount(int degree, int period) {
    int64_t count = 0, power = 1;
    for (int k = 1; k <= period; ++k) {
        power *= degree;
        if (period % k == 0) count += moebius(period / k) * power;
    }
    return count;
}

PeriodicPoints periodicPoints(const ComplexPolynomial& f, int period) {
    const int d = f.degree();
    if (d < 2) throw UserError("period", "periodic points need a polynomial of degree 2 or more");
    if (period < 1 || period * std::log(double(d)) > std::log(double(kMaxPeriodicPoints)) + 1e-9) {
        throw UserError("period", "period " + std::to_string(period) +
                                      " out of range: need 1 <= n "
                                      "and degree^n <= " +
                                      std::to_string(kMaxPeriodicPoints));
    }
    PeriodicPoints result;
    result.period = period;
    result.count = periodicPointCount(d, period);
    std::vector<int> mu(period + 1, 0);
    for (int k = 1; k <= period; ++k) {
        if (period % k == 0) mu[k] = moebius(period / k);
    }
    // Periodic points lie in K_f, inside the escape radius: start the roots on that circle.
    double radius = quaternionPolynomial(f).escapeRadius();
    std::vector<Complex> roots = aberthRoots(
        int(result.count), [&](Complex z) { return newtonRatio(f, mu, z); }, radius);
    // Simple roots are accurate to rounding: the image of a root matches the nearest root, and
    // within 1e-6 of the scale two roots are the same (see kParabolicMatch for multiple roots).
    const double scale = std::max(1.0, radius), matchTolerance = 1e-6 * scale;
    for (PeriodicCycle& cycle :
         groupIntoCycles(f, roots, period, std::max(matchTolerance, kParabolicMatch * scale))) {
        describe(f, cycle, period, scale);
        auto same = std::find_if(result.cycles.begin(), result.cycles.end(), [&](const auto& c) {
            return sameCycle(c, cycle, matchTolerance, scale);
        });
        if (same != result.cycles.end()) {
            merge(f, *same, cycle);
        } else {
            result.cycles.push_back(std::move(cycle));
        }
    }
    std::sort(result.cycles.begin(), result.cycles.end(), [](const auto& a, const auto& b) {
        Complex x = a.points[0], y = b.points[0];
        return x.real() != y.real() ? x.real() > y.real() : x.imag() > y.imag();
    });
    return result;
}

}  // namespace quaternia
