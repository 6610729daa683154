#include "quaternia/algebra/program_bounds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "quaternia/algebra/formula.h"
#include "quaternia/algebra/formula_tree.h"
#include "quaternia/algebra/hypercomplex_formula.h"

namespace quaternia {
namespace {

// The bounds as HypercomplexFormula computed them from the parse tree before the analysis pass
// over programs replaced it (commit 140b180), node by node.
struct TreeBounds {
    std::vector<double> bound;
    int degree = 0;
    double top = 0;
    bool transcendental = false;
};

std::vector<double> added(const std::vector<double>& a, const std::vector<double>& b) {
    std::vector<double> sum(std::max(a.size(), b.size()), 0.0);
    for (std::size_t k = 0; k < a.size(); ++k)
        sum[k] += a[k];
    for (std::size_t k = 0; k < b.size(); ++k)
        sum[k] += b[k];
    return sum;
}

std::vector<double> multiplied(const std::vector<double>& a, const std::vector<double>& b,
                               double kappa) {
    std::vector<double> product(a.size() + b.size() - 1, 0.0);
    for (std::size_t i = 0; i < a.size(); ++i)
        for (std::size_t j = 0; j < b.size(); ++j)
            product[i + j] += kappa * a[i] * b[j];
    return product;
}

TreeBounds treeBounds(const FormulaNode& n, double kappa, const Hypercomplex& c) {
    using Kind = FormulaNode::Kind;
    TreeBounds t;
    switch (n.kind) {
        case Kind::kConstant:
        case Kind::kC: {
            const Hypercomplex value =
                n.kind == Kind::kC ? c : Hypercomplex{n.value.w, n.value.x, n.value.y, n.value.z,
                                                      0,         0,         0,         0};
            t.bound = {euclideanNorm(value)};
            t.top = t.bound[0];
            return t;
        }
        case Kind::kZ:
            return {{0.0, 1.0}, 1, 1, false};
        case Kind::kNegate:
            return treeBounds(*n.left, kappa, c);
        case Kind::kPower: {
            const TreeBounds a = treeBounds(*n.left, kappa, c);
            t.bound = {1.0};
            for (int e = 0; e < n.exponent; ++e)
                t.bound = e == 0 ? a.bound : multiplied(t.bound, a.bound, kappa);
            t.degree = n.exponent * a.degree;
            t.top = std::pow(a.top, n.exponent);
            t.transcendental = a.transcendental;
            return t;
        }
        case Kind::kFunction:
        case Kind::kRealPower:
            return {{0.0}, 0, 0, true};
        case Kind::kSum:
        case Kind::kDifference:
        case Kind::kProduct: {
            const TreeBounds a = treeBounds(*n.left, kappa, c), b = treeBounds(*n.right, kappa, c);
            t.transcendental = a.transcendental || b.transcendental;
            if (n.kind == Kind::kProduct) {
                t.bound = multiplied(a.bound, b.bound, kappa);
                t.degree = a.degree + b.degree;
                t.top = a.top * b.top;
            } else {
                t.bound = added(a.bound, b.bound);
                t.degree = std::max(a.degree, b.degree);
                t.top = a.degree > b.degree ? a.top
                        : b.degree > a.degree
                            ? b.top
                            : std::max({0.0, a.top - b.bound[std::size_t(b.degree)],
                                        b.top - a.bound[std::size_t(a.degree)]});
            }
            return t;
        }
    }
    return t;
}

const char* const kFormulas[] = {"z^2 + c",
                                 "z^3 + c",
                                 "z^8 + c",
                                 "(z + c)^12",
                                 "z^0 + z^2",
                                 "(1+0.2i) z (1-0.1k) z + c",
                                 "i*z*j*z + c",
                                 "k (2 (i z j) (-3)) + c",
                                 "(1 + i)(1 - i) z^2 + c",
                                 "(z + c)*(z + c)",
                                 "z*z*z + 0.5*z + c",
                                 "z^2 - z^2 + c",
                                 "-(z^3) - 2 z + c",
                                 "z (z z) + c",
                                 "0.5 z^3 + 0.1 z + c",
                                 "2 z^2 + 3 z^2 + c",
                                 "(z^2 + c)^2 + c",
                                 "z^5 - 0.3 z^4 + i z^2 + c",
                                 "(2+i) z^2 (0.5 - j) + c",
                                 "j z^2 j + c",
                                 "(z^2 + c)(z - c) + 0.5",
                                 "z^7 + 0.2 z^6 + c",
                                 "(0.5 + 0.5i + 0.5j + 0.5k) z^2 + c",
                                 "z^2 + (1 + 2j) z + c",
                                 "0*z^2 + z^3 + c"};

TEST(ProgramBounds, EqualThoseOfTheFormulaTreeBitForBit) {
    // Every algebra whose arithmetic is kept as written: each register is a node of the tree
    // (equal ones shared), so the pass finds the tree's bounds exactly.
    const Hypercomplex c{-0.2, 0.6, 0.2, 0.2, 0.1, 0, 0.05, 0};
    for (Algebra algebra : allAlgebras()) {
        if (algebraArithmetic(algebra).rewritesArithmetic) continue;
        Hypercomplex ca = c;
        for (int n = algebraDimension(algebra); n < kMaxAlgebraDimension; ++n)
            ca[std::size_t(n)] = 0;
        for (const char* text : kFormulas) {
            const Formula formula = Formula::parse(text);
            const ProgramBounds b = analyzeProgram(FormulaProgram::compile(formula, algebra, ca));
            const TreeBounds t = treeBounds(*formula.root(), productBound(algebra), ca);
            std::vector<double> expected = t.bound;
            expected.resize(std::size_t(t.degree) + 1, 0.0);
            EXPECT_EQ(b.degree, t.degree) << text << " in " << algebraName(algebra);
            EXPECT_EQ(b.normBound, expected) << text << " in " << algebraName(algebra);
            EXPECT_EQ(b.topDegreeMinimum,
                      algebraArithmetic(algebra).multiplicativeNorm ? t.top : 0.0)
                << text << " in " << algebraName(algebra);
            EXPECT_FALSE(b.transcendental);
        }
    }
}

TEST(ProgramBounds, QuaternionProgramsBoundNoLooserThanTheTree) {
    // The quaternions' programs fold constants, scale, map and square. Their norm is
    // multiplicative, so each rewrite keeps the tree's bound but for rounding, and a folded
    // constant is bounded by its own norm instead of the triangle inequality's sum, so the bound
    // can only tighten ((1 + i)(1 - i): 2, not 4) and the top-degree minimum only grow.
    const Quaternion c(-0.2, 0.6, 0.2, 0.2);
    const Hypercomplex ca{c.w, c.x, c.y, c.z, 0, 0, 0, 0};
    const std::set<std::string> nothingToFold = {"z^2 + c",
                                                 "z^3 + c",
                                                 "z^8 + c",
                                                 "(z + c)^12",
                                                 "i*z*j*z + c",
                                                 "j z^2 j + c",
                                                 "z*z*z + 0.5*z + c",
                                                 "0.5 z^3 + 0.1 z + c",
                                                 "z (z z) + c",
                                                 "z^7 + 0.2 z^6 + c",
                                                 "k (2 (i z j) (-3)) + c"};
    for (const char* text : kFormulas) {
        const Formula formula = Formula::parse(text);
        const ProgramBounds b = analyzeProgram(FormulaProgram::compile(formula, c));
        const TreeBounds t = treeBounds(*formula.root(), 1.0, ca);
        ASSERT_EQ(b.degree, t.degree) << text;
        const bool equal = nothingToFold.count(text) > 0;
        for (int k = 0; k <= t.degree; ++k) {
            const double bk = b.normBound[std::size_t(k)], tk = t.bound[std::size_t(k)];
            EXPECT_LE(bk, tk * (1 + 1e-14)) << text << " coefficient " << k;
            if (equal) {
                EXPECT_NEAR(bk, tk, 1e-14 * (1 + tk)) << text << " coefficient " << k;
            }
        }
        EXPECT_GE(b.topDegreeMinimum, t.top * (1 - 1e-14)) << text;
        if (equal) {
            EXPECT_NEAR(b.topDegreeMinimum, t.top, 1e-14 * (1 + t.top)) << text;
        }
    }
}

TEST(ProgramBounds, TranscendentalProgramsHaveNoBound) {
    const ProgramBounds b = analyzeProgram(
        FormulaProgram::compile(Formula::parse("sin(z) + z^3 + c"), Algebra::kBicomplex,
                                Hypercomplex{0.3, 0.1, 0, 0, 0, 0, 0, 0}));
    EXPECT_TRUE(b.transcendental);
    EXPECT_EQ(b.degree, 2);
    EXPECT_FALSE(b.complexAxis.has_value());
}

TEST(ProgramBounds, ComplexAxisIsTheFirstConstantWrittenOutsideTheReals) {
    // Every constant lies in span{1, j}; the first one written with an imaginary part gives u,
    // sign included: -j from c = 0.3 - 0.4j written first, j from 2j written first.
    const Hypercomplex c{0.3, 0, -0.4, 0, 0, 0, 0, 0};
    for (Algebra algebra : {Algebra::kBicomplex, Algebra::kOctonion, Algebra::kQuaternion}) {
        const ProgramBounds first =
            analyzeProgram(FormulaProgram::compile(Formula::parse("z^2 + c + 2j"), algebra, c));
        ASSERT_TRUE(first.complexAxis.has_value()) << algebraName(algebra);
        EXPECT_EQ(*first.complexAxis, -kUnitJ) << algebraName(algebra);
        const ProgramBounds second =
            analyzeProgram(FormulaProgram::compile(Formula::parse("2j + z^2 + c"), algebra, c));
        ASSERT_TRUE(second.complexAxis.has_value()) << algebraName(algebra);
        EXPECT_EQ(*second.complexAxis, kUnitJ) << algebraName(algebra);
        // A constant outside the plane: none.
        EXPECT_FALSE(
            analyzeProgram(FormulaProgram::compile(Formula::parse("z^2 + c + i"), algebra, c))
                .complexAxis.has_value())
            << algebraName(algebra);
    }
}

TEST(ProgramBounds, HypercomplexFormulaHoldsTheProgramAndItsAnalysis) {
    const Hypercomplex c{-0.2, 0.6, 0.2, 0.2, 0.1, 0, 0.05, 0};
    const HypercomplexFormula f(Formula::parse("z^3 + 0.5 z + c"), Algebra::kOctonion, c);
    const ProgramBounds b = analyzeProgram(f.program());
    EXPECT_EQ(f.degree(), b.degree);
    EXPECT_EQ(f.normBound(), b.normBound);
    EXPECT_EQ(f.topDegreeMinimum(), b.topDegreeMinimum);
    EXPECT_EQ(f.derivativeNormBound(1.5), b.derivativeNormBound(1.5));
    EXPECT_EQ(f.dimension(), 8);
}

}  // namespace
}  // namespace quaternia
