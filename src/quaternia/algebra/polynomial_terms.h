// What polynomial.cpp and top_degree_minimum.cpp both do with one term a0 z a1 ... z ad of a
// quaternion polynomial (polynomial.h): its value and the product of its coefficients' norms.
#pragma once

#include <vector>

#include "quaternia/algebra/polynomial.h"

namespace quaternia::terms {

inline bool isOne(const Quaternion& q) {
    return q == Quaternion{1};
}

// q a, skipping the product for the common coefficient 1 (z^2 is the term 1 z 1 z 1).
inline Quaternion timesCoefficient(const Quaternion& q, const Quaternion& a) {
    return isOne(a) ? q : q * a;
}

// The product of the coefficient norms: |a0 z a1 ... z ad| = this * |z|^d, because the norm is
// multiplicative (docs/facts.md, Algebra).
inline double normProduct(const Term& term) {
    double product = 1;
    for (const Quaternion& a : term.coefficients)
        product *= norm(a);
    return product;
}

inline Quaternion evaluateTerm(const Term& term, const Quaternion& z) {
    const std::vector<Quaternion>& a = term.coefficients;
    Quaternion value = a[0];
    for (size_t i = 1; i < a.size(); ++i)
        value = timesCoefficient(value * z, a[i]);
    return value;
}

}  // namespace quaternia::terms
