#include "connectedness.h"

#include <algorithm>
#include <stdexcept>

namespace quaternia {

double complexEscapeRadius(const ComplexPolynomial& p) {
    const auto& a = p.coefficients();
    double lower = 0;
    for (int k = 0; k < p.degree(); ++k)
        lower += std::abs(a[k]);
    return std::max(1.0, (2 + lower) / std::abs(a.back()));
}

Connectedness classifyConnectedness(const ComplexPolynomial& p, int maxIterations) {
    if (p.degree() < 2)
        throw std::invalid_argument("classifyConnectedness: degree " + std::to_string(p.degree()) +
                                    " has no critical point");
    const double escapeSquared = complexEscapeRadius(p) * complexEscapeRadius(p);
    int bounded = 0, escaped = 0;
    for (Complex z : polynomialRoots(p.derivativePolynomial())) {
        int n = 0;
        while (n < maxIterations && std::norm(z) <= escapeSquared) {
            z = p.evaluate(z);
            ++n;
        }
        ++(std::norm(z) <= escapeSquared ? bounded : escaped);
    }
    if (escaped == 0) return Connectedness::Connected;
    return bounded == 0 ? Connectedness::CantorSet : Connectedness::Disconnected;
}

const char* describe(Connectedness connectedness) {
    switch (connectedness) {
        case Connectedness::Connected:
            return "connected";
        case Connectedness::Disconnected:
            return "disconnected";
        case Connectedness::CantorSet:
            return "a Cantor set";
    }
    return "?";
}

}  // namespace quaternia
