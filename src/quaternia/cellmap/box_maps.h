// The maps that cell mapping (cell_mapping.h) iterates, on boxes by interval arithmetic
// (interval.h, outward rounding):
// - a complex polynomial on the plane, in the frame of a plane image (z = origin + e^(i theta)
//   p for grid coordinates p; theta = 0 adds the origin only);
// - a real polynomial sum a_k z^k + c of the quaternions or octonions on the reduced space
//   (x, a, r), r >= 0: z = x + a n + w with n = Im c / |Im c| and w orthogonal to n, r = |w|
//   (Bogush and Gazizov, arXiv nlin/0105060). With zeta = x + i rho, rho = |Im z| =
//   sqrt(a^2 + r^2), and p(zeta) = P + i rho Y (Y a polynomial in x and rho^2, since the
//   imaginary part of a real polynomial is odd in rho), p(z) = P + Y Im z, so
//   x' = P + Re c, a' = Y a + |Im c|, r' = |Y| r. The subalgebra that z and c generate is
//   associative for octonions too (Artin's theorem), so the same map serves both. Every slice
//   and every rotation of the 4D (8D) set is this 3D set turned about the axis 1, n.
#pragma once

#include <complex>
#include <vector>

#include "quaternia/cellmap/cell_mapping.h"

namespace quaternia {

// A radius R with |z| > R implying that the orbit of z under p tends to infinity, for p with
// coefficient moduli `moduli` (lowest degree first, the constant included) in an algebra with
// a multiplicative norm (C, H, O): the positive root of |a_d| r^d - sum_{k<d} |a_k| r^k - r,
// beyond which |p(z)| - |z| is positive and grows (Polynomial::escapeRadius). Rounded up.
// Throws UserError naming fractal.formula for a degree below 2.
double escapeRadiusOfModuli(const std::vector<double>& moduli);

// The box map of p(z) = sum_k coefficients[k] z^k (lowest degree first) in the frame
// z = origin + (cos theta + i sin theta) p, with `escapeRadius` a proven escape radius of p.
BoxMap complexPolynomialBoxMap(std::vector<std::complex<double>> coefficients,
                               std::complex<double> origin, double rotationDegrees,
                               double escapeRadius);

// The reduced map of p(z) = sum_k coefficients[k] z^k + constant (coefficients real, lowest
// degree first, coefficients[0] included in Re c by the caller), with Re c = realConstant and
// |Im c| = imaginaryConstant >= 0, on boxes of (x, a, r).
BoxMap reducedPolynomialBoxMap(std::vector<double> coefficients, double realConstant,
                               double imaginaryConstant, double escapeRadius);

// The reduced map on one point, in double (the tests' orbits and the renderer's lookups): the
// same formulas as the box map.
std::array<double, 3> reducedPolynomialStep(const std::vector<double>& coefficients,
                                            double realConstant, double imaginaryConstant,
                                            const std::array<double, 3>& xar);

}  // namespace quaternia
