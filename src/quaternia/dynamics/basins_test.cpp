#include "quaternia/dynamics/basins.h"

#include <gtest/gtest.h>

#include <set>
#include <tuple>

namespace quaternia {
namespace {

ComplexPolynomial quadratic(Complex c) {
    return ComplexPolynomial({c, 0, 1});
}

PlaneView view(Complex centre, double width, int pixelWidth, int pixelHeight) {
    PlaneView v;
    v.centre = centre;
    v.width = width;
    v.pixelWidth = pixelWidth;
    v.pixelHeight = pixelHeight;
    return v;
}

// The colour of the basin of one point: a 1x1 image centred on it.
Rgba colourAt(const ComplexPolynomial& p, Complex z) {
    return renderBasins(p, view(z, 1e-9, 1, 1), {}).image.at(0, 0);
}

bool isGrey(const Rgba& c) {
    return c.r == c.g && c.g == c.b;
}

TEST(Basins, MinusOneHasOneTwoCycleWithTwoImmediateBasinsAndIsSymmetric) {
    ComplexPolynomial p = quadratic(-1);
    BasinOptions options;
    options.threads = 2;
    BasinImage basins = renderBasins(p, view(0, 4, 80, 60), options);
    EXPECT_TRUE(basins.completed);
    EXPECT_EQ(basins.attractingCycles, 1);
    EXPECT_EQ(basins.periods, std::vector<int>{2});
    std::set<std::tuple<float, float, float>> finite;
    int infinity = 0;
    for (int y = 0; y < 60; ++y) {
        for (int x = 0; x < 80; ++x) {
            const Rgba& c = basins.image.at(x, y);
            EXPECT_EQ(c.a, 1.0f);
            // z -> -z: f(-z) = f(z) exactly, and the pixel grid is symmetric about 0.
            EXPECT_EQ(c, basins.image.at(79 - x, 59 - y)) << x << ", " << y;
            if (isGrey(c)) {
                EXPECT_LE(c.r, 0.25f);  // infinity: no undecided pixel at this size
                ++infinity;
            } else {
                finite.insert({c.r, c.g, c.b});
            }
        }
    }
    EXPECT_EQ(finite.size(), 2u);  // the immediate basins of 0 and of -1
    EXPECT_GT(infinity, 0);
    // 0 and -1 lie in different immediate basins; 1 maps to 0, so at even times it follows -1.
    Rgba zero = colourAt(p, 0), minusOne = colourAt(p, -1);
    EXPECT_FALSE(isGrey(zero));
    EXPECT_NE(zero, minusOne);
    EXPECT_EQ(colourAt(p, 1), minusOne);
    EXPECT_TRUE(isGrey(colourAt(p, 1.7)));
}

TEST(Basins, RabbitHasThreeImmediateBasins) {
    ComplexPolynomial p = quadratic({-0.12256116687665, 0.74486176661974});
    EXPECT_EQ(renderBasins(p, view(0, 3, 4, 4), {}).periods, std::vector<int>{3});
    Complex c = p.coefficients()[0];
    std::set<std::tuple<float, float, float>> colours;
    for (Complex z : {Complex(0), c, c * c + c}) {
        Rgba colour = colourAt(p, z);
        EXPECT_FALSE(isGrey(colour));
        colours.insert({colour.r, colour.g, colour.b});
    }
    EXPECT_EQ(colours.size(), 3u);
}

TEST(Basins, OutsideTheMandelbrotSetEverythingEscapes) {
    BasinImage basins = renderBasins(quadratic(0.5), view(0, 4, 16, 16), {});
    EXPECT_EQ(basins.attractingCycles, 0);
    for (const Rgba& c : basins.image.pixels())
        EXPECT_TRUE(isGrey(c) && c.r <= 0.25f);
}

TEST(Basins, CancelledRenderReportsIncomplete) {
    std::atomic<bool> cancel{true};
    BasinOptions options;
    options.cancel = &cancel;
    EXPECT_FALSE(renderBasins(quadratic(-1), view(0, 4, 64, 64), options).completed);
}

TEST(Basins, SamplesAverageColours) {
    // A pixel straddling the basins of 0 and of infinity mixes them; one sample does not.
    ComplexPolynomial p = quadratic(-1);
    BasinOptions options;
    options.samples = 16;
    Rgba mixed = renderBasins(p, view(Complex(0, 0.6), 0.6, 1, 1), options).image.at(0, 0);
    EXPECT_EQ(mixed.a, 1.0f);
    EXPECT_FALSE(isGrey(mixed));
}

}  // namespace
}  // namespace quaternia
