#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "quaternia/algebra/formula.h"
#include "quaternia/algebra/hypercomplex_formula.h"
#include "quaternia/interval/interval.h"
#include "quaternia/interval/interval_element.h"
#include "quaternia/interval/segment_form.h"

namespace quaternia {
namespace {

// An exact real number as an unevaluated sum hi + lo with |lo| <= ulp(hi) / 2 (the results of
// TwoSum and TwoProduct, Ogita, Rump and Oishi 2005), compared exactly with a double: x < hi
// means x < hi + lo, since hi is the nearest double to hi + lo.
struct Exact {
    double hi, lo;
};
Exact exactSum(double a, double b) {
    const double s = a + b, bb = s - a;
    return {s, (a - (s - bb)) + (b - bb)};
}
Exact exactProduct(double a, double b) {
    const double p = a * b;
    return {p, std::fma(a, b, -p)};
}
bool atMost(double x, const Exact& e) {
    return x < e.hi || (x == e.hi && e.lo >= 0);
}
bool atLeast(double x, const Exact& e) {
    return x > e.hi || (x == e.hi && e.lo <= 0);
}
bool encloses(const Interval& i, const Exact& e) {
    return atMost(i.lo, e) && atLeast(i.hi, e);
}

// Doubles of random sign and magnitude 2^-400 .. 2^400: sums and products stay normal, where
// TwoSum and TwoProduct are exact.
double randomDouble(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> mantissa(1, 2);
    std::uniform_int_distribution<int> exponent(-400, 400);
    return std::ldexp(rng() & 1 ? -mantissa(rng) : mantissa(rng), exponent(rng));
}

TEST(Interval, OperationsEncloseTheExactResult) {
    std::mt19937_64 rng(38);
    for (int trial = 0; trial < 200000; ++trial) {
        const double a = randomDouble(rng), b = randomDouble(rng);
        // Near magnitudes too, where sums cancel.
        const double c = trial % 2 ? -a * (1 + std::ldexp(double(rng() % 1000), -40)) : b;
        const Interval x = Interval::point(a), y = Interval::point(c);
        ASSERT_TRUE(encloses(x + y, exactSum(a, c))) << a << " + " << c;
        ASSERT_TRUE(encloses(x - y, exactSum(a, -c))) << a << " - " << c;
        ASSERT_TRUE(encloses(x * y, exactProduct(a, c))) << a << " * " << c;
        ASSERT_TRUE(encloses(c * x, exactProduct(c, a))) << c << " * " << a;
        ASSERT_TRUE(encloses(square(x), exactProduct(a, a))) << a << "^2";
        // Each bound is a few ulps from the exact result: outward, not loose.
        const Interval p = x * y;
        EXPECT_LE(p.width(), std::fabs(a * c) * 0x1p-48);
    }
}

TEST(Interval, ProductsHoldEveryProductOfTheirPoints) {
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> u(-2, 2), f(0, 1);
    for (int trial = 0; trial < 20000; ++trial) {
        const Interval x = Interval::hull(u(rng), u(rng)), y = Interval::hull(u(rng), u(rng));
        const Interval p = x * y, s = square(x);
        for (double a : {x.lo, x.hi, x.lo + f(rng) * x.width()})
            for (double b : {y.lo, y.hi, y.lo + f(rng) * y.width()}) {
                ASSERT_TRUE(encloses(p, exactProduct(a, b)));
                ASSERT_TRUE(encloses(s, exactProduct(a, a)));
            }
        // The square knows both factors are one number: never below 0.
        EXPECT_GE(s.lo, 0);
    }
}

TEST(Interval, LowerSquareIsALowerBound) {
    EXPECT_EQ(lowerSquare(Interval{-1, 2}), 0);
    EXPECT_LE(lowerSquare(Interval{3, 4}), 9);
    EXPECT_GT(lowerSquare(Interval{3, 4}), 9 * (1 - 1e-15));
    EXPECT_LE(lowerSquare(Interval{-4, -3}), 9);
    EXPECT_EQ(lowerSquare(Interval{NAN, 1}), 0);
}

Hypercomplex randomElement(std::mt19937_64& rng, int dimension, double scale) {
    std::uniform_real_distribution<double> u(-scale, scale);
    Hypercomplex a{};
    for (int i = 0; i < dimension; ++i)
        a[size_t(i)] = u(rng);
    return a;
}

// A box about `centre` of half-width `radius`, and a point in it.
IntervalElement boxAbout(const Hypercomplex& centre, double radius, int dimension) {
    IntervalElement box = pointBox(centre);
    for (int i = 0; i < dimension; ++i)
        box[size_t(i)] = {centre[size_t(i)] - radius, centre[size_t(i)] + radius};
    return box;
}
Hypercomplex pointIn(const IntervalElement& box, int dimension, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> f(0.05, 0.95);
    Hypercomplex a{};
    for (int i = 0; i < dimension; ++i)
        a[size_t(i)] = box[size_t(i)].lo + f(rng) * box[size_t(i)].width();
    return a;
}

// The product through the table in long double: 64-bit mantissas, 2^11 times finer than the
// intervals' margins, so a box that misses it is wrong, not merely tight.
std::array<long double, kMaxAlgebraDimension> fineProduct(const MultiplicationTable& table,
                                                          const Hypercomplex& a,
                                                          const Hypercomplex& b) {
    std::array<long double, kMaxAlgebraDimension> r{};
    for (int i = 0; i < table.dimension(); ++i)
        for (int j = 0; j < table.dimension(); ++j) {
            const BasisProduct p = table.product(i, j);
            r[size_t(p.index)] += p.sign * (long double)a[size_t(i)] * (long double)b[size_t(j)];
        }
    return r;
}

TEST(IntervalElement, ProductsAndSquaresHoldTheAlgebrasProducts) {
    std::mt19937_64 rng(7);
    for (Algebra algebra : allAlgebras()) {
        const MultiplicationTable& table = MultiplicationTable::of(algebra);
        const int d = table.dimension();
        for (int trial = 0; trial < 2000; ++trial) {
            const double radius = trial % 3 == 0 ? 0 : 0.3;
            const IntervalElement a = boxAbout(randomElement(rng, d, 1.5), radius, d);
            const IntervalElement b = boxAbout(randomElement(rng, d, 1.5), radius, d);
            const IntervalElement ab = multiply(table, a, b), aa = square(table, a);
            const Hypercomplex x = radius > 0 ? pointIn(a, d, rng) : Hypercomplex{};
            const Hypercomplex y = radius > 0 ? pointIn(b, d, rng) : Hypercomplex{};
            Hypercomplex px = x, py = y;
            if (radius == 0)
                for (int i = 0; i < d; ++i) {
                    px[size_t(i)] = a[size_t(i)].lo;
                    py[size_t(i)] = b[size_t(i)].lo;
                }
            const auto product = fineProduct(table, px, py), squared = fineProduct(table, px, px);
            for (int k = 0; k < d; ++k) {
                ASSERT_LE((long double)ab[size_t(k)].lo, product[size_t(k)])
                    << algebraName(algebra) << " component " << k;
                ASSERT_GE((long double)ab[size_t(k)].hi, product[size_t(k)]);
                ASSERT_LE((long double)aa[size_t(k)].lo, squared[size_t(k)])
                    << algebraName(algebra) << " square, component " << k;
                ASSERT_GE((long double)aa[size_t(k)].hi, squared[size_t(k)]);
                // The square is never wider than the product of the box with itself.
                EXPECT_LE(aa[size_t(k)].width(), multiply(table, a, a)[size_t(k)].width() + 1e-12);
            }
        }
    }
}

// z^2 + c with the default c, and the default scene's N and bailout 2.
HypercomplexFormula defaultQuadratic(Algebra algebra) {
    return HypercomplexFormula(Formula::parse("z^2 + c"), algebra,
                               Hypercomplex{-0.2, 0.6, 0.2, 0.2, 0, 0, 0, 0});
}
constexpr int kIterations = 12;
constexpr double kBailout = 2;

// Whether z_0 .. z_{N-1} all lie in the ball |z| <= bailout: membership in K_N, point by point.
bool inSet(const HypercomplexFormula& formula, Hypercomplex z, int iterations, double bailout) {
    for (int n = 0; n < iterations; ++n) {
        if (normSquared(z) > bailout * bailout) return false;
        z = formula.evaluate(z);
    }
    return true;
}

struct AlgebraFormula {
    Algebra algebra;
    std::string formula;
};

TEST(IntervalElement, ProgramsHoldTheirValuesOnEveryBox) {
    const std::vector<AlgebraFormula> cases = {
        {Algebra::kQuaternion, "z^2 + c"},
        {Algebra::kQuaternion, "(1+0.2i) z (1-0.1k) z + 0.1j z + c"},
        {Algebra::kQuaternion, "z^3 + 0.2j z^2 + c"},
        {Algebra::kBicomplex, "z^2 + c"},
        {Algebra::kBicomplex, "sin(z) + c"},
        {Algebra::kBicomplex, "exp(z) - 0.5 cosh(z) + c"},
        {Algebra::kBicomplex, "cos(z^2) + 0.3 sinh(z) + c"},
        {Algebra::kCoquaternion, "z^2 + c"},
        {Algebra::kCoquaternion, "i z^2 j + 0.5 z^3 - z + c"},
        {Algebra::kBiquaternion, "z^2 + c"},
        {Algebra::kBiquaternion, "z^4 - (z + 0.3j)^2 + c"},
        {Algebra::kOctonion, "z^2 + c"},
        {Algebra::kOctonion, "(i z) (z j) + z^5 + c"},
    };
    std::mt19937_64 rng(5);
    std::vector<IntervalElement> registers;
    for (const AlgebraFormula& test : cases) {
        const int d = algebraDimension(test.algebra);
        const Hypercomplex c = randomElement(rng, d, 0.5);
        const HypercomplexFormula formula(Formula::parse(test.formula), test.algebra, c);
        ASSERT_FALSE(withoutIntervalExtension(formula.program()));
        const MultiplicationTable& table = MultiplicationTable::of(test.algebra);
        for (int trial = 0; trial < 300; ++trial) {
            const IntervalElement box =
                boxAbout(randomElement(rng, d, 1.2), trial % 2 ? 0.05 : 0.002, d);
            const IntervalElement image = evaluateOnBox(formula.program(), table, box, registers);
            for (int point = 0; point < 8; ++point) {
                const Hypercomplex z = pointIn(box, d, rng);
                ASSERT_TRUE(boxContains(image, formula.evaluate(z), d))
                    << test.formula << " in " << algebraName(test.algebra);
            }
        }
    }
}

// exp, sin, cos, sinh and cosh have forms (function_forms.h); the others and real powers are
// named.
TEST(IntervalElement, FunctionsWithoutAFormAreNamed) {
    auto missing = [](const char* text) {
        const HypercomplexFormula formula(Formula::parse(text), Algebra::kBicomplex,
                                          Hypercomplex{0.2, 0.1});
        return withoutIntervalExtension(formula.program()).value_or("");
    };
    EXPECT_EQ(missing("sin(z) + exp(z) + cos(z) + sinh(z) + cosh(z) + c"), "");
    EXPECT_EQ(missing("sin(z) + log(z) + c"), "the function log");
    EXPECT_EQ(missing("tan(z) + c"), "the function tan");
    EXPECT_EQ(missing("z^2.5 + c"), "a real power");
}

// Boxes proven outside hold no point of K_N, and the proof decides most boxes of a ray's
// length away from the set.
TEST(IntervalElement, BoxesLeavingTheBallHoldNoPointOfTheSet) {
    std::mt19937_64 rng(11);
    std::vector<IntervalElement> registers;
    for (Algebra algebra : {Algebra::kCoquaternion, Algebra::kBiquaternion, Algebra::kOctonion,
                            Algebra::kBicomplex}) {
        const int d = algebraDimension(algebra);
        const HypercomplexFormula formula = defaultQuadratic(algebra);
        const MultiplicationTable& table = MultiplicationTable::of(algebra);
        int proven = 0, far = 0;
        for (int trial = 0; trial < 3000; ++trial) {
            const Hypercomplex centre = randomElement(rng, d, 2.0);
            const IntervalElement box = boxAbout(centre, 0.01, d);
            if (!boxLeavesBall(formula.program(), table, box, kIterations, kBailout, registers))
                continue;
            ++proven;
            for (int point = 0; point < 16; ++point)
                ASSERT_FALSE(inSet(formula, pointIn(box, d, rng), kIterations, kBailout))
                    << algebraName(algebra);
        }
        for (int trial = 0; trial < 200; ++trial) {
            // Wholly outside the ball: proven at the first iterate.
            Hypercomplex centre = randomElement(rng, d, 1.0);
            centre[0] = 2.5;
            far += boxLeavesBall(formula.program(), table, boxAbout(centre, 0.2, d), kIterations,
                                 kBailout, registers);
        }
        EXPECT_EQ(far, 200) << algebraName(algebra);
        EXPECT_GT(proven, 300) << algebraName(algebra);
    }
}

const std::vector<AlgebraFormula>& formulasOfEveryAlgebra() {
    static const std::vector<AlgebraFormula> cases = {
        {Algebra::kQuaternion, "z^2 + c"},
        {Algebra::kQuaternion, "(1+0.2i) z (1-0.1k) z + 0.1j z + c"},
        {Algebra::kBicomplex, "z^3 - 0.5 z + c"},
        {Algebra::kBicomplex, "sin(z) + c"},
        {Algebra::kBicomplex, "exp(z) - 0.5 cosh(z) + c"},
        {Algebra::kBicomplex, "cos(z^2) + 0.3 sinh(z) + c"},
        {Algebra::kCoquaternion, "z^2 + c"},
        {Algebra::kCoquaternion, "i z^2 j + 0.5 z^3 - z + c"},
        {Algebra::kBiquaternion, "z^2 + c"},
        {Algebra::kBiquaternion, "z^4 - (z + 0.3j)^2 + c"},
        {Algebra::kOctonion, "(i z) (z j) + z^5 + c"},
    };
    return cases;
}

// p of every point of a thickened segment lies in the image form at the same e (segment_form.h).
TEST(SegmentForm, ProgramsHoldTheirValuesAlongTheSegment) {
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> unit(-1, 1);
    for (const AlgebraFormula& test : formulasOfEveryAlgebra()) {
        const int d = algebraDimension(test.algebra);
        const HypercomplexFormula formula(Formula::parse(test.formula), test.algebra,
                                          randomElement(rng, d, 0.5));
        const MultiplicationTable& table = MultiplicationTable::of(test.algebra);
        for (int trial = 0; trial < 300; ++trial) {
            const Hypercomplex from = randomElement(rng, d, 1.2);
            Hypercomplex to = from;
            const double length = trial % 2 ? 0.5 : 0.02, thickness = trial % 3 ? 0 : 0.01;
            for (int k = 0; k < d; ++k)
                to[size_t(k)] += length * unit(rng);
            const SegmentForm form = segmentBetween(from, to, thickness, d);
            const SegmentForm image = evaluateOnSegment(formula.program(), table, form);
            for (int point = 0; point < 8; ++point) {
                const double e = point == 0 ? -1 : point == 1 ? 1 : unit(rng);
                Hypercomplex z{};
                for (int k = 0; k < d; ++k)
                    z[size_t(k)] =
                        form.centre[size_t(k)] + form.slope[size_t(k)] * e + thickness * unit(rng);
                ASSERT_TRUE(formContains(form, e, z, d));
                ASSERT_TRUE(formContains(image, e, formula.evaluate(z), d))
                    << test.formula << " in " << algebraName(test.algebra) << ", e = " << e;
            }
        }
    }
}

// Segments proven outside hold no point of K_N; and a segment's form proves more of them than
// the box about its ends, which cannot know that the points lie on a line.
TEST(SegmentForm, SegmentsLeavingTheBallHoldNoPointOfTheSet) {
    std::mt19937_64 rng(23);
    std::uniform_real_distribution<double> unit(-1, 1), f(0, 1);
    std::vector<IntervalElement> boxRegisters;
    for (Algebra algebra : {Algebra::kCoquaternion, Algebra::kBiquaternion, Algebra::kOctonion,
                            Algebra::kQuaternion}) {
        const int d = algebraDimension(algebra);
        const HypercomplexFormula formula = defaultQuadratic(algebra);
        const MultiplicationTable& table = MultiplicationTable::of(algebra);
        int bySegment = 0, byBox = 0;
        for (int trial = 0; trial < 3000; ++trial) {
            const Hypercomplex from = randomElement(rng, d, 1.2);
            Hypercomplex to = from;
            for (int k = 0; k < d; ++k)
                to[size_t(k)] += 0.4 * unit(rng);
            IntervalElement box = pointBox(from);
            for (int k = 0; k < d; ++k)
                box[size_t(k)] = Interval::hull(from[size_t(k)], to[size_t(k)]);
            byBox +=
                boxLeavesBall(formula.program(), table, box, kIterations, kBailout, boxRegisters);
            if (!segmentLeavesBall(formula.program(), table, segmentBetween(from, to, 0, d),
                                   kIterations, kBailout))
                continue;
            ++bySegment;
            for (int point = 0; point < 16; ++point)
                ASSERT_FALSE(inSet(formula, from + f(rng) * (to - from), kIterations, kBailout))
                    << algebraName(algebra);
        }
        // Of the segments their boxes leave undecided, the forms prove at least 15% (19% for
        // the coquaternions, 37 to 74% for the others when this was written).
        EXPECT_GE(bySegment - byBox, (3000 - byBox) * 15 / 100)
            << algebraName(algebra) << ": " << bySegment << " segments, " << byBox
            << " boxes proven";
    }
}

// A tube from a random point of components within `scale`, its segment's and its two across
// directions' components within `length` and `width`.
TubeForm randomTube(std::mt19937_64& rng, int d, double scale, double length, double width,
                    double thickness) {
    std::uniform_real_distribution<double> unit(-1, 1);
    const Hypercomplex from = randomElement(rng, d, scale);
    Hypercomplex to = from, across1{}, across2{};
    for (int k = 0; k < d; ++k) {
        to[size_t(k)] += length * unit(rng);
        across1[size_t(k)] = width * unit(rng);
        across2[size_t(k)] = width * unit(rng);
    }
    return tubeAbout(from, to, across1, across2, thickness, d);
}

// p of every point of a tube lies in the image form at the same symbols: the products of
// different symbols (e_s e_t, in the remainder) matter here, the tubes as wide as long.
TEST(TubeForm, ProgramsHoldTheirValuesOverTheTube) {
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> unit(-1, 1);
    for (const AlgebraFormula& test : formulasOfEveryAlgebra()) {
        if (test.algebra == Algebra::kBicomplex) continue;  // duplex forms: segments only
        const int d = algebraDimension(test.algebra);
        const HypercomplexFormula formula(Formula::parse(test.formula), test.algebra,
                                          randomElement(rng, d, 0.5));
        const MultiplicationTable& table = MultiplicationTable::of(test.algebra);
        for (int trial = 0; trial < 200; ++trial) {
            const double size = trial % 2 ? 0.3 : 0.02, thickness = trial % 3 ? 0 : 0.005;
            const TubeForm tube = randomTube(rng, d, 1.2, size, size, thickness);
            const TubeForm image = evaluateOnTube(formula.program(), table, tube);
            for (int point = 0; point < 16; ++point) {
                // The corners of the symbols' cube first, where the products of symbols peak.
                std::array<double, 3> e;
                for (size_t s = 0; s < 3; ++s)
                    e[s] = point < 8 ? ((point >> s) & 1 ? 1.0 : -1.0) : unit(rng);
                // Summed in tubeContains's order, so that only the thickness separates them.
                Hypercomplex z = tube.centre;
                for (int k = 0; k < d; ++k) {
                    for (size_t s = 0; s < 3; ++s)
                        z[size_t(k)] += tube.slopes[s][size_t(k)] * e[s];
                    z[size_t(k)] += thickness * unit(rng);
                }
                ASSERT_TRUE(tubeContains(tube, e, z, d));
                ASSERT_TRUE(tubeContains(image, e, formula.evaluate(z), d))
                    << test.formula << " in " << algebraName(test.algebra);
            }
        }
    }
}

// Tubes (three noise symbols) proven outside hold no point of K_N: points of the segment swept
// across both directions and thickened, sampled. The squares in these formulas are the table's
// symmetric square (form_arithmetic-inl.h), whose cancelled pairs add no remainder.
TEST(TubeForm, TubesLeavingTheBallHoldNoPointOfTheSet) {
    std::mt19937_64 rng(29);
    std::uniform_real_distribution<double> unit(-1, 1);
    const std::vector<std::pair<Algebra, std::string>> cases = {
        {Algebra::kCoquaternion, "z^2 + c"},     {Algebra::kCoquaternion, "i z^2 j + z^3 + c"},
        {Algebra::kBiquaternion, "z^2 + c"},     {Algebra::kBiquaternion, "(z + 0.3j)^2 + c"},
        {Algebra::kOctonion, "(i z) (z j) + c"}, {Algebra::kQuaternion, "z^4 + c"}};
    for (const auto& [algebra, text] : cases) {
        const int d = algebraDimension(algebra);
        const HypercomplexFormula formula(Formula::parse(text), algebra,
                                          randomElement(rng, d, 0.5));
        const MultiplicationTable& table = MultiplicationTable::of(algebra);
        int proven = 0;
        for (int trial = 0; trial < 1500; ++trial) {
            const double length = trial % 2 ? 0.3 : 0.03, width = trial % 3 ? 0.02 : 0.002;
            const double thickness = trial % 5 ? 0 : 1e-3;
            const TubeForm tube = randomTube(rng, d, 1.3, length, width, thickness);
            if (!tubeLeavesBall(formula.program(), table, tube, kIterations, kBailout)) continue;
            ++proven;
            for (int point = 0; point < 24; ++point) {
                Hypercomplex z = tube.centre;
                for (const Hypercomplex& slope : tube.slopes)
                    z = z + unit(rng) * slope;
                for (int k = 0; k < d; ++k)
                    z[size_t(k)] += thickness * unit(rng);
                ASSERT_FALSE(inSet(formula, z, kIterations, kBailout))
                    << text << " in " << algebraName(algebra);
            }
        }
        // Enough tubes proven, and not all, for the samples to test something.
        EXPECT_GT(proven, 150) << text << " in " << algebraName(algebra);
        EXPECT_LT(proven, 1500) << text << " in " << algebraName(algebra);
    }
}

}  // namespace
}  // namespace quaternia
