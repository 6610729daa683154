// Balls (ball_form.h): every point of a ball proven in K_N stays in the bailout's ball for N
// iterates, in every algebra; and near an attracting cycle a ball survives the hundreds of
// iterations that a box about the same point does not (the wrapping effect).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "quaternia/algebra/formula.h"
#include "quaternia/algebra/formula_program.h"
#include "quaternia/interval/ball_form.h"
#include "quaternia/interval/interval_element.h"

namespace quaternia {
namespace {

FormulaProgram programOf(const std::string& formula, Algebra algebra, const Hypercomplex& c) {
    return FormulaProgram::compile(Formula::parse(formula), algebra, c);
}

// Whether the orbit of z0 stays in the ball for n iterates (plain floating point).
bool orbitStays(const FormulaProgram& program, const MultiplicationTable& table, Hypercomplex z,
                int n, double bailout) {
    for (int k = 0; k < n; ++k) {
        if (euclideanNorm(z) > bailout) return false;
        if (k + 1 < n) z = evaluateInAlgebra(program, table, z);
    }
    return true;
}

TEST(BallForm, ProvenBallsHoldOnlyPointsOfTheSet) {
    const Hypercomplex c{-0.5, 0.4, 0.2, 0.1, 0.05, 0, 0.02, 0};
    std::mt19937 random(11);
    std::uniform_real_distribution<double> coordinate(-1, 1), unit(-1, 1);
    for (Algebra algebra : allAlgebras()) {
        const MultiplicationTable& table = MultiplicationTable::of(algebra);
        const int d = table.dimension();
        int proven = 0;  // over the formulas: the check is not vacuous
        for (const char* formula : {"z^2 + c", "z^3 + 0.3 z + c", "sin(z) + c"}) {
            if (std::string(formula).find("sin") != std::string::npos &&
                algebra != Algebra::kBicomplex)
                continue;
            const FormulaProgram program = programOf(formula, algebra, c);
            for (int trial = 0; trial < 300; ++trial) {
                BallForm ball;
                for (int k = 0; k < d; ++k)
                    ball.centre[size_t(k)] = 0.8 * coordinate(random);
                ball.radius = 1e-3 * std::fabs(unit(random));
                if (!ballStaysInBall(program, table, ball, 12, 2)) continue;
                ++proven;
                for (int sample = 0; sample < 20; ++sample) {
                    Hypercomplex offset{};
                    double norm = 0;
                    for (int k = 0; k < d; ++k) {
                        offset[size_t(k)] = unit(random);
                        norm += offset[size_t(k)] * offset[size_t(k)];
                    }
                    Hypercomplex z = ball.centre;
                    for (int k = 0; k < d; ++k)
                        z[size_t(k)] += ball.radius * offset[size_t(k)] / std::sqrt(norm);
                    ASSERT_TRUE(orbitStays(program, table, z, 12, 2))
                        << algebraName(algebra) << " " << formula;
                }
            }
        }
        EXPECT_GE(proven, 5) << algebraName(algebra);
    }
}

// c = -0.5 + 0.424i: an attracting fixed point of multiplier 0.925, near which a box about a
// point is turned and wrapped ever wider.
TEST(BallForm, SurvivesTheIterationsOfABasinWhereABoxDoesNot) {
    const Hypercomplex c{-0.5, 0.424, 0, 0};
    const MultiplicationTable& table = MultiplicationTable::of(Algebra::kQuaternion);
    const FormulaProgram program = programOf("z^2 + c", Algebra::kQuaternion, c);
    const Hypercomplex z0{0.05, 0.1, 0, 0};
    ASSERT_TRUE(orbitStays(program, table, z0, 256, 2));
    EXPECT_TRUE(ballStaysInBall(program, table, {z0, 1e-12}, 256, 2));
    EXPECT_FALSE(boxAboutStaysInBall(program, table, z0, 1e-12, 256, 2));
}

}  // namespace
}  // namespace quaternia
