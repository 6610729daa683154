// Octonion real forms folded onto the quaternions (docs/methods.md, Other algebras): for a
// formula sum a_k z^k + C with real a_k, every power of z lies in span{1, Im z}, so z_n stays in
// span{1, Im z_0, Im C} and |z_n| depends only on three numbers of z_0: its real part, the
// component of Im z_0 along u = Im C / |Im C|, and the length of the rest. The fold
//     phi(z) = Re z + <Im z, u> i + |Im z - <Im z, u> u| j
// carries each octonion orbit to the quaternion orbit of sum a_k z^k + c', c' = Re C + |Im C| i,
// with the same radii: the same K_N, escape counts and estimates (the quaternion estimate's
// derivative bound is the same P'(|z|)). phi keeps |z| and is 1-Lipschitz, so the quaternion
// estimate at phi(z) is also a lower bound of the distance to the octonion set.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "quaternia/algebra/polynomial.h"
#include "quaternia/fractal/hypercomplex_julia.h"
#include "quaternia/fractal/slice.h"

namespace quaternia {

struct OctonionFold {
    Polynomial polynomial;  // sum a_k z^k + c' in the quaternions
    // The slice's point p = (x, y, z) in folded coordinates, each an affine function of p given
    // as (value at 0, d/dx, d/dy, d/dz): rows[0] is Re, rows[1] the component along u, and
    // rows[2..] the coordinates of the part orthogonal to 1 and u in an orthonormal basis of
    // the span that part takes over the slice (0 to 4 rows): phi = (rows[0], rows[1],
    // sqrt(rows[2]^2 + ...), 0).
    std::vector<std::array<double, 4>> rows;
    // Whether the slice's origin is orthogonal to its axes (|p| <= |s(p)|: the set's bounding
    // sphere is the bailout's).
    bool originOrthogonal = false;
};

// The fold of an octonion fractal whose formula (as written in fractal.formula) is a real form;
// nothing for any other formula (or one too large to multiply out).
// `set` is the octonion set of that formula, `slice` the slice it is seen through.
std::optional<OctonionFold> foldOctonion(const std::string& formula,
                                         const HypercomplexJuliaSet& set, const Slice& slice);

}  // namespace quaternia
