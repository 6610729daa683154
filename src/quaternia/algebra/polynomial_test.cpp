// Polynomials: construction, the derivative against finite differences, the power form, the
// certified minimum of the top-degree part and the escape radius (docs/facts.md, Escape radius and
// bounding sphere), and the canonical text's round trip through the parser.
#include "quaternia/algebra/polynomial.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <random>

#include "quaternia/algebra/formula.h"
#include "quaternia/algebra/test_helpers.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

using namespace quaternia::testing;

Quaternion randomUnit(std::mt19937& rng) {
    std::normal_distribution<double> g;
    return normalize(Quaternion{g(rng), g(rng), g(rng), g(rng)});
}

const std::vector<const char*> kFormulas = {
    "z^2 + c",
    "z^3 + c",
    "z^5 + c",
    "z*z*z + 0.5*z + c",
    "(1+2i) z (0.5-k) z + c",
    "i*z*j*z + c",
    "z^2 + (0.1 + 0.2j)*z + c",
    "2 z^2 + i z i z + c",
    "3 z^2 + j z (1+i) z - 0.5 z + c",
};

TEST(Polynomial, ConstructorDropsZeroTermsAndSumsConstants) {
    const Polynomial p({Term{{Quaternion{1}}}, Term{{Quaternion{1}, Quaternion{}, Quaternion{2}}},
                        Term{{Quaternion{2}, Quaternion{1}}}, Term{{kI}}, Term{{}}});
    ASSERT_EQ(p.terms().size(), 2u);
    EXPECT_EQ(p.terms()[0].coefficients, (std::vector<Quaternion>{2, 1}));
    EXPECT_EQ(p.terms()[1].coefficients, (std::vector<Quaternion>{{1, 1, 0, 0}}));  // last
    EXPECT_EQ(p.degree(), 1);
    EXPECT_TRUE(Polynomial({Term{{kI}}, Term{{-kI}}}).terms().empty());
    EXPECT_EQ(Polynomial().degree(), 0);
    EXPECT_EQ(Polynomial().evaluate(kJ), Quaternion{});
}

TEST(Polynomial, DerivativeMatchesCentralDifference) {
    std::mt19937 rng(99);
    for (const char* text : kFormulas) {
        const Polynomial p = compileFormula(text, randomQuaternion(rng, 0.7));
        for (int n = 0; n < 20; ++n) {
            const Quaternion z = randomQuaternion(rng, 1.2), h = randomUnit(rng);
            const double eps = 1e-5;
            const Quaternion difference =
                (p.evaluate(z + h * eps) - p.evaluate(z - h * eps)) / (2 * eps);
            const Quaternion derivative = p.derivative(z, h);
            SCOPED_TRACE(text);
            EXPECT_LT(norm(derivative - difference), 1e-7 * (1 + norm(derivative)));
        }
    }
}

TEST(Polynomial, DerivativeNormBoundDominatesDerivative) {
    std::mt19937 rng(5);
    for (const char* text : kFormulas) {
        const Polynomial p = compileFormula(text, randomQuaternion(rng, 0.7));
        for (int n = 0; n < 200; ++n) {
            const Quaternion z = randomQuaternion(rng, 2), h = randomUnit(rng);
            SCOPED_TRACE(text);
            EXPECT_LE(norm(p.derivative(z, h)), p.derivativeNormBound(norm(z)) * (1 + 1e-14));
        }
    }
    // Attained for z^2 in the direction h = z: D(z^2)[z] = 2 z^2.
    const Polynomial square = compileFormula("z^2", Quaternion{});
    EXPECT_DOUBLE_EQ(square.derivativeNormBound(1.5), 3);
    EXPECT_DOUBLE_EQ(norm(square.derivative(Quaternion{0, 1.5, 0, 0}, kI)), 3);
}

