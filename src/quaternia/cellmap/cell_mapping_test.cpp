#include "quaternia/cellmap/cell_mapping.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <random>
#include <stdexcept>
#include <vector>

#include "quaternia/algebra/quaternion.h"
#include "quaternia/cellmap/box_maps.h"
#include "quaternia/cellmap/cell_grid.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

using Complex = std::complex<double>;
constexpr uint8_t kOut = uint8_t(CellClass::kOutside), kIn = uint8_t(CellClass::kInside),
                  kUnd = uint8_t(CellClass::kUndecided);

Box3 box2(double x0, double x1, double y0, double y1) {
    return {Interval{x0, x1}, Interval{y0, y1}, Interval{0, 0}};
}

// Whether the orbit of (x, y) under z^2 + c leaves the disc of radius R within n steps (long
// double). Staying: never beyond R in n steps, or the rounded orbit repeats exactly (Brent's
// cycle detection), after which it stays forever among the values already seen.
bool orbitEscapes(long double x, long double y, Complex c, long double R, int n) {
    for (int k = 0; k < n; ++k) {
        const long double nx = x * x - y * y + c.real();
        y = 2 * x * y + c.imag(), x = nx;
        if (x * x + y * y > R * R) return true;
    }
    return false;
}
bool orbitStays(long double x, long double y, Complex c, long double R, int n) {
    long double sx = x, sy = y;
    for (int k = 0, power = 1, lambda = 0; k < n; ++k) {
        const long double nx = x * x - y * y + c.real();
        y = 2 * x * y + c.imag(), x = nx;
        if (x * x + y * y > R * R) return false;
        if (x == sx && y == sy) return true;
        if (++lambda == power) sx = x, sy = y, power *= 2, lambda = 0;
    }
    return true;
}

struct Leaf {
    int level;
    CellIndex cell;
    uint8_t value;
};
void collectLeaves(const CellGrid& g, int level, const CellIndex& c, std::vector<Leaf>& out) {
    const uint8_t v = g.valueAt(level, c);
    if (v == kRefined && level + 1 < g.levels()) {
        for (int n = 0; n < 4; ++n)
            collectLeaves(g, level + 1, {2 * c[0] + (n & 1), 2 * c[1] + (n >> 1), 0}, out);
        return;
    }
    out.push_back({level, c, v});
}
std::vector<Leaf> leaves(const CellGrid& g) {
    std::vector<Leaf> out;
    for (int64_t j = 0; j < g.cellsAt(0, 1); ++j)
        for (int64_t i = 0; i < g.cellsAt(0, 0); ++i)
            collectLeaves(g, 0, {i, j, 0}, out);
    return out;
}

double radiusOf(Complex c) {
    return escapeRadiusOfModuli({std::abs(c), 0, 1});
}

// z^2 + c on [-2, 2]^2, 64 x 64 cells at level 0, refined everywhere down to level 3.
CellGrid classifyQuadratic(Complex c, int threads, CellMappingReport* report = nullptr) {
    CellGrid grid(2, {-2, -2, 0}, {4.0 / 64, 4.0 / 64, 1}, {64, 64, 1}, 1, CellClass::kUndecided);
    CellMappingOptions options;
    options.finestLevel = 3;
    options.work.threads = threads;
    const CellMappingReport r =
        classifyCells(grid, complexPolynomialBoxMap({c, 0, 1}, 0, 0, radiusOf(c)), options);
    if (report) *report = r;
    return grid;
}

