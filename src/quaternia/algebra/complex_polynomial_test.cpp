#include "quaternia/algebra/complex_polynomial.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "quaternia/algebra/formula.h"

namespace quaternia {
namespace {

TEST(ComplexPolynomial, HornerEvaluationAndDerivative) {
    ComplexPolynomial p({Complex(1, 1), 0, Complex(2, 0), Complex(0, 0)});  // 2z^2 + (1+i)
    EXPECT_EQ(p.degree(), 2);
    EXPECT_EQ(p.evaluate(Complex(0, 1)), Complex(-1, 1));
    EXPECT_EQ(p.derivative(Complex(3, 0)), Complex(12, 0));
    EXPECT_EQ(p.derivativePolynomial().coefficients(), (std::vector<Complex>{0, Complex(4, 0)}));
}

TEST(ComplexPolynomial, RestrictsToThePlaneOfTheCoefficients) {
    // c in span{1, j}: the plane is C_j and z^2 + c becomes z^2 + (-0.5 + 0.3 i).
    auto r = restrictToComplexPlane(compileFormula("z^2 + c", Quaternion(-0.5, 0, 0.3, 0)));
    ASSERT_TRUE(r);
    EXPECT_EQ(r->axis, kUnitJ);
    ASSERT_EQ(r->polynomial.degree(), 2);
    EXPECT_NEAR(std::abs(r->polynomial.coefficients()[0] - Complex(-0.5, 0.3)), 0, 1e-15);
    // The restriction commutes with the embedding: p(toQuaternion(z)) = toQuaternion(p(z)).
    Polynomial p = compileFormula("(1+2j) z (0.5-j) z + 0.25 z + c", Quaternion(0.1, 0, -0.2, 0));
    auto restricted = restrictToComplexPlane(p);
    ASSERT_TRUE(restricted);
    Complex z(0.3, -0.7);
    Quaternion image = p.evaluate(restricted->toQuaternion(z));
    Complex expected = restricted->polynomial.evaluate(z);
    EXPECT_NEAR(norm(image - restricted->toQuaternion(expected)), 0, 1e-14);
}

// The squares of the components under- or overflow here: the axis still follows the coefficient
// (a coefficient of 1e-228 got the axis i whatever its direction; found by fuzzing).
TEST(ComplexPolynomial, PlaneOfTinyAndHugeCoefficients) {
    EXPECT_EQ(planeAxis(Quaternion(0, 0, 3e-228, 0)), kUnitJ);
    EXPECT_EQ(planeAxis(Quaternion(1, 0, 0, -1e200)), -kUnitK);
    const Quaternion axis = planeAxis(Quaternion(-3.2e-228, 9.6e-228, 3.2e-228, 3.2e-228));
    const Quaternion expected = planeAxis(Quaternion(-3.2, 9.6, 3.2, 3.2));
    for (int k = 0; k < 4; ++k)
        EXPECT_NEAR(axis[k], expected[k], 1e-15);
    EXPECT_EQ(planeAxis(Quaternion(5)), kUnitI);
    EXPECT_FALSE(inPlane(Quaternion(0, 0, 1e306, 0), kUnitI));
    EXPECT_TRUE(inPlane(Quaternion(1e306, 1e306, 0, 0), kUnitI));
}

TEST(ComplexPolynomial, NoRestrictionWhenCoefficientsLeaveThePlane) {
    EXPECT_FALSE(restrictToComplexPlane(compileFormula("i*z*j*z + c", Quaternion(0.1))));
    // One non-real coefficient always spans a plane.
    EXPECT_TRUE(restrictToComplexPlane(compileFormula("z^2 + c", Quaternion(0, 0.2, 0.3, 0))));
    EXPECT_FALSE(
        restrictToComplexPlane(compileFormula("i z^2 + c", Quaternion(0, 0, 0.3, 0))).has_value());
}

TEST(ComplexPolynomial, AberthFindsAllRootsWithMultiplicity) {
    // (z - 1)(z + 2)(z - i)(z + i) = z^4 + z^3 - z^2 + z - 2
    ComplexPolynomial p({-2, 1, -1, 1, 1});
    std::vector<Complex> roots = polynomialRoots(p);
    ASSERT_EQ(roots.size(), 4u);
    for (Complex expected : {Complex(1), Complex(-2), Complex(0, 1), Complex(0, -1)}) {
        double nearest = 1e9;
        for (Complex r : roots)
            nearest = std::min(nearest, std::abs(r - expected));
        EXPECT_LT(nearest, 1e-12) << expected;
    }
    // Fixed points of z^2 - 1: (1 +- sqrt 5) / 2 (docs/facts.md, Cycles and multipliers of
    // z^2 + c).
    std::vector<Complex> fixed = polynomialRoots(ComplexPolynomial({-1, -1, 1}));
    std::sort(fixed.begin(), fixed.end(), [](Complex a, Complex b) { return a.real() < b.real(); });
    EXPECT_NEAR(fixed[0].real(), -0.6180339887498949, 1e-14);
    EXPECT_NEAR(fixed[1].real(), 1.6180339887498949, 1e-14);
}

}  // namespace
}  // namespace quaternia