TEST(Polynomial, DerivativeNormBoundCoefficientsGiveTheBound) {
    std::mt19937 rng(6);
    for (const char* text : kFormulas) {
        const Polynomial p = compileFormula(text, randomQuaternion(rng, 0.7));
        const std::vector<double> b = p.derivativeNormBoundCoefficients();
        EXPECT_EQ(int(b.size()), std::max(1, p.degree())) << text;
        for (double r : {0.0, 0.3, 1.0, 2.5}) {
            double horner = 0;
            for (auto k = b.rbegin(); k != b.rend(); ++k)
                horner = horner * r + *k;
            EXPECT_NEAR(horner, p.derivativeNormBound(r), 1e-12 * (1 + horner)) << text;
        }
    }
    // z^3 + 0.5 (1 + j) z: P(r) = r^3 + 0.5 sqrt(2) r, P'(r) = 3 r^2 + 0.5 sqrt(2).
    const std::vector<double> b =
        compileFormula("z^3 + 0.5*(1 + j)*z", Quaternion{}).derivativeNormBoundCoefficients();
    ASSERT_EQ(b.size(), 3u);
    EXPECT_DOUBLE_EQ(b[0], 0.5 * std::sqrt(2.0));
    EXPECT_EQ(b[1], 0);
    EXPECT_EQ(b[2], 3);
}

TEST(Polynomial, RealFormCollectsRealCoefficientsByDegree) {
    const Quaternion c(-0.2, 0.6, 0.2, 0.2);
    const auto form = compileFormula("z^3 + 0.5*z*2*z - 0.1*z + c", c).realForm();
    ASSERT_TRUE(form);
    EXPECT_EQ(form->coefficients, (std::vector<double>{0, -0.1, 1, 1}));
    EXPECT_EQ(form->constant, c);
    // Its value is the polynomial's.
    const Polynomial p = compileFormula("z^3 + 0.5*z*2*z - 0.1*z + c", c);
    std::mt19937 rng(8);
    for (int n = 0; n < 20; ++n) {
        const Quaternion z = randomQuaternion(rng, 1.5);
        Quaternion value = form->constant, power(1);
        for (double a : form->coefficients) {
            value = value + power * a;
            power = power * z;
        }
        EXPECT_LT(norm(value - form->constant - (p.evaluate(z) - c)), 1e-13);
    }
    EXPECT_FALSE(compileFormula("z^2 + 0.1j*z + c", c).realForm());
    EXPECT_FALSE(compileFormula("i*z*j*z + c", c).realForm());
}

TEST(Polynomial, QuadraticTermNamesTheThreeFactorsOfItsOneTerm) {
    const Quaternion c(-0.2, 0.6, 0.2, 0.2);
    const Polynomial p = compileFormula("(1+0.2i) z (1-0.1k) z j + 0.5 + c", c);
    const auto form = p.quadraticTerm();
    ASSERT_TRUE(form);
    EXPECT_EQ(form->constant, c + Quaternion(0.5));
    std::mt19937 rng(9);
    for (int n = 0; n < 20; ++n) {
        const Quaternion z = randomQuaternion(rng, 1.5);
        const Quaternion value = form->left * z * form->middle * z * form->right + form->constant;
        EXPECT_LT(norm(value - p.evaluate(z)), 1e-13);
    }
    EXPECT_FALSE(compileFormula("z^2 + 0.1*z + c", c).quadraticTerm());
    EXPECT_FALSE(compileFormula("z^3 + c", c).quadraticTerm());
    EXPECT_FALSE(compileFormula("z i z + z^2 + c", c).quadraticTerm());
}

TEST(Polynomial, DetectsPowerForm) {
    const Quaternion c{-0.2, 0.6, 0.2, 0.2};
    const auto quadratic = compileFormula("z^2 + c", c).powerForm();
    ASSERT_TRUE(quadratic);
    EXPECT_EQ(quadratic->degree, 2);
    EXPECT_EQ(quadratic->scale, 1);
    EXPECT_EQ(quadratic->constant, c);
    const auto cubic = compileFormula("2*z^3 + c", c).powerForm();
    ASSERT_TRUE(cubic);
    EXPECT_EQ(cubic->degree, 3);
    EXPECT_EQ(cubic->scale, 2);
    const auto inner = compileFormula("-z*0.5*z^3", c).powerForm();
    ASSERT_TRUE(inner);
    EXPECT_EQ(inner->degree, 4);
    EXPECT_EQ(inner->scale, -0.5);
    EXPECT_EQ(inner->constant, Quaternion{});
    for (const char* text : {"i*z*j*z + c", "z^2 + z + c", "c", "(1+2i) z (0.5-k) z", "i z^2"}) {
        SCOPED_TRACE(text);
        EXPECT_FALSE(compileFormula(text, c).powerForm());
    }
}