// Every outside cell's centre and corners escape; every inside cell's (at most ~2000 of them,
// a fixed stride) stay for 10^5 steps. Returns the numbers of outside and inside leaves.
std::pair<int64_t, int64_t> expectCellsAgreeWithOrbits(Complex c) {
    CellMappingReport report;
    const CellGrid grid = classifyQuadratic(c, 2, &report);
    EXPECT_TRUE(report.completed);
    const long double R = radiusOf(c);
    std::vector<Leaf> outside, inside;
    for (const Leaf& leaf : leaves(grid))
        if (leaf.value == kOut)
            outside.push_back(leaf);
        else if (leaf.value == kIn)
            inside.push_back(leaf);
    const size_t stride = std::max<size_t>(1, inside.size() / 2000);
    int wrong = 0;
    auto check = [&](const Leaf& l, bool out) {
        const double x0 = grid.cellLower(l.level, 0, l.cell[0]);
        const double x1 = grid.cellLower(l.level, 0, l.cell[0] + 1);
        const double y0 = grid.cellLower(l.level, 1, l.cell[1]);
        const double y1 = grid.cellLower(l.level, 1, l.cell[1] + 1);
        const double xs[5] = {0.5 * (x0 + x1), x0, x1, x0, x1};
        const double ys[5] = {0.5 * (y0 + y1), y0, y0, y1, y1};
        for (int p = 0; p < 5; ++p) {
            const bool right = out ? orbitEscapes(xs[p], ys[p], c, R, 100000)
                                   : orbitStays(xs[p], ys[p], c, R, 100000);
            if (!right && wrong++ < 5)
                ADD_FAILURE() << "c = " << c << ": " << (out ? "outside" : "inside")
                              << " cell level " << l.level << " (" << l.cell[0] << ", " << l.cell[1]
                              << "), point (" << xs[p] << ", " << ys[p] << ")";
        }
    };
    for (const Leaf& l : outside)
        check(l, true);
    for (size_t n = 0; n < inside.size(); n += stride)
        check(inside[n], false);
    EXPECT_EQ(wrong, 0);
    return {int64_t(outside.size()), int64_t(inside.size())};
}

TEST(CellGrid, RefineAndValueAtFallBackToTheAncestor) {
    // 64 cells at level 0: level 1 has 2 x 2 tiles, so refining (0, 0) leaves tile (1, 1) unmade.
    CellGrid grid(2, {0, 0, 0}, {1, 1, 1}, {64, 64, 1}, 1, CellClass::kOutside);
    grid.setValue(0, {40, 41, 0}, kIn);
    grid.setValue(0, {1, 0, 0}, kIn);
    grid.refine(0, {0, 0, 0});
    EXPECT_EQ(grid.levels(), 2);
    EXPECT_EQ(grid.valueAt(0, {0, 0, 0}), kRefined);
    for (int64_t n = 0; n < 4; ++n)
        EXPECT_EQ(grid.valueAt(1, {n & 1, n >> 1, 0}), kUnd);
    EXPECT_EQ(grid.valueAt(1, {2, 1, 0}), kIn);  // in the new tile: its parent's class
    EXPECT_EQ(grid.valueAt(1, {4, 0, 0}), kOut);
    EXPECT_EQ(grid.cellSlot(1, {80, 83, 0}), -1);  // no tile there
    EXPECT_EQ(grid.valueAt(1, {80, 83, 0}), kIn);  // the ancestor (40, 41)
    EXPECT_EQ(grid.valueAt(1, {82, 83, 0}), kOut);
    EXPECT_EQ(grid.valueAt(5, {40 << 5, 41 << 5, 0}), kIn);  // below the finest level made
    grid.setValue(1, {1, 1, 0}, kIn);
    EXPECT_EQ(grid.valueAt(4, {15, 15, 0}), kIn);
    EXPECT_EQ(grid.valueAt(4, {0, 0, 0}), kUnd);
    EXPECT_DOUBLE_EQ(grid.cellSize(1, 0), 0.5);
    EXPECT_DOUBLE_EQ(grid.cellLower(1, 1, 3), 1.5);
    EXPECT_THROW(grid.setValue(1, {100, 100, 0}, kIn), std::logic_error);
}

// [0, 8]^2 in unit cells: columns 0 and 1 outside, the rest inside, cell (5, 5) refined with
// children inside but for (10, 11), outside.
CellGrid mixedGrid() {
    CellGrid grid(2, {0, 0, 0}, {1, 1, 1}, {8, 8, 1}, 1, CellClass::kInside);
    for (int64_t j = 0; j < 8; ++j)
        grid.setValue(0, {0, j, 0}, kOut), grid.setValue(0, {1, j, 0}, kOut);
    grid.refine(0, {5, 5, 0});
    for (int64_t n = 0; n < 4; ++n)
        grid.setValue(1, {10 + (n & 1), 10 + (n >> 1), 0}, kIn);
    grid.setValue(1, {10, 11, 0}, kOut);
    return grid;
}

