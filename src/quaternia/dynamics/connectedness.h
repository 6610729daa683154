// Connected filled Julia set or Cantor set, decided by the critical orbits (docs/facts.md,
// Mandelbrot set; seed paper section 2.2.1): K_p of a complex polynomial is connected iff every
// critical point (root of p') has a bounded orbit; if any escapes, K_p is disconnected, and if
// all escape it is a Cantor set. For z^2 + c the one critical point is 0, so K_c is connected
// iff c is in the Mandelbrot set.
#pragma once

#include <complex>
#include <vector>

#include "quaternia/algebra/complex_polynomial.h"
#include "quaternia/dynamics/orbit.h"

namespace quaternia {

struct CriticalOrbit {
    std::complex<double> point;
    int multiplicity = 1;  // as a root of p'
    OrbitResult orbit;
};

struct Connectedness {
    bool connected = true;  // no critical orbit escaped
    bool cantor = false;    // every critical orbit escaped
    // Of `connected`: an escape is certain (so is "disconnected"); boundedness is certain when
    // every critical orbit reached or converged to a cycle, and only "bounded for
    // maxIterations" when some stayed undecided. `cantor` is claimed only when all escaped.
    bool certain = true;
    std::vector<CriticalOrbit> criticalOrbits;
};

// Throws UserError for a degree below 2 (no escape radius).
Connectedness connectedness(const ComplexPolynomial& p, int maxIterations);

// The distinct critical points of p (roots of p', merged within 1e-6 of each other, as
// Aberth-Ehrlich returns a multiple root as a cluster), each with its multiplicity.
std::vector<std::pair<std::complex<double>, int>> criticalPoints(const ComplexPolynomial& p);

}  // namespace quaternia
