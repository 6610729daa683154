// Balls of an algebra of section 2.3 in midpoint-radius arithmetic (Rump, "Fast and parallel
// interval arithmetic", BIT 39(3), 1999): a BallForm stands for every element within `radius`
// of `centre` in the Euclidean norm. A product's radius is bounded through the algebra's
// product bound kappa (|a b| <= kappa |a| |b|: 1 in the quaternions and octonions, whose norm
// is multiplicative), so a ball is turned, not widened, by a rotation: where an orbit settles
// on an attracting cycle the ball shrinks with the cycle's multiplier, while a box about the
// same point is wrapped in a wider box at every turn and, over the hundreds of iterations of
// a plane image, outgrows the bailout (Moore's wrapping effect). The proof that a point
// belongs to K_N (JuliaSet::includesBox) tries a ball first, then a box.
#pragma once

#include "quaternia/algebra/formula_program.h"
#include "quaternia/algebra/hypercomplex.h"

namespace quaternia {

struct BallForm {
    Hypercomplex centre{};
    double radius = 0;  // >= 0
};

// Whether every element of the ball belongs to K_N of p with this bailout: every iterate z_n,
// n < maxIterations, lies within the ball |z| <= bailout for every z_0 in it (the iterates the
// membership test reads). False proves nothing. The program must have an interval extension
// (interval_element.h, withoutIntervalExtension).
bool ballStaysInBall(const FormulaProgram& program, const MultiplicationTable& table,
                     const BallForm& ball, int maxIterations, double bailout);

}  // namespace quaternia