TEST(Polynomial, EscapeRadiusOfQuadraticIsClosedForm) {
    // R_c = (1 + sqrt(1 + 4|c|)) / 2 (docs/facts.md, Escape radius and bounding sphere):
    // 1, 1.2071, 1.6180, 2, 2.3028.
    const double norms[] = {0, 0.25, 1, 2, 3};
    const double expected[] = {1, 1.2071, 1.6180, 2, 2.3028};
    for (int n = 0; n < 5; ++n) {
        const Quaternion c = Quaternion{0.6, 0, -0.8, 0} * norms[n];
        const double r = compileFormula("z^2 + c", c).escapeRadius();
        EXPECT_NEAR(r, (1 + std::sqrt(1 + 4 * norms[n])) / 2, 1e-13 * r);
        EXPECT_NEAR(r, expected[n], 5e-5);
    }
    EXPECT_EQ(compileFormula("z^2", Quaternion{}).escapeRadius(), 1);
    // Sharp for real c <= 0: R is a fixed point of z^2 + c, so no smaller radius escapes.
    const Polynomial airplane = compileFormula("z^2 + c", Quaternion{-2});
    EXPECT_NEAR(norm(airplane.evaluate(Quaternion{airplane.escapeRadius()})), 2, 1e-13);
}

TEST(Polynomial, EscapeRadiusMakesOrbitsGrow) {
    std::mt19937 rng(17);
    for (const char* text : kFormulas) {
        for (int trial = 0; trial < 3; ++trial) {
            const Polynomial p = compileFormula(text, randomQuaternion(rng, 1));
            const double r = p.escapeRadius();
            for (int n = 0; n < 200; ++n) {
                const Quaternion z = randomUnit(rng) * (r * (1 + 1e-6));
                SCOPED_TRACE(text);
                EXPECT_GT(norm(p.evaluate(z)), norm(z));
            }
            // Just outside R the orbit grows without bound.
            Quaternion z = randomUnit(rng) * (r * 1.01);
            for (int n = 0; n < 200 && norm(z) < 1e6; ++n)
                z = p.evaluate(z);
            EXPECT_GT(norm(z), 1e6) << text;
        }
    }
}

TEST(Polynomial, VanishingTopDegreeIsRefused) {
    // z i z - i z^2 = (z i - i z) z is 0 on all of C_i, so with c in C_i the set is unbounded.
    const Polynomial p = compileFormula("z i z - i z^2 + c", Quaternion{0.1, 0.2, 0, 0});
    EXPECT_EQ(p.topDegreeMinimum(), 0);
    EXPECT_EQ(p.evaluate(Quaternion{3, -7, 0, 0}), (Quaternion{0.1, 0.2, 0, 0}));
    try {
        p.escapeRadius();
        ADD_FAILURE() << "no error";
    } catch (const UserError& error) {
        EXPECT_EQ(error.key(), "fractal.formula");
        EXPECT_NE(std::string(error.what()).find("vanishes on the unit sphere"), std::string::npos);
    }
    // i u i u = -s(u) u with s negating j and k, so z^2 + i z i z vanishes on C_i too.
    EXPECT_EQ(compileFormula("z^2 + i z i z", Quaternion{}).topDegreeMinimum(), 0);
}

TEST(Polynomial, EscapeRadiusNeedsDegreeTwo) {
    for (const char* text : {"2 z + c", "c", "z^2 - z^2 + z"}) {
        SCOPED_TRACE(text);
        EXPECT_THROW(compileFormula(text, Quaternion{0.5}).escapeRadius(), UserError);
    }
}

