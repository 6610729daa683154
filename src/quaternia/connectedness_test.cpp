#include "connectedness.h"

#include <gtest/gtest.h>

#include <random>

namespace quaternia {
namespace {

ComplexPolynomial quadratic(Complex c) {
    return ComplexPolynomial({c, 0, 1});
}

TEST(Connectedness, QuadraticIsConnectedExactlyOnM) {
    const Complex rabbit(-0.12256116687665, 0.74486176661974);
    for (Complex c : {Complex(-2), Complex(0.25), Complex(-0.75), Complex(0, 1), Complex(0),
                      Complex(-1), rabbit})
        EXPECT_EQ(classifyConnectedness(quadratic(c)), Connectedness::Connected) << c;
    for (Complex c : {Complex(0.26), Complex(1), Complex(-2.01), Complex(0, 1.1)})
        EXPECT_EQ(classifyConnectedness(quadratic(c)), Connectedness::CantorSet) << c;
}

TEST(Connectedness, CubicWithOneEscapingCriticalPointIsDisconnected) {
    // z^3 + 3 z^2: critical points 0 (a superattracting fixed point) and -2, whose orbit
    // -2 -> 4 -> 112 -> ... escapes.
    EXPECT_EQ(classifyConnectedness(ComplexPolynomial({0, 0, 3, 1})), Connectedness::Disconnected);
    // z^3 - 3 z: critical points +-1 -> -+2 -> -+2: the Chebyshev map, K = [-2, 2].
    EXPECT_EQ(classifyConnectedness(ComplexPolynomial({0, -3, 0, 1})), Connectedness::Connected);
    // z^3 - 3 z + 3: critical orbits 1 -> 1 -> 1 (bounded), -1 -> 5 -> escapes.
    EXPECT_EQ(classifyConnectedness(ComplexPolynomial({3, -3, 0, 1})), Connectedness::Disconnected);
    EXPECT_STREQ(describe(Connectedness::CantorSet), "a Cantor set");
}

TEST(Connectedness, EscapeRadiusCertifiesEscape) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-2, 2);
    for (int n = 0; n < 200; ++n) {
        ComplexPolynomial p({{u(rng), u(rng)}, {u(rng), u(rng)}, {u(rng), u(rng)}, {0.5, 0.2}});
        double r = complexEscapeRadius(p);
        for (double angle = 0; angle < 6.28; angle += 0.1) {
            Complex z = std::polar(r * 1.0001, angle);
            EXPECT_GT(std::abs(p.evaluate(z)), 2 * std::abs(z));
        }
    }
    EXPECT_THROW(classifyConnectedness(ComplexPolynomial({1, 1})), std::invalid_argument);
}

}  // namespace
}  // namespace quaternia
