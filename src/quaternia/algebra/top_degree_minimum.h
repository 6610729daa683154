// The certified minimum m = min |P_d(u)| over the unit sphere |u| = 1 of a quaternion
// polynomial's top-degree part P_d: the escape radius (Polynomial::escapeRadius) is only as
// sound as this bound, so it is never overestimated.
#pragma once

#include <vector>

#include "quaternia/algebra/polynomial.h"

namespace quaternia {

// m for the terms of `terms` of degree `degree` (the others are ignored), by branch and bound
// over S^3 when there are several such terms (they can cancel); exact for one. The last
// results are remembered, keyed by the coefficients exactly.
double certifiedTopDegreeMinimum(const std::vector<Term>& terms, int degree);

}  // namespace quaternia
