// The formula language: every syntax against a hand-written evaluation at seeded random z, the
// expansion's term structure, and the columns and wording of parse errors.
#include "quaternia/algebra/formula.h"

#include <gtest/gtest.h>

#include <functional>
#include <random>

#include "quaternia/algebra/test_helpers.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

using namespace quaternia::testing;

struct DirectCase {
    const char* text;
    std::function<Quaternion(const Quaternion& z, const Quaternion& c)> direct;
};

TEST(Formula, EvaluatesEverySyntaxLikeDirectComputation) {
    const Quaternion a{1, 2, 0, 0}, b{0.5, 0, 0, -1};
    const std::vector<DirectCase> cases = {
        {"z^2 + c", [](auto z, auto c) { return z * z + c; }},
        {"z^3 + c", [](auto z, auto c) { return z * z * z + c; }},
        {"z^5 + c", [](auto z, auto c) { return z * z * z * z * z + c; }},
        {"z*z*z + 0.5*z + c", [](auto z, auto c) { return z * z * z + 0.5 * z + c; }},
        {"(1+2i) z (0.5-k) z + c", [&](auto z, auto c) { return a * z * b * z + c; }},
        {"i*z*j*z + c", [](auto z, auto c) { return kI * z * kJ * z + c; }},
        {"i z j z + c", [](auto z, auto c) { return kI * z * kJ * z + c; }},
        {"z^2 + (0.1 + 0.2j)*z + c",
         [](auto z, auto c) {
             return z * z + Quaternion{0.1, 0, 0.2, 0} * z + c;
         }},
        {"1+2i-0.5j+k",
         [](auto, auto) {
             return Quaternion{1, 2, -0.5, 1};
         }},
        {"2z + 3", [](auto z, auto) { return 2.0 * z + Quaternion{3}; }},
        {"(z + i)(z - i)", [](auto z, auto) { return (z + kI) * (z - kI); }},
        {"(z + c)^3", [](auto z, auto c) { return (z + c) * (z + c) * (z + c); }},
        {"-z^2 + z ++ c", [](auto z, auto c) { return -(z * z) + z + c; }},
        {"z (1+i) z^2 (2-j)",
         [](auto z, auto) {
             return z * Quaternion{1, 1, 0, 0} * z * z * Quaternion{2, 0, -1, 0};
         }},
        {"c z - z c", [](auto z, auto c) { return c * z - z * c; }},
        {"0.5j z k",
         [](auto z, auto) {
             return Quaternion{0, 0, 0.5, 0} * z * kK;
         }},
        {"z^0 + z^1", [](auto z, auto) { return Quaternion{1} + z; }},
    };
    std::mt19937 rng(2024);
    for (const DirectCase& test : cases) {
        const Quaternion c = randomQuaternion(rng, 0.8);
        const Polynomial p = compileFormula(test.text, c);
        for (int n = 0; n < 20; ++n) {
            const Quaternion z = randomQuaternion(rng);
            SCOPED_TRACE(test.text);
            expectNear(p.evaluate(z), test.direct(z, c), 1e-12);
        }
    }
}

TEST(Formula, ReadsEveryNumberForm) {
    const std::vector<std::pair<const char*, Quaternion>> cases = {
        {"0.5", Quaternion{0.5}},
        {"2", Quaternion{2}},
        {"1e-3", Quaternion{1e-3}},
        {".5", Quaternion{0.5}},
        {"5.", Quaternion{5}},
        {"1E+2", Quaternion{100}},
        {"2i", 2.0 * kI},
        {"0.5j", 0.5 * kJ},
        {"1e-3k", 1e-3 * kK},
        {"-i", -kI},
        {"2 i", 2.0 * kI},
        {"2*3", Quaternion{6}},
        {"2^3", Quaternion{8}},
        {"-2^2", Quaternion{-4}},
        {"(1+i)^2", 2.0 * kI},
        {"2i^2", Quaternion{-4}},
        {"0^0", Quaternion{1}},
        {"i j", kK},
        {"j i", -kK},
        {"1 + 2i - 0.5j + k", Quaternion{1, 2, -0.5, 1}},
    };
    for (const auto& [text, value] : cases) {
        const Polynomial p = compileFormula(text, Quaternion{});
        SCOPED_TRACE(text);
        EXPECT_EQ(p.degree(), 0);
        EXPECT_EQ(p.evaluate(Quaternion{0.3, 0.1, 0.2, 0.4}), value);
    }
}