TEST(CellGrid, ClassOfBoxOverMixedClasses) {
    const CellGrid grid = mixedGrid();
    EXPECT_EQ(grid.classOfBox(box2(4.2, 5.8, 1.2, 2.8), false), CellClass::kInside);
    EXPECT_EQ(grid.classOfBox(box2(0.2, 1.8, 0.2, 7.8), false), CellClass::kOutside);
    EXPECT_EQ(grid.classOfBox(box2(1.5, 2.5, 3, 3.5), false), CellClass::kUndecided);
    // A bound on a cell boundary touches both cells.
    EXPECT_EQ(grid.classOfBox(box2(2, 2, 3.2, 3.5), false), CellClass::kUndecided);
    EXPECT_EQ(grid.classOfBox(box2(2.01, 2.5, 3.2, 3.5), false), CellClass::kInside);
    // Beyond the grid: outside only where the grid holds the escape ball.
    EXPECT_EQ(grid.classOfBox(box2(-1, 0.5, 2, 3), true), CellClass::kOutside);
    EXPECT_EQ(grid.classOfBox(box2(-1, 0.5, 2, 3), false), CellClass::kUndecided);
    EXPECT_EQ(grid.classOfBox(box2(6.5, 9, 2, 3), true), CellClass::kUndecided);
    EXPECT_EQ(grid.classOfBox(box2(10, 11, 2, 3), true), CellClass::kOutside);
    // Into the refined cell.
    EXPECT_EQ(grid.classOfBox(box2(5.1, 5.4, 5.1, 5.4), false), CellClass::kInside);
    EXPECT_EQ(grid.classOfBox(box2(5.1, 5.4, 5.6, 5.9), false), CellClass::kOutside);
    EXPECT_EQ(grid.classOfBox(box2(5.1, 5.9, 5.1, 5.4), false), CellClass::kInside);
    EXPECT_EQ(grid.classOfBox(box2(4.5, 5.9, 5.1, 5.4), false), CellClass::kInside);
    EXPECT_EQ(grid.classOfBox(box2(5.1, 5.4, 5.1, 5.9), false), CellClass::kUndecided);
    EXPECT_EQ(grid.classOfBox(box2(5.1, 5.4, 5.6, 6.4), false), CellClass::kUndecided);
}

TEST(CellGrid, CensusCountsLeavesAndTheirAreas) {
    CellGrid grid = mixedGrid();
    CellGrid::Census census = grid.census();
    EXPECT_EQ(census.outside, 16 + 1);
    EXPECT_EQ(census.inside, 47 + 3);
    EXPECT_EQ(census.undecided, 0);
    EXPECT_DOUBLE_EQ(census.outsideVolume, 16.25);
    EXPECT_DOUBLE_EQ(census.insideVolume, 47.75);
    grid.setValue(1, {11, 11, 0}, kUnd);
    grid.refine(0, {7, 7, 0});  // four undecided children of a quarter each
    census = grid.census();
    EXPECT_EQ(census.inside, 46 + 2);
    EXPECT_EQ(census.undecided, 1 + 4);
    EXPECT_DOUBLE_EQ(census.undecidedVolume, 1.25);
    EXPECT_DOUBLE_EQ(census.outsideVolume + census.insideVolume + census.undecidedVolume, 64);
}

