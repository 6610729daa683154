#include "quaternia/dynamics/connectedness.h"

#include <gtest/gtest.h>

namespace quaternia {
namespace {

ComplexPolynomial quadratic(Complex c) {
    return ComplexPolynomial({c, 0, 1});
}

// For z^2 + c, K_c is connected exactly when c is in the Mandelbrot set (docs/facts.md, Mandelbrot
// set), and a Cantor set otherwise, including the boundary points -2, 1/4, -3/4 and i.
TEST(Connectedness, QuadraticIsConnectedExactlyOnM) {
    const Complex rabbit(-0.12256116687665, 0.74486176661974);
    for (Complex c : {Complex(-2), Complex(0.25), Complex(-0.75), Complex(0, 1), Complex(0),
                      Complex(-1), rabbit}) {
        Connectedness k = connectedness(quadratic(c), 2000);
        EXPECT_TRUE(k.connected) << c;
        EXPECT_FALSE(k.cantor) << c;
    }
    for (Complex c : {Complex(0.26), Complex(1), Complex(-2.01), Complex(0, 1.1)}) {
        Connectedness k = connectedness(quadratic(c), 2000);
        EXPECT_FALSE(k.connected) << c;
        EXPECT_TRUE(k.cantor) << c;
        EXPECT_TRUE(k.certain) << c;  // an escape is certain
    }
}

// With two critical points, one may escape while the other stays bounded: disconnected, but
// not a Cantor set.
TEST(Connectedness, CubicWithOneEscapingCriticalPointIsDisconnected) {
    // z^3 + 3 z^2: critical points 0 (a superattracting fixed point) and -2 -> 4 -> 112 -> ...
    Connectedness mixed = connectedness(ComplexPolynomial({0, 0, 3, 1}), 500);
    EXPECT_FALSE(mixed.connected);
    EXPECT_FALSE(mixed.cantor);
    // z^3 - 3 z: critical points +-1 -> -+2 -> -+2: the Chebyshev map, K = [-2, 2].
    EXPECT_TRUE(connectedness(ComplexPolynomial({0, -3, 0, 1}), 500).connected);
    // z^3 - 3 z + 3: critical orbits 1 -> 1 (fixed), -1 -> 5 -> escapes.
    EXPECT_FALSE(connectedness(ComplexPolynomial({3, -3, 0, 1}), 500).connected);
}

}  // namespace
}  // namespace quaternia