TEST(Formula, KeepsTwoSidedCoefficientsInOrder) {
    const Polynomial p = compileFormula("(1+2i) z (0.5-k) z + c", Quaternion{0.25, 0, 0.5, 0});
    ASSERT_EQ(p.terms().size(), 2u);
    EXPECT_EQ(p.terms()[0].coefficients,
              (std::vector<Quaternion>{{1, 2, 0, 0}, {0.5, 0, 0, -1}, {1}}));
    EXPECT_EQ(p.terms()[1].coefficients, (std::vector<Quaternion>{{0.25, 0, 0.5, 0}}));
    // Adjacent constants merge by the Hamilton product, in order: i j = k, j i = -k.
    const Polynomial q = compileFormula("i j z j i", Quaternion{});
    ASSERT_EQ(q.terms().size(), 1u);
    EXPECT_EQ(q.terms()[0].coefficients, (std::vector<Quaternion>{kK, -kK}));
}

TEST(Formula, CombinesLikeTermsAndDropsZeros) {
    EXPECT_EQ(compileFormula("z^2 - z^2 + c", Quaternion{1, 2, 3, 4}).degree(), 0);
    EXPECT_TRUE(compileFormula("z^2 + c", Quaternion{}).terms().size() == 1);
    EXPECT_TRUE(compileFormula("0 z^3 + z - z", Quaternion{}).terms().empty());
    // (z + 1)^3 = z^3 + 3 z^2 + 3 z + 1: z 1 and 1 z are the same term.
    const Polynomial cube = compileFormula("(z + 1)^3", Quaternion{});
    ASSERT_EQ(cube.terms().size(), 4u);
    EXPECT_EQ(cube.evaluate(Quaternion{2}), Quaternion{27});
    // z i and i z are different terms and stay apart.
    EXPECT_EQ(compileFormula("z i + i z", Quaternion{}).terms().size(), 2u);
}

TEST(Formula, PowerBindsTighterThanUnaryMinus) {
    const Quaternion z{0.5, -1, 0.25, 2};
    EXPECT_EQ(compileFormula("-z^2", Quaternion{}).evaluate(z), -(z * z));
    EXPECT_EQ(compileFormula("(-z)^2", Quaternion{}).evaluate(z), z * z);
    EXPECT_EQ(compileFormula("--z", Quaternion{}).evaluate(z), z);
    EXPECT_EQ(compileFormula("z ++ c", Quaternion{1}).evaluate(z), z + Quaternion{1});
    EXPECT_EQ(compileFormula("z - -c", Quaternion{1}).evaluate(z), z + Quaternion{1});
}

TEST(Formula, ReportsUsesC) {
    EXPECT_TRUE(Formula::parse("z^2 + c").usesC());
    EXPECT_TRUE(Formula::parse("(z (c))^2").usesC());
    EXPECT_FALSE(Formula::parse("z^2 + 0.5i").usesC());
    EXPECT_EQ(Formula::parse(" z^2 + c ").text(), " z^2 + c ");
}

struct ErrorCase {
    const char* text;
    int column;
    const char* message;  // the whole what(), "column N: ..."
};

TEST(Formula, ReportsErrorColumns) {
    const std::vector<ErrorCase> cases = {
        {"z^2 + ", 7, "column 7: expected a number, i, j, k, z, c or '(' but found end of formula"},
        {"z^2 + x", 7,
         "column 7: unknown name 'x'; expected z, c, i, j, k, a number, '(' or a function such "
         "as sin("},
        {"z^2 + * c", 7, "column 7: expected a number, i, j, k, z, c or '(' but found '*'"},
        {"(z + c", 7,
         "column 7: expected ')' to close the '(' at column 1 but found end of formula"},
        {"z + c)", 6, "column 6: unmatched ')': no '(' is open"},
        {"()", 2, "column 2: expected a number, i, j, k, z, c or '(' but found ')'"},
        {"z^-z", 4, "column 4: expected an exponent but found 'z'"},
        {"z^2i", 3, "column 3: expected an exponent but found '2i'"},
        {"z^", 3, "column 3: expected an exponent but found end of formula"},
        {"sin z", 5, "column 5: expected '(' after sin but found 'z'"},
        {"cos(z + c", 10, "column 10: expected ')' to close cos( but found end of formula"},
        {"z^65", 3, "column 3: the exponent 65 is too large; the limit is 64"},
        {"z^2^3", 4, "column 4: expected '+', '-', '*' or end of formula but found '^'"},
        {"", 1, "column 1: the formula is empty; write a polynomial in z such as 'z^2 + c'"},
        {"   ", 1, "column 1: the formula is empty; write a polynomial in z such as 'z^2 + c'"},
        {"z % 2", 3, "column 3: unexpected character '%'"},
        {"z\u00b2 + c", 2,
         "column 2: unexpected non-ASCII or control character (write powers as z^2)"},
        {"zz + c", 1,
         "column 1: unknown name 'zz'; expected z, c, i, j, k, a number, '(' or a function such "
         "as sin("},
        {"2iz", 2,
         "column 2: unknown name 'iz'; expected z, c, i, j, k, a number, '(' or a function such "
         "as sin("},
        {"1.2.3", 1, "column 1: malformed number '1.2.'"},
        {"1e999 z", 1, "column 1: the number '1e999' is out of range"},
        {"z *", 4, "column 4: expected a number, i, j, k, z, c or '(' but found end of formula"},
    };
    for (const ErrorCase& test : cases) {
        SCOPED_TRACE(test.text);
        try {
            Formula::parse(test.text);
            ADD_FAILURE() << "parsed without error";
        } catch (const FormulaError& error) {
            EXPECT_EQ(error.column(), test.column);
            EXPECT_EQ(std::string(error.what()), test.message);
        }
    }
}