TEST(CellGrid, SerialisationRoundTripsAndRefusesTruncatedBytes) {
    const CellGrid grid = classifyQuadratic({-1, 0}, 2);
    std::vector<uint8_t> bytes;
    grid.appendTo(bytes);
    const uint8_t* at = bytes.data();
    const CellGrid read = CellGrid::readFrom(at, bytes.data() + bytes.size());
    EXPECT_EQ(at, bytes.data() + bytes.size());
    ASSERT_EQ(read.levels(), grid.levels());
    const CellGrid::Census a = grid.census(), b = read.census();
    EXPECT_EQ(std::tie(a.outside, a.inside, a.undecided),
              std::tie(b.outside, b.inside, b.undecided));
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> centre(-2.3, 2.3), exponent(-3, 0);
    std::map<CellClass, int> seen;
    for (int n = 0; n < 3000; ++n) {
        const double x = centre(random), y = centre(random);
        const double w = std::pow(10.0, exponent(random)), h = std::pow(10.0, exponent(random));
        const Box3 box = box2(x, x + w, y, y + h);
        for (bool beyond : {false, true}) {
            const CellClass c = grid.classOfBox(box, beyond);
            ++seen[c];
            ASSERT_EQ(read.classOfBox(box, beyond), c) << x << " " << y << " " << w << " " << h;
        }
    }
    EXPECT_GT(seen[CellClass::kInside], 0);
    EXPECT_GT(seen[CellClass::kOutside], 0);
    EXPECT_GT(seen[CellClass::kUndecided], 0);
    // Every prefix short of the whole record is refused (a stride of them past the header).
    for (size_t length = 0; length < bytes.size(); length += length < 200 ? 1 : 997) {
        std::vector<uint8_t> part(bytes.begin(), bytes.begin() + ptrdiff_t(length));
        const uint8_t* p = part.data();
        EXPECT_THROW(CellGrid::readFrom(p, part.data() + part.size()), std::runtime_error)
            << length;
    }
    std::vector<uint8_t> part(bytes.begin(), bytes.end() - 1);
    const uint8_t* p = part.data();
    EXPECT_THROW(CellGrid::readFrom(p, part.data() + part.size()), std::runtime_error);
    std::vector<uint8_t> damaged = bytes;
    damaged[0] = 7;  // dimension 7
    p = damaged.data();
    EXPECT_THROW(CellGrid::readFrom(p, damaged.data() + damaged.size()), std::runtime_error);
}

TEST(CellMapping, EscapeRadiusOfTheQuadratic) {
    for (double modulus : {0.0, 0.25, 0.7746, 1.0, 2.0, 10.0, 1e6}) {
        const double exact = (1 + std::sqrt(1 + 4 * modulus)) / 2;
        const double radius = escapeRadiusOfModuli({modulus, 0, 1});
        EXPECT_GE(radius, exact) << modulus;  // rounded up
        EXPECT_LE(radius, exact * (1 + 2e-9)) << modulus;
    }
    EXPECT_THROW(escapeRadiusOfModuli({0.5, 1}), UserError);
    EXPECT_THROW(escapeRadiusOfModuli({1}), UserError);
    EXPECT_THROW(escapeRadiusOfModuli({0.5, 0, 0}), UserError);  // the degree-2 term is 0
}

TEST(CellMapping, ComplexBoxImageHoldsThePolynomialOfItsPoints) {
    const std::vector<std::vector<Complex>> polynomials = {{{-0.122561, 0.744862}, 0, 1},
                                                           {{0.3, -0.2}, {-0.5, 0.1}, {0, 0.7}, 1}};
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> corner(-1.5, 1.5), unit(0, 1), exponent(-4, -0.3);
    for (const auto& p : polynomials)
        for (double degrees : {0.0, 30.0})
            for (Complex origin : {Complex(0, 0), Complex(0.1, -0.2)}) {
                const BoxMap map = complexPolynomialBoxMap(p, origin, degrees, 2.0);
                const long double angle = degrees * 3.14159265358979323846264338327950L / 180;
                const std::complex<long double> turn(std::cos(angle), std::sin(angle));
                for (int n = 0; n < 300; ++n) {
                    const double x0 = corner(random), y0 = corner(random);
                    const double w = std::pow(10.0, exponent(random));
                    const double h = std::pow(10.0, exponent(random));
                    const Box3 box = box2(x0, x0 + w, y0, y0 + h);
                    const Box3 image = map.image(box);
                    for (int k = 0; k < 12; ++k) {
                        const double u = k < 4 ? x0 + (k & 1) * w : x0 + unit(random) * w;
                        const double v = k < 4 ? y0 + (k >> 1) * h : y0 + unit(random) * h;
                        const std::complex<long double> o(origin.real(), origin.imag());
                        const std::complex<long double> z =
                            o + turn * std::complex<long double>(u, v);
                        std::complex<long double> value(p.back().real(), p.back().imag());
                        for (size_t m = p.size() - 1; m-- > 0;)
                            value = value * z + std::complex<long double>(p[m].real(), p[m].imag());
                        const std::complex<long double> q = (value - o) / turn;
                        const double slack = 1e-12 * (1 + double(std::abs(q)));
                        ASSERT_TRUE(
                            image[0].lo - slack <= q.real() && q.real() <= image[0].hi + slack &&
                            image[1].lo - slack <= q.imag() && q.imag() <= image[1].hi + slack)
                            << "rotation " << degrees << " box (" << x0 << ", " << y0 << ") + ("
                            << w << ", " << h << ") point (" << u << ", " << v << ")";
                    }
                }
                // escapes: true only beyond the radius, and not vacuous.
                EXPECT_FALSE(map.escapes(box2(-0.1, 0.1, -0.1, 0.1)));
                EXPECT_FALSE(map.escapes(box2(1.5, 2.5, -0.5, 0.5)));
                EXPECT_TRUE(map.escapes(box2(3, 3.5, 3, 3.5)));
            }
}

