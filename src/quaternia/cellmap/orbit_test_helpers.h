// The orbit check the tests of certified sets share (certify_set_test.cpp,
// render/true_set_certificate_test.cpp): a point's orbit in its algebra, in double, against
// the proven escape radius.
#pragma once

#include "quaternia/algebra/hypercomplex_formula.h"

namespace quaternia::testing {

// Whether the orbit of z stays within `radius` (an escape radius: an orbit that leaves it tends
// to infinity) for `iterations` iterates. Brent's cycle detection: an orbit that repeats a value
// exactly (as attracted orbits do in floating point) revisits only values already seen, so it
// stays for every iterate.
inline bool staysBounded(const HypercomplexFormula& formula, Hypercomplex z, double radius,
                         int iterations) {
    Hypercomplex saved = z;
    int power = 1, length = 0;
    for (int n = 0; n < iterations; ++n) {
        double norm = 0;
        for (int k = 0; k < kMaxAlgebraDimension; ++k)
            norm += z[k] * z[k];
        if (norm > radius * radius) return false;
        z = formula.evaluate(z);
        if (z == saved) return true;
        if (++length == power) saved = z, power *= 2, length = 0;
    }
    return true;
}

}  // namespace quaternia::testing
