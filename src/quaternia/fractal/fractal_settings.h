// What a fractal is, as plain values: the formula, its algebra and constant, the iteration's
// limits, and the slice through which 3D space sees it. The scene file fills these
// (scene/scene.h holds them among the rest of a scene), and Fractal::fromSettings builds the
// set from them, so the mathematics does not depend on the file format.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "quaternia/algebra/hypercomplex.h"
#include "quaternia/algebra/quaternion.h"

namespace quaternia {

struct FractalSettings {
    std::string formula;  // eq. 2.10 polynomial in z; the name c stands for `c` below
    // The algebra z, c and the formula's constants live in (algebra/hypercomplex.h).
    Algebra algebra = Algebra::kQuaternion;
    Quaternion c;  // (1, i, j, k): components 0 .. 3 of c
    // Components 4 .. 7 of c for the 8-component algebras (biquaternion, octonion); zero else.
    std::array<double, 4> cUpper{};
    // How many components fractal.c was given (4 or 8): validateScene checks it against the
    // algebra's dimension, whichever of the two keys came first.
    int cComponents = 4;
    int maxIterations = 0;
    double bailout = 0;  // |z| > bailout escapes; 0 = the polynomial's own escape radius
};

// 4D -> 3D (slice.h): a 3D point p is drawn iff left * s(p) * right is in the set, where s(p) is
// POV-Ray's slice embedding for hyperplane normal . q = distance, and the six plane angles are a
// friendlier way to compose extra rotations into left and right.
struct SliceSettings {
    Quaternion normal;  // (x, y, z, w) components of the 4D hyperplane normal
    double distance = 0;
    Quaternion left, right;                 // unit quaternions
    std::array<double, 6> anglesDegrees{};  // planes 1i, 1j, 1k, ij, ik, jk
    // The slice of the 8-component algebras: the 3D point (x, y, z) stands for
    // origin + x axes[0] + y axes[1] + z axes[2], the axes orthonormalised in that order
    // (Gram-Schmidt). Empty when not given: the 8-component algebras then take origin 0 and
    // axes e0, e1, e2 (the quaternion default slice, normal k and distance 0). `axes` holds the
    // three vectors one after the other (3 x 8 numbers).
    std::vector<double> origin;
    std::vector<double> axes;
};

}  // namespace quaternia
