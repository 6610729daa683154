// How each algebra of section 2.3 is drawn, in one table (docs/algebras.md): which Julia set
// computes it, what bounds a step (an escape-time estimate, or a proven Lipschitz distance with
// Algorithm 2's fixed steps), where orbits escape, the bailout taken when the scene leaves it at
// 0, which iterate the normal differentiates, and which fast paths apply (octonion real forms
// folded onto the quaternions, bicomplex polynomials as two complex iterations in the lanes,
// the quaternion half of the 8-component algebras drawn as the quaternions).
// Every choice that depends on the algebra reads this table instead of branching on the algebra.
#pragma once

#include "quaternia/algebra/hypercomplex.h"
#include "quaternia/fractal/julia_set.h"

namespace quaternia {

// Where the orbits of an algebra certainly escape.
enum class EscapeRule {
    // The norm is multiplicative (quaternions, octonions): from the top-degree part's minimum
    // m over unit points, the root of m r^d - P_{<d}(r) - r (Polynomial::escapeRadius).
    kMultiplicativeNorm,
    // Bicomplex numbers: each duplex component is a complex polynomial with its own radius
    // (hypercomplex_julia.h); the bailout of |q| is the scene's.
    kDuplexComponents,
    // Null elements (coquaternions, biquaternions): no radius is certain; the bailout decides.
    kNone,
};

struct AlgebraRules {
    Algebra algebra;
    // The quaternions' own set (QuaternionJuliaSet, from the expanded polynomial); the other
    // algebras take HypercomplexJuliaSet.
    bool quaternionSet;
    DistanceKind distance;
    // The bailout where fractal.bailout is 0: 0 for the certified escape radius, else POV-Ray's
    // (4 for its bicomplex `hypercomplex`) or 2.
    double defaultBailout;
    // The normal's M: the iterate where the estimate was taken (as the quaternions, so that the
    // quaternion paths that draw octonion real forms shade alike), or the escape iteration.
    bool gradientAtEstimate;
    // Octonion real forms drawn as quaternion sets where the slice allows (octonion_fold.h).
    bool foldsOntoQuaternions;
    // Bicomplex polynomials iterated as their two duplex components (the SIMD lanes).
    bool duplexForm;
    // Elements with components 4 .. 7 zero are a subalgebra isomorphic to H: a c and slice there
    // draw the quaternion set (fractal.cpp, quaternionHalf).
    bool quaternionHalf;
    // Where orbits escape: not written per row but derived (algebraRules) from the algebra's
    // arithmetic (hypercomplex.h: a multiplicative norm) and the duplex form, so that the two
    // tables cannot disagree.
    EscapeRule escape = EscapeRule::kNone;
};

// The row of `algebra`.
const AlgebraRules& algebraRules(Algebra algebra);

}  // namespace quaternia
