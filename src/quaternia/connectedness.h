// Whether the filled Julia set K_p of a complex polynomial is connected, from its critical
// orbits (Fatou 1919, Julia 1918; Milnor, Dynamics in One Complex Variable, Thm. 9.5): K_p is
// connected iff every critical point of p has a bounded orbit, and a Cantor set iff every one
// escapes. In between K_p is disconnected with infinitely many components, some not points.
#pragma once

#include "complex_polynomial.h"

namespace quaternia {

enum class Connectedness { Connected, Disconnected, CantorSet };

// Iterates every critical point (the roots of p', polynomialRoots of derivativePolynomial())
// until it leaves the disc of the escape radius below, or for maxIterations steps (then it counts
// as bounded, so a parameter just outside the connectedness locus may read as connected).
// Throws std::invalid_argument for degree below 2 (no critical point, nothing to decide).
Connectedness classifyConnectedness(const ComplexPolynomial& p, int maxIterations = 2000);

// R = max(1, (2 + |a_0| + ... + |a_{d-1}|) / |a_d|): for |z| > R, |p(z)| >= |z|^(d-1) (|a_d| |z|
// - sum |a_k|) > 2 |z|, so an orbit that leaves the disc of radius R escapes to infinity.
double complexEscapeRadius(const ComplexPolynomial& p);

// "connected", "disconnected" or "a Cantor set".
const char* describe(Connectedness connectedness);

}  // namespace quaternia
