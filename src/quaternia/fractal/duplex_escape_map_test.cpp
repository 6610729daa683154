#include "quaternia/fractal/duplex_escape_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "quaternia/algebra/formula.h"
#include "quaternia/algebra/hypercomplex_formula.h"
#include "quaternia/fractal/hypercomplex_julia.h"

namespace quaternia {
namespace {

using Complex = std::complex<double>;

const char* const kFormulas[] = {"sin(z) + c", "exp(z) + c", "exp(z) - 0.5 cosh(z) + c",
                                 "0.5 cos(z^2) + 0.3 sinh(z) + c", "0.6 cosh(z) - 0.4 z^2 + c"};
const Hypercomplex kC{-0.2, 0.6, 0.2, 0.2, 0, 0, 0, 0};  // the default c: a != b

HypercomplexFormula bicomplex(const char* text, const Hypercomplex& c = kC) {
    return HypercomplexFormula(Formula::parse(text), Algebra::kBicomplex, c);
}

Hypercomplex randomPoint(std::mt19937& rng, double radius) {
    std::uniform_real_distribution<double> u(-radius, radius);
    return {u(rng), u(rng), u(rng), u(rng), 0, 0, 0, 0};
}

// The duplex form is an isomorphism onto C x C: each component program computes the component
// of the algebra's own value.
TEST(DuplexComponentProgram, ComputesTheDuplexComponentsOfTheAlgebrasValue) {
    std::mt19937 rng(3);
    for (const char* text : kFormulas) {
        const HypercomplexFormula formula = bicomplex(text);
        ASSERT_TRUE(DuplexComponentProgram::supports(formula.program())) << text;
        const DuplexComponentProgram a(formula.program(), 0), b(formula.program(), 1);
        std::vector<Complex> registers;
        for (int k = 0; k < 200; ++k) {
            const Hypercomplex q = randomPoint(rng, 1.5);
            const auto w = duplexForm(q);
            const auto expected = duplexForm(formula.evaluate(q));
            const Complex fa = a.value(w[0], registers), fb = b.value(w[1], registers);
            // Both round differently (the table's products in the standard basis).
            EXPECT_NEAR(std::abs(fa - expected[0]), 0, 1e-10 * (1 + std::abs(fa))) << text;
            EXPECT_NEAR(std::abs(fb - expected[1]), 0, 1e-10 * (1 + std::abs(fb))) << text;
        }
    }
    EXPECT_FALSE(DuplexComponentProgram::supports(bicomplex("log(z) + c").program()));
    EXPECT_FALSE(DuplexComponentProgram::supports(bicomplex("z^2.5 + c").program()));
}

// A disc's image, iterated, holds the images of the disc's points (Taylor forms, rounding
// included).
TEST(DuplexComponentProgram, DiscsHoldTheImagesOfTheirPoints) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1, 1), unit(0, 1);
    for (const char* text : kFormulas) {
        const DuplexComponentProgram program(bicomplex(text).program(), 0);
        std::vector<Complex> values;
        std::vector<ComplexDisc> discs;
        for (int k = 0; k < 100; ++k) {
            const ComplexDisc start{Complex(2 * u(rng), 2 * u(rng)), 0.05 * unit(rng)};
            for (int m = 0; m < 10; ++m) {
                const double angle = 3.14159 * u(rng), r = start.radius * std::sqrt(unit(rng));
                Complex w = start.centre + std::polar(r, angle);
                ComplexDisc disc = start;
                for (int n = 0; n < 3 && std::isfinite(disc.radius) && disc.radius < 10; ++n) {
                    w = program.value(w, values);
                    disc = program.disc(disc, discs);
                    if (!std::isfinite(std::norm(w)) || !std::isfinite(disc.radius)) break;
                    EXPECT_LE(std::abs(w - disc.centre), disc.radius) << text << " n " << n;
                }
            }
        }
    }
}

// The maps' clearance is proven: no point within it of q is in K_N (the orbit decides), and a
// cell the maps call outside holds no point of K_N; most of the ball is cleared.
TEST(DuplexEscapeMaps, NoPointWithinTheClearanceIsInTheSet) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> unit(0, 1);
    std::normal_distribution<double> normal;
    // The formulas at the default c, and sin(z) + c at a complex c (both components one map).
    std::vector<std::pair<const char*, Hypercomplex>> cases;
    for (const char* text : kFormulas)
        cases.emplace_back(text, kC);
    cases.emplace_back("sin(z) + c", Hypercomplex{-0.5, 0.5, 0, 0, 0, 0, 0, 0});
    for (const auto& [text, c] : cases) {
        const HypercomplexJuliaSet set(bicomplex(text, c), 12, 4);
        ASSERT_TRUE(set.hasClearance()) << text;
        const std::array<DuplexComponentProgram, 2> programs{
            DuplexComponentProgram(set.formula().program(), 0),
            DuplexComponentProgram(set.formula().program(), 1)};
        const DuplexEscapeMaps maps(programs, 12, 4, 8);
        int cleared = 0, inside = 0, tested = 0;
        for (int k = 0; k < 3000; ++k) {
            const Hypercomplex q = randomPoint(rng, 2.5);
            const bool in = set.containsByOrbit(q);
            inside += in;
            if (maps.outside(q)) {
                EXPECT_FALSE(in) << text;
            }
            const double d = maps.clearance(q);
            if (!(d > 0)) continue;
            ++cleared;
            EXPECT_FALSE(in) << text;
            for (int m = 0; m < 8; ++m) {
                Hypercomplex offset{normal(rng), normal(rng), normal(rng), normal(rng)};
                const double length = std::sqrt(normSquared(offset));
                const double r = (m < 2 ? 0.999 : unit(rng)) * d;
                const Hypercomplex p = q + (r / length) * offset;
                ++tested;
                EXPECT_FALSE(set.containsByOrbit(p)) << text << " at " << r << " of " << d;
            }
        }
        EXPECT_GT(cleared, 1000) << text;
        EXPECT_GT(inside, 20) << text;
        EXPECT_GT(tested, 8000) << text;
    }
}

// The orbit in duplex form is the algebra's orbit: membership agrees with iterating the formula
// through the multiplication table.
TEST(DuplexEscapeMaps, DuplexOrbitsDecideAsTheAlgebrasArithmetic) {
    std::mt19937 rng(13);
    for (const char* text : kFormulas) {
        const HypercomplexJuliaSet set(bicomplex(text), 12, 4);
        const HypercomplexFormula& formula = set.formula();
        int inside = 0, differ = 0;
        for (int k = 0; k < 3000; ++k) {
            const Hypercomplex q = randomPoint(rng, 2.5);
            bool in = true;
            Hypercomplex z = q;
            for (int n = 0; n < 12; ++n) {
                if (normSquared(z) > 16) {
                    in = false;
                    break;
                }
                if (n + 1 < 12) z = formula.evaluate(z);
            }
            inside += in;
            differ += in != set.containsByOrbit(q);
        }
        EXPECT_GT(inside, 20) << text;
        EXPECT_EQ(differ, 0) << text;
    }
}

}  // namespace
}  // namespace quaternia
