#include "quaternia/algebra/formula_program.h"

#include <gtest/gtest.h>

#include <memory>
#include <random>

#include "quaternia/algebra/formula.h"
#include "quaternia/algebra/test_helpers.h"

namespace quaternia {
namespace {

using Op = Instruction::Op;
using testing::randomQuaternion;

FormulaProgram compiled(const std::string& text, const Quaternion& c = {-0.2, 0.6, 0.2, 0.2}) {
    return FormulaProgram::compile(Formula::parse(text), c);
}

// Every register is written before it is read, and the result is the last.
void expectWellFormed(const FormulaProgram& p) {
    ASSERT_FALSE(p.instructions().empty());
    EXPECT_EQ(p.result(), int(p.instructions().size()) - 1);
    for (std::size_t n = 0; n < p.instructions().size(); ++n) {
        const Instruction& i = p.instructions()[n];
        EXPECT_LT(i.a, int(n));
        EXPECT_LT(i.b, int(n));
    }
}

TEST(FormulaProgram, AgreesWithTheExpandedPolynomial) {
    // One- and two-sided coefficients, mixed degrees, several top-degree terms, powers of sums,
    // cancellations, constants to fold: the program keeps the products as written, the
    // expansion multiplies them out, and in H both are the same polynomial.
    const char* formulas[] = {"z^2 + c",
                              "z^2 + 0.1*z + c",
                              "(1+0.2i) z (1-0.1k) z + c",
                              "z^3 + c",
                              "i*z*j*z + c",
                              "z*z*z + 0.5*z + c",
                              "(z + c)^5",
                              "(z - c)(z + c) - z^2",
                              "2z^2*z + k - 3",
                              "z^2 - z^2 + c",
                              "(1 + i)(1 - i) z^2 + c",
                              "z (0.5 - k) z (2 + j) z + c z + c",
                              "-(z^2) + -z + c",
                              "z^0 + z^1 + c",
                              "((z^2 + c)^2 + c)^2 + c",
                              "0*z + c",
                              "z*1 + 0",
                              "(j z)^3 + z^4 k + c"};
    std::mt19937 rng(11);
    for (const char* text : formulas) {
        const Quaternion c(-0.2, 0.6, 0.2, 0.2);
        const FormulaProgram program = compiled(text, c);
        expectWellFormed(program);
        const Polynomial p = Formula::parse(text).expand(c);
        // The program of the expansion itself, term by term, is the same polynomial too.
        const FormulaProgram termByTerm = FormulaProgram::fromPolynomial(p);
        expectWellFormed(termByTerm);
        for (int n = 0; n < 20; ++n) {
            const Quaternion z = randomQuaternion(rng, 1.2);
            const Quaternion expected = p.evaluate(z);
            const double scale = 1 + norm(expected) + std::pow(2.0 * (1 + norm(z)), 8);
            EXPECT_LE(norm(program.evaluate(z) - expected), 1e-13 * scale) << text << " at " << z;
            EXPECT_LE(norm(termByTerm.evaluate(z) - expected), 1e-13 * scale)
                << text << " at " << z;
        }
    }
}

TEST(FormulaProgram, TermByTermSharesPowersAndScalesByRealCoefficients) {
    // 0.5 z^3 + 0.1 z + c: z^2 and z^3 once, two scalings, no quaternion product by a real.
    const Quaternion c(-0.2, 0.6, 0.2, 0.2);
    const FormulaProgram p =
        FormulaProgram::fromPolynomial(Formula::parse("0.5 z^3 + 0.1 z + c").expand(c));
    EXPECT_EQ(p.count(Op::kSquare), 1);
    EXPECT_EQ(p.count(Op::kMultiply), 1);
    EXPECT_EQ(p.count(Op::kScale), 2);
    EXPECT_EQ(p.count(Op::kAdd), 2);
    // A two-sided term keeps its quaternion coefficients as products.
    const FormulaProgram twoSided =
        FormulaProgram::fromPolynomial(Formula::parse("(1+0.2i) z (1-0.1k) z + c").expand(c));
    // A two-sided term's constants around one z make one linear map: a z b z is (L_a R_b z) z.
    EXPECT_EQ(twoSided.count(Op::kLinear), 1);
    EXPECT_EQ(twoSided.count(Op::kMultiply), 1);
    // The zero polynomial is the constant 0.
    const FormulaProgram zero = FormulaProgram::fromPolynomial(Polynomial{});
    EXPECT_EQ(zero.evaluate(Quaternion(1, 2, 3, 4)), Quaternion{});
}

TEST(FormulaProgram, ZSquaredPlusCIsOneSquaringAndOneSum) {
    const FormulaProgram p = compiled("z^2 + c");
    ASSERT_EQ(p.instructions().size(), 4u);  // z, z^2, c, z^2 + c
    EXPECT_EQ(p.count(Op::kSquare), 1);
    EXPECT_EQ(p.count(Op::kAdd), 1);
    EXPECT_EQ(p.count(Op::kMultiply), 0);
    EXPECT_EQ(compiled("z*z + c").instructions().size(), 4u);
}

TEST(FormulaProgram, RealFactorsScaleAndOnesAndZerosVanish) {
    const FormulaProgram p = compiled("z^2 + 0.1*z + c");
    EXPECT_EQ(p.count(Op::kScale), 1);
    EXPECT_EQ(p.count(Op::kMultiply), 0);
    ASSERT_EQ(p.factors().size(), 1u);
    EXPECT_EQ(p.factors()[0], 0.1);
    // Multiplying by 1 and adding 0 leave z; multiplying by 0 leaves c alone.
    EXPECT_EQ(compiled("1*z*1 + 0").instructions().size(), 1u);
    EXPECT_EQ(compiled("0*z^7 + c").instructions().size(), 1u);
    EXPECT_EQ(compiled("-1*z").count(Op::kNegate), 1);
    // Quaternion factors are linear maps on their side, composed: (L_a R_b z) z.
    const FormulaProgram twoSided = compiled("(1+0.2i) z (1-0.1k) z + c");
    EXPECT_EQ(twoSided.count(Op::kLinear), 1);
    EXPECT_EQ(twoSided.count(Op::kMultiply), 1);
    EXPECT_EQ(twoSided.count(Op::kScale), 0);
}

TEST(FormulaProgram, ConstantFactorsComposeIntoOneLinearMap) {
    // i z j, scaled by 2 and by -3 and multiplied by k on the left: one map of z.
    const Quaternion c(-0.2, 0.6, 0.2, 0.2);
    const FormulaProgram p = compiled("k (2 (i z j) (-3)) + c", c);
    EXPECT_EQ(p.count(Op::kLinear), 1);
    EXPECT_EQ(p.count(Op::kScale), 0);
    EXPECT_EQ(p.count(Op::kMultiply), 0);
    std::mt19937 rng(13);
    for (int n = 0; n < 10; ++n) {
        const Quaternion z = randomQuaternion(rng, 1.5);
        const Quaternion expected =
            testing::kK * (2.0 * (testing::kI * z * testing::kJ) * -3.0) + c;
        EXPECT_LT(norm(p.evaluate(z) - expected), 1e-14);
    }
}

TEST(FormulaProgram, FoldsConstantsAndSharesEqualSubexpressions) {
    // (1 + i)(1 - i) = 2: folded into one scaling.
    const FormulaProgram folded = compiled("(1 + i)(1 - i) z^2 + c");
    EXPECT_EQ(folded.count(Op::kMultiply), 0);
    EXPECT_EQ(folded.count(Op::kScale), 1);
    EXPECT_EQ(folded.factors()[0], 2.0);
    // (z + c) is computed once and squared.
    const FormulaProgram shared = compiled("(z + c)*(z + c)");
    EXPECT_EQ(shared.count(Op::kAdd), 1);
    EXPECT_EQ(shared.count(Op::kSquare), 1);
    EXPECT_EQ(shared.instructions().size(), 4u);
}

TEST(FormulaProgram, PowersGoByRepeatedSquaring) {
    // x^12 = ((x^2)^2)^2 x^4: three squarings and one product, not eleven products.
    const FormulaProgram p = compiled("(z + c)^12");
    EXPECT_EQ(p.count(Op::kSquare), 3);
    EXPECT_EQ(p.count(Op::kMultiply), 1);
    EXPECT_EQ(compiled("z^64").count(Op::kSquare), 6);
    EXPECT_EQ(compiled("z^64").count(Op::kMultiply), 0);
    // z^0 = 1, as in the expansion.
    const FormulaProgram one = compiled("z^0");
    EXPECT_EQ(one.instructions().size(), 1u);
    EXPECT_EQ(one.evaluate(Quaternion(0.3, 1, 2, 3)), Quaternion(1));
}

TEST(FormulaProgram, TangentsAreTheDerivativeOfTheExpansion) {
    // Dp(z)[h] by the product rule through the program equals the expansion's derivative.
    const char* formulas[] = {"z^2 + c",
                              "z^2 + 0.1*z + c",
                              "(1+0.2i) z (1-0.1k) z + c",
                              "(z + c)^5",
                              "z (0.5 - k) z (2 + j) z + c z + c",
                              "c"};
    std::mt19937 rng(12);
    for (const char* text : formulas) {
        const Quaternion c(-0.2, 0.6, 0.2, 0.2);
        const FormulaProgram program = compiled(text, c);
        const Polynomial p = Formula::parse(text).expand(c);
        for (int n = 0; n < 10; ++n) {
            const Quaternion z = randomQuaternion(rng, 1.2);
            const Quaternion h[3] = {randomQuaternion(rng), randomQuaternion(rng),
                                     randomQuaternion(rng)};
            std::vector<Quaternion> registers(program.instructions().size());
            std::vector<Quaternion> tangents(3 * program.instructions().size());
            Quaternion derivative[3];
            const Quaternion value = runProgramWithTangents<3>(
                program.instructions(), program.result(), z, h, Quaternion(),
                program.constants().data(), program.factors().data(), registers.data(),
                tangents.data(), derivative);
            EXPECT_LE(norm(value - p.evaluate(z)), 1e-12 * (1 + norm(value))) << text;
            for (int m = 0; m < 3; ++m) {
                const Quaternion expected = p.derivative(z, h[m]);
                EXPECT_LE(norm(derivative[m] - expected), 1e-11 * (1 + norm(expected)))
                    << text << " tangent " << m;
            }
        }
    }
}

TEST(FormulaProgram, RunsOnFloatComponentsToo) {
    // The same instructions on QuaternionT<float>, as the lanes will run them.
    const FormulaProgram p = compiled("(1+0.2i) z (1-0.1k) z + 0.3*z + c");
    std::vector<Quaternionf> constants;
    for (const Quaternion& q : p.constants())
        constants.push_back(Quaternionf(q));
    std::vector<float> factors(p.factors().begin(), p.factors().end());
    std::vector<Quaternionf> registers(p.instructions().size());
    const Quaternion z(0.3, -0.4, 0.5, 0.1);
    const Quaternionf value = runProgram(p.instructions(), p.result(), Quaternionf(z),
                                         constants.data(), factors.data(), registers.data());
    const Quaternion expected = p.evaluate(z);
    for (int k = 0; k < 4; ++k)
        EXPECT_NEAR(value[k], expected[k], 1e-6);
}

}  // namespace
}  // namespace quaternia