TEST(Polynomial, SingleTopTermMinimumIsNormProduct) {
    const Polynomial p = compileFormula("(1+2i) z (0.5-k) z + 7 z", Quaternion{});
    EXPECT_DOUBLE_EQ(p.topDegreeMinimum(), std::sqrt(5.0) * std::sqrt(1.25));
    EXPECT_EQ(compileFormula("z^2 + c", Quaternion{1}).topDegreeMinimum(), 1);
}

// An upper bound on min |P_d| over the sphere: dense random samples, then a shrinking random
// search from the best ones.
double sampledMinimum(const Polynomial& top, std::mt19937& rng) {
    std::vector<std::pair<double, Quaternion>> samples;
    for (int n = 0; n < 100000; ++n) {
        const Quaternion u = randomUnit(rng);
        samples.emplace_back(norm(top.evaluate(u)), u);
    }
    std::partial_sort(samples.begin(), samples.begin() + 20, samples.end(),
                      [](const auto& a, const auto& b) { return a.first < b.first; });
    double best = samples[0].first;
    for (int s = 0; s < 20; ++s) {
        auto [value, u] = samples[s];
        for (double step = 0.05; step > 1e-7; step *= 0.7) {
            for (int n = 0; n < 30; ++n) {
                const Quaternion v = normalize(u + randomUnit(rng) * step);
                const double f = norm(top.evaluate(v));
                if (f < value) value = f, u = v;
            }
        }
        best = std::min(best, value);
    }
    return best;
}

TEST(Polynomial, TopDegreeMinimumOfSeveralTermsIsCertified) {
    std::mt19937 rng(31);
    struct Case {
        const char* top;
        double exact;  // < 0 when unknown
    };
    // a u^2 + i u i u = (a u - s(u)) u with s negating j, k: |.| >= |a - 1|, attained on C_i.
    const Case cases[] = {{"2 z^2 + i z i z", 1},
                          {"1.01 z^2 + i z i z", 0.01},
                          {"z^3 + 0.5 i z j z k z", 0.5},
                          {"(1+i) z^2 + z (1-2j) z + 0.5k z k z", -1},
                          {"z^2 + 0.3 j z k z + 0.2 i z i z + 0.1 z k z", -1}};
    for (const Case& test : cases) {
        SCOPED_TRACE(test.top);
        const Polynomial p = compileFormula(test.top, Quaternion{});
        const double m = p.topDegreeMinimum();
        const double sampled = sampledMinimum(p, rng);
        EXPECT_LE(m, sampled);
        EXPECT_GE(m, sampled * (1 - 1e-3));
        if (test.exact > 0) {
            EXPECT_LE(m, test.exact * (1 + 1e-12));
            EXPECT_GE(m, test.exact * (1 - 1e-3));
        }
    }
}

// The branch and bound's results are kept per top-degree part (the explorer asks again for every
// c): each part gets its own minimum, whatever was asked before, and lower terms and c do not
// change it.
TEST(Polynomial, RememberedTopDegreeMinimaBelongToTheirTerms) {
    const double first = compileFormula("2 z^2 + i z i z + c", Quaternion{0.3}).topDegreeMinimum();
    const double other = compileFormula("3 z^2 + i z i z", Quaternion{}).topDegreeMinimum();
    EXPECT_NEAR(first, 1, 1e-3);  // |2 - 1|
    EXPECT_NEAR(other, 2, 2e-3);  // |3 - 1|
    const double again = compileFormula("2 z^2 + i z i z + 0.2 z + c", Quaternion{-0.7, 0.1, 0, 0})
                             .topDegreeMinimum();
    EXPECT_EQ(again, first);
    // The same terms in the other order are another key, and the same minimum.
    EXPECT_NEAR(compileFormula("i z i z + 2 z^2", Quaternion{}).topDegreeMinimum(), first, 1e-3);
}

