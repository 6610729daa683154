// Membership in K_N for a batch of points at once, in exactly the arithmetic of
// evaluateInAlgebra (formula_program.h): the same operations on the same numbers in the same
// order, lane by lane, so that every point is decided as the one-point loop decides it, bit for
// bit. The lanes hide the interpreter's dispatch and the table's lookups, which cost more than
// the arithmetic of a 4-component product, and the compiler vectorises each operation across
// the points. Used by the fixed-step marcher (render/march.cpp) to test runs of consecutive
// samples of the algebras whose empty space is crossed by proofs (coquaternions,
// biquaternions, octonion formulas): far from the set most samples escape in a few iterations,
// and testing them costs less than proving their run.
#pragma once

#include "quaternia/algebra/formula_program.h"
#include "quaternia/algebra/hypercomplex.h"

namespace quaternia {

// Whether firstInsideOfBatch takes the program: table arithmetic (not the quaternion
// programs, which evaluateInAlgebra runs through runProgram), no functions or real powers.
bool batchesOrbits(const FormulaProgram& program);

// The index of the first of points[0 .. count) whose iterates z_0 ..
// z_{maxIterations - 1} all have normSquared at most bailoutSquared, or count if none: the
// loop z <- evaluateInAlgebra(program, table, z) of HypercomplexJuliaSet::containsByOrbit.
int firstInsideOfBatch(const FormulaProgram& program, const MultiplicationTable& table,
                       const Hypercomplex* points, int count, int maxIterations,
                       double bailoutSquared);

}  // namespace quaternia