TEST(Formula, FunctionsAndRealPowersParseButDoNotExpand) {
    // POV-Ray's hypercomplex functions and real powers are the bicomplex numbers' (their duplex
    // form); a polynomial expansion refuses them at their column.
    for (const auto& [text, column] :
         {std::pair{"sin(z) + c", 1}, std::pair{"z^-1 + c", 2}, std::pair{"z^2 + 0.5*exp(z*i)", 11},
          std::pair{"z^1.5 + c", 2}}) {
        SCOPED_TRACE(text);
        const Formula formula = Formula::parse(text);
        try {
            formula.expand(Quaternion(0.1));
            ADD_FAILURE() << "expanded";
        } catch (const FormulaError& error) {
            EXPECT_EQ(error.column(), column);
            EXPECT_NE(std::string(error.what()).find("bicomplex"), std::string::npos);
        }
    }
}

TEST(Formula, RefusesDeepNestingWithoutOverflowingTheStack) {
    const std::string deep = std::string(1000, '(') + "z" + std::string(1000, ')');
    EXPECT_THROW(Formula::parse(deep), FormulaError);
    EXPECT_THROW(Formula::parse(std::string(1000, '-') + "z"), FormulaError);
    EXPECT_NO_THROW(Formula::parse(std::string(50, '(') + "z" + std::string(50, ')')));
    // A long flat chain is refused by length before its tree gets deep.
    std::string chain = "z";
    while (chain.size() <= 10000)
        chain += " + z";
    EXPECT_THROW(Formula::parse(chain), FormulaError);
    EXPECT_EQ(compileFormula(chain.substr(0, 9997), Quaternion{}).terms().size(), 1u);
}

TEST(Formula, RefusesFormulasThatAreTooLarge) {
    const Quaternion c{0.1, 0.2, 0.3, 0.4};
    auto expectTooLarge = [&](const char* text) {
        SCOPED_TRACE(text);
        try {
            Formula::parse(text).expand(c);
            ADD_FAILURE() << "expanded without error";
        } catch (const FormulaError& error) {
            EXPECT_EQ(error.column(), 0);
            EXPECT_EQ(std::string(error.what()).rfind("formula too large: ", 0), 0u)
                << error.what();
        }
    };
    expectTooLarge("z^64 * z");
    expectTooLarge("(z^2)^33");
    expectTooLarge("(z + c)^13");  // z c and c z differ: 2^13 terms
    EXPECT_EQ(compileFormula("z^64 + c", c).degree(), 64);
    EXPECT_EQ(compileFormula("(z + c)^12", c).degree(), 12);
    EXPECT_EQ(compileFormula("(z + 1)^64", c).terms().size(), 65u);  // like terms combine
}

TEST(Formula, CompileFormulaNamesTheKey) {
    try {
        compileFormula("z^2 + * c", Quaternion{});
        ADD_FAILURE() << "compiled without error";
    } catch (const UserError& error) {
        EXPECT_EQ(error.key(), "fractal.formula");
        EXPECT_EQ(std::string(error.what()),
                  "fractal.formula: column 7: expected a number, i, j, k, z, c or '(' but found "
                  "'*'");
    }
    try {
        compileFormula("z^70", Quaternion{}, "preset.formula");
        ADD_FAILURE() << "compiled without error";
    } catch (const UserError& error) {
        EXPECT_EQ(error.key(), "preset.formula");
        EXPECT_EQ(std::string(error.what()).rfind("preset.formula: column 3: ", 0), 0u);
    }
    EXPECT_THROW(compileFormula("1e300^2 z", Quaternion{}), UserError);  // overflows
}

}  // namespace
}  // namespace quaternia