TEST(Polynomial, TopDegreeMinimumStaysCertifiedAtTheWorkCap) {
    // Minima on whole circles or spheres of S^3 need more cells than the cap allows: the bound
    // is then looser than 1e-3 but still below the true minimum.
    std::mt19937 rng(37);
    const Polynomial linear = compileFormula("3 z^2 + j z (1+i) z", Quaternion{});
    const double m = linear.topDegreeMinimum();
    const double sampled = sampledMinimum(linear, rng);
    EXPECT_LE(m, sampled);
    EXPECT_GE(m, sampled * 0.99);
    // z^2 + z^2 as two terms (the parser would combine them): |P_d| = 2 everywhere.
    const Polynomial twice({Term{{1, 1, 1}}, Term{{1, 1, 1}}});
    EXPECT_LE(twice.topDegreeMinimum(), 2);
    EXPECT_GE(twice.topDegreeMinimum(), 2 * 0.97);
}

TEST(Polynomial, TopDegreeMinimumIsQuick) {
    const auto start = std::chrono::steady_clock::now();
    int certified = 0;
    for (const char* text : {"2 z^2 + i z i z + c", "z^3 + 0.5 i z j z k z", "3 z^2 + j z (1+i) z",
                             "z i z - i z^2 + c", "3 z^5 + z^2 z (i + j) z^2"}) {
        certified += compileFormula(text, Quaternion{0.1}).topDegreeMinimum() > 0;
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(certified, 4);
    EXPECT_LT(seconds, 5.0);  // at most ~20 ms each in a release build; lenient for sanitizers
}

void expectSameTerms(const Polynomial& a, const Polynomial& b) {
    ASSERT_EQ(a.terms().size(), b.terms().size());
    for (size_t t = 0; t < a.terms().size(); ++t) {
        EXPECT_EQ(a.terms()[t].coefficients, b.terms()[t].coefficients) << "term " << t;
    }
}

TEST(Polynomial, ToStringRoundTripsThroughParser) {
    std::mt19937 rng(8);
    for (const char* text : kFormulas) {
        const Polynomial p = compileFormula(text, randomQuaternion(rng, 1));
        SCOPED_TRACE(p.toString());
        expectSameTerms(compileFormula(p.toString(), Quaternion{}), p);
    }
    // Random coefficients (distinct tails, so no like terms), with units, reals of both signs,
    // and extreme magnitudes.
    const Quaternion specials[] = {
        {1}, {-1}, {2}, {-0.5}, kI, -kJ, {0, 0, 0, 1e-300}, {1e22, -3e-7, 0, 1}};
    for (int n = 0; n < 200; ++n) {
        std::vector<Term> terms;
        for (int degree = 0; degree < 4; ++degree) {
            Term term;
            for (int k = 0; k <= degree; ++k) {
                const bool special = rng() % 2 == 0;
                term.coefficients.push_back(special ? specials[rng() % 8] : randomQuaternion(rng));
            }
            terms.push_back(term);
        }
        const Polynomial p(terms);
        SCOPED_TRACE(p.toString());
        expectSameTerms(compileFormula(p.toString(), Quaternion{}), p);
    }
}

TEST(Polynomial, ToStringIsReadable) {
    EXPECT_EQ(
        compileFormula("z^2 + (0.1 + 0.2j)*z + c", Quaternion{-0.2, 0.6, 0.2, 0.2}).toString(),
        "z^2 + (0.1+0.2j)*z + (-0.2+0.6i+0.2j+0.2k)");
    EXPECT_EQ(compileFormula("-z^2 - 0.5 z (1-i) z^3 + i", Quaternion{}).toString(),
              "-z^2 - 0.5*z*(1-i)*z^3 + (i)");
    EXPECT_EQ(compileFormula("(1+2i) z (0.5-k) z - 1", Quaternion{}).toString(),
              "(1+2i)*z*(0.5-k)*z - 1");
    EXPECT_EQ(compileFormula("z*(-2)*z", Quaternion{}).toString(), "z*(-2)*z");
    EXPECT_EQ(Polynomial().toString(), "0");
}

}  // namespace
}  // namespace quaternia
