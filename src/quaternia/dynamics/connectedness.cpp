#include "quaternia/dynamics/connectedness.h"

#include <cmath>

namespace quaternia {

std::vector<std::pair<std::complex<double>, int>> criticalPoints(const ComplexPolynomial& p) {
    std::vector<std::pair<Complex, int>> points;
    ComplexPolynomial derivative = p.derivativePolynomial();
    // z^d + c (one top term over a constant) has the single critical point 0 of multiplicity
    // d - 1: answer it exactly instead of from a cluster of d - 1 approximate roots.
    bool monomialDerivative = true;
    for (int k = 0; k < derivative.degree(); ++k)
        monomialDerivative = monomialDerivative && derivative.coefficients()[k] == Complex(0);
    if (monomialDerivative) {
        if (derivative.degree() >= 1) points.push_back({0, derivative.degree()});
        return points;
    }
    for (Complex root : polynomialRoots(derivative)) {
        bool merged = false;
        for (auto& [point, multiplicity] : points) {
            if (std::abs(point - root) <= 1e-6 * std::max(1.0, std::abs(root))) {
                point = (point * double(multiplicity) + root) / double(multiplicity + 1);
                ++multiplicity;
                merged = true;
                break;
            }
        }
        if (!merged) points.push_back({root, 1});
    }
    return points;
}

Connectedness connectedness(const ComplexPolynomial& p, int maxIterations) {
    Polynomial map = quaternionPolynomial(p);
    OrbitOptions options;
    options.maxIterations = maxIterations;
    Connectedness result;
    int escaped = 0;
    for (auto [point, multiplicity] : criticalPoints(p)) {
        CriticalOrbit critical{
            point, multiplicity,
            analyzeOrbit(map, Quaternion(point.real(), point.imag(), 0, 0), options)};
        if (critical.orbit.fate == OrbitFate::Escapes) ++escaped;
        if (critical.orbit.fate == OrbitFate::Undecided) result.certain = false;
        result.criticalOrbits.push_back(std::move(critical));
    }
    result.connected = escaped == 0;
    if (escaped > 0) result.certain = true;  // one escape decides: disconnected
    result.cantor = !result.criticalOrbits.empty() && escaped == int(result.criticalOrbits.size());
    return result;
}

}  // namespace quaternia