TEST(CellMapping, IterateImageHoldsTheIteratesOfItsPoints) {
    // f^k's box by the mean value form (BoxMap::iterateImage) against long double iterates.
    const std::vector<std::vector<Complex>> polynomials = {{{-0.122561, 0.744862}, 0, 1},
                                                           {{0.3, -0.2}, {-0.5, 0.1}, {0, 0.7}, 1}};
    std::mt19937_64 random(12);
    std::uniform_real_distribution<double> corner(-1.2, 1.2), unit(0, 1), exponent(-6, -1.5);
    for (const auto& p : polynomials)
        for (double degrees : {0.0, 30.0})
            for (int iterates : {2, 3}) {
                const Complex origin(0.1, -0.2);
                const BoxMap map = complexPolynomialBoxMap(p, origin, degrees, 2.0);
                ASSERT_TRUE(map.iterateImage);
                const long double angle = degrees * 3.14159265358979323846264338327950L / 180;
                const std::complex<long double> turn(std::cos(angle), std::sin(angle));
                const std::complex<long double> o(origin.real(), origin.imag());
                int tight = 0, small = 0;
                for (int n = 0; n < 300; ++n) {
                    const double x0 = corner(random), y0 = corner(random);
                    const double w = std::pow(10.0, exponent(random));
                    const Box3 box = box2(x0, x0 + w, y0, y0 + w);
                    const Box3 image = map.iterateImage(box, iterates);
                    long double lowest = INFINITY, highest = -INFINITY;
                    for (int k = 0; k < 12; ++k) {
                        const double u = k < 4 ? x0 + (k & 1) * w : x0 + unit(random) * w;
                        const double v = k < 4 ? y0 + (k >> 1) * w : y0 + unit(random) * w;
                        std::complex<long double> z = o + turn * std::complex<long double>(u, v);
                        for (int j = 0; j < iterates; ++j) {
                            std::complex<long double> value(p.back().real(), p.back().imag());
                            for (size_t m = p.size() - 1; m-- > 0;)
                                value =
                                    value * z + std::complex<long double>(p[m].real(), p[m].imag());
                            z = value;
                        }
                        const std::complex<long double> q = (z - o) / turn;
                        if (std::abs(q) > 1e6) continue;  // escaped far: nothing to compare
                        lowest = std::min(lowest, q.real()), highest = std::max(highest, q.real());
                        ASSERT_TRUE(image[0].lo <= q.real() && q.real() <= image[0].hi &&
                                    image[1].lo <= q.imag() && q.imag() <= image[1].hi)
                            << "f^" << iterates << " rotation " << degrees << " box (" << x0 << ", "
                            << y0 << ") + " << w << " point (" << u << ", " << v << ")";
                    }
                    // Not vacuous: a small box's image is a few times the spread of its points'
                    // images (the corners' among them), as a turned square's box is.
                    if (w < 1e-3 && highest > lowest) {
                        ++small;
                        tight += image[0].width() < 4 * double(highest - lowest);
                    }
                }
                EXPECT_GT(small, 100);
                EXPECT_GE(tight, small * 9 / 10);
            }
}

Quaternion polynomialOf(const std::vector<double>& coefficients, const Quaternion& z) {
    Quaternion p(coefficients.back());
    for (size_t k = coefficients.size() - 1; k-- > 0;)
        p = p * z + Quaternion(coefficients[k]);
    return p;
}

std::array<double, 3> reduced(const Quaternion& q, const Quaternion& n) {
    const double a = q.x * n.x + q.y * n.y + q.z * n.z;
    const double wx = q.x - a * n.x, wy = q.y - a * n.y, wz = q.z - a * n.z;
    return {q.w, a, std::sqrt(wx * wx + wy * wy + wz * wz)};
}

