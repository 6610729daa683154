// The lanes decide every point as the one-point loop of evaluateInAlgebra does, bit for bit:
// the first point inside of a batch is the loop's, in every algebra the table serves.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "quaternia/algebra/formula.h"
#include "quaternia/algebra/formula_program.h"
#include "quaternia/algebra/orbit_batch.h"

namespace quaternia {
namespace {

// HypercomplexJuliaSet::containsByOrbit's loop through the table.
bool insideByLoop(const FormulaProgram& program, const MultiplicationTable& table,
                  const Hypercomplex& z0, int maxIterations, double bailoutSquared) {
    Hypercomplex z = z0;
    for (int n = 0;; ++n) {
        if (normSquared(z) > bailoutSquared) return false;
        if (n + 1 >= maxIterations) return true;
        z = evaluateInAlgebra(program, table, z);
    }
}

TEST(OrbitBatch, DecidesEveryPointAsTheOnePointLoop) {
    // Squares, products on both sides (linear maps), scaling, negation, differences and powers.
    const std::vector<std::string> formulas = {
        "z^2 + c",         "i z^2 j + c",        "(1+0.2i) z (1-0.1k) z + 0.1j z + c",
        "z^3 - 0.5 z + c", "-z^2 + 0.3 z^4 - c", "z^5 + 0.2 z^2 + c",
        "z j z + c"};
    const std::vector<Algebra> algebras = {Algebra::kCoquaternion, Algebra::kBiquaternion,
                                           Algebra::kOctonion, Algebra::kBicomplex};
    std::mt19937 random(42);
    std::uniform_real_distribution<double> component(-1.3, 1.3);
    int inside = 0, outside = 0, batches = 0;
    for (Algebra algebra : algebras) {
        const MultiplicationTable& table = MultiplicationTable::of(algebra);
        const int d = table.dimension();
        Hypercomplex c{};
        for (int k = 0; k < d; ++k)
            c[std::size_t(k)] = 0.3 * component(random);
        for (const std::string& text : formulas) {
            const FormulaProgram program =
                FormulaProgram::compile(Formula::parse(text), algebra, c);
            ASSERT_TRUE(batchesOrbits(program)) << text;
            for (int maxIterations : {1, 2, 12, 40}) {
                const double bailoutSquared = 4;
                for (int trial = 0; trial < 30; ++trial) {
                    // Runs of 1 to 40 points, shrunk towards the origin so that some are inside.
                    const int count = 1 + int(random() % 40);
                    const double scale = 0.3 + 0.7 * double(trial % 4) / 3;
                    std::vector<Hypercomplex> points(std::size_t(count), Hypercomplex{});
                    for (auto& p : points)
                        for (int k = 0; k < d; ++k)
                            p[std::size_t(k)] = scale * component(random);
                    int expected = count;
                    for (int i = 0; i < count; ++i) {
                        const bool in = insideByLoop(program, table, points[std::size_t(i)],
                                                     maxIterations, bailoutSquared);
                        (in ? inside : outside) += 1;
                        // Each point alone, and the first of the run.
                        EXPECT_EQ(firstInsideOfBatch(program, table, &points[std::size_t(i)], 1,
                                                     maxIterations, bailoutSquared),
                                  in ? 0 : 1)
                            << text << " in " << algebraName(algebra);
                        if (in && expected == count) expected = i;
                    }
                    EXPECT_EQ(firstInsideOfBatch(program, table, points.data(), count,
                                                 maxIterations, bailoutSquared),
                              expected)
                        << text << " in " << algebraName(algebra) << ", N " << maxIterations;
                    ++batches;
                }
            }
        }
    }
    // Both answers were met often enough for the comparison to mean something.
    EXPECT_GT(inside, 2000);
    EXPECT_GT(outside, 2000);
    EXPECT_EQ(batches, 4 * 7 * 4 * 30);
}

TEST(OrbitBatch, RefusesWhatTheTableDoesNotRun) {
    Hypercomplex c{};
    c[0] = -0.2;
    EXPECT_FALSE(
        batchesOrbits(FormulaProgram::compile(Formula::parse("z^2 + c"), Algebra::kQuaternion, c)));
    EXPECT_FALSE(batchesOrbits(
        FormulaProgram::compile(Formula::parse("sin(z) + c"), Algebra::kBicomplex, c)));
    EXPECT_TRUE(batchesOrbits(
        FormulaProgram::compile(Formula::parse("z^2 + c"), Algebra::kCoquaternion, c)));
}

}  // namespace
}  // namespace quaternia