TEST(CellMapping, ReducedMapAgreesWithQuaternionArithmetic) {
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> component(-1.2, 1.2), unit(0, 1), exponent(-5, -1);
    for (const std::vector<double>& coefficients :
         {std::vector<double>{0, 0, 1}, std::vector<double>{0.1, 0, -0.3, 1}}) {
        for (int trial = 0; trial < 200; ++trial) {
            Quaternion n(0, component(random), component(random), component(random));
            const double length = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
            n = Quaternion(0, n.x / length, n.y / length, n.z / length);
            const double c0 = component(random), s = unit(random);
            const Quaternion c(c0, s * n.x, s * n.y, s * n.z);
            const Quaternion z(component(random), component(random), component(random),
                               component(random));
            const std::array<double, 3> expected = reduced(polynomialOf(coefficients, z) + c, n);
            const std::array<double, 3> xar = reduced(z, n);
            const std::array<double, 3> got = reducedPolynomialStep(coefficients, c0, s, xar);
            for (int a = 0; a < 3; ++a)
                ASSERT_NEAR(got[size_t(a)], expected[size_t(a)], 1e-12) << "axis " << a;
            const BoxMap map = reducedPolynomialBoxMap(coefficients, c0, s, 4.0);
            Box3 box;
            for (int a = 0; a < 3; ++a) {
                const double below = unit(random) * std::pow(10.0, exponent(random));
                const double above = unit(random) * std::pow(10.0, exponent(random));
                box[size_t(a)] = {xar[size_t(a)] - below, xar[size_t(a)] + above};
            }
            const Box3 image = map.image(box);
            const Box3 point = map.image(
                {Interval::point(xar[0]), Interval::point(xar[1]), Interval::point(xar[2])});
            for (int a = 0; a < 3; ++a) {
                EXPECT_LE(image[size_t(a)].lo, expected[size_t(a)] + 1e-12) << a;
                EXPECT_GE(image[size_t(a)].hi, expected[size_t(a)] - 1e-12) << a;
                EXPECT_LT(point[size_t(a)].width(), 1e-12) << a;  // a point maps to a point
            }
            EXPECT_GE(image[2].lo, 0);
        }
    }
}

TEST(CellMapping, BasilicaAndRabbitCellsAgreeWithOrbits) {
    for (Complex c : {Complex(-1, 0), Complex(-0.122561, 0.744862)}) {
        const auto [outside, inside] = expectCellsAgreeWithOrbits(c);
        EXPECT_GT(outside, 1000) << c;
        EXPECT_GT(inside, 100) << c;
    }
}

TEST(CellMapping, CantorSetHasNoInsideCells) {
    // 0.3 + 0.6i lies outside the Mandelbrot set (the critical orbit leaves |z| > 2 at step
    // 15): K has no interior, so no cell may be proven inside. (0.3 + 0.5i would not do: it lies
    // in the period-4 bulb, with an attracting 4-cycle.)
    const auto [outside, inside] = expectCellsAgreeWithOrbits({0.3, 0.6});
    EXPECT_GT(outside, 1000);
    EXPECT_EQ(inside, 0);
    const CellGrid::Census census = classifyQuadratic({0.3, 0.6}, 2).census();
    EXPECT_EQ(census.inside, 0);
    EXPECT_GT(census.undecided, 0);  // J is not empty
}

TEST(CellMapping, ClassesDoNotDependOnTheThreads) {
    for (Complex c : {Complex(-1, 0), Complex(-0.122561, 0.744862)}) {
        const CellGrid one = classifyQuadratic(c, 1), two = classifyQuadratic(c, 2);
        const CellGrid::Census a = one.census(), b = two.census();
        EXPECT_EQ(std::tie(a.outside, a.inside, a.undecided),
                  std::tie(b.outside, b.inside, b.undecided));
        EXPECT_GT(a.inside, 0);
        std::vector<uint8_t> pixelsOne, pixelsTwo;
        for (int64_t j = 0; j < one.cellsAt(3, 1); ++j)
            for (int64_t i = 0; i < one.cellsAt(3, 0); ++i) {
                pixelsOne.push_back(one.valueAt(3, {i, j, 0}));
                pixelsTwo.push_back(two.valueAt(3, {i, j, 0}));
            }
        EXPECT_TRUE(pixelsOne == pixelsTwo) << c;
    }
}

}  // namespace
}  // namespace quaternia
