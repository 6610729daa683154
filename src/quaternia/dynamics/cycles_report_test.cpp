#include "quaternia/dynamics/cycles_report.h"

#include <gtest/gtest.h>

#include <complex>

#include "quaternia/scene/parameters.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

Scene cyclesScene(const std::string& formula, const Quaternion& c, int period) {
    Scene scene = defaultScene();
    scene.fractal.formula = formula;
    scene.fractal.c = c;
    scene.cycles.period = period;
    return scene;
}

std::complex<double> complexOf(const Json& pair) {
    return {pair[0].get<double>(), pair[1].get<double>()};
}

TEST(CyclesReport, MinusOneHasTheOne2CycleZeroMinusOneWithMultiplierZero) {
    // The points of exact period 2 of z^2 - 1 solve z^2 + z + c + 1 = z^2 + z = 0: the cycle
    // {0, -1}, multiplier 2z over the cycle: (2 * 0) * (2 * -1) = 0, superattracting.
    const CyclesReport report = cyclesReport(cyclesScene("z^2 + c", -1.0, 2));
    const Json json = toJson(report);
    EXPECT_EQ(json["command"], "cycles");
    EXPECT_EQ(json["period"], 2);
    EXPECT_EQ(json["points"], 2);
    ASSERT_EQ(json["cycles"].size(), 1u);
    const Json& cycle = json["cycles"][0];
    EXPECT_EQ(cycle["period"], 2);
    ASSERT_EQ(cycle["points"].size(), 2u);
    EXPECT_NEAR(std::abs(complexOf(cycle["points"][0]) - 0.0), 0, 1e-12);
    EXPECT_NEAR(std::abs(complexOf(cycle["points"][1]) - -1.0), 0, 1e-12);
    EXPECT_NEAR(std::abs(complexOf(cycle["multiplier"])), 0, 1e-12);
    EXPECT_EQ(cycle["class"], "superattracting");
    EXPECT_FALSE(cycle["degenerate"].get<bool>());
    EXPECT_EQ(toText(report),
              "z^2 + c with c = -1: 2 points of period 2 in 1 cycle\n"
              "   #  multiplier                   |multiplier|  class            points\n"
              "   1  0                            0             superattracting  0 -> -1\n");
}

TEST(CyclesReport, FixedPointMultipliersAreOnePlusOrMinusRootOfOneMinus4c) {
    // z^2 + c has fixed points (1 +- sqrt(1 - 4c)) / 2 with multipliers 1 +- sqrt(1 - 4c), in
    // the coordinates x + y u of the plane C_u that holds c (u = -i for c = -0.1-0.7i, so
    // there c reads -0.1+0.7i).
    for (const Quaternion& c : {Quaternion(-2), Quaternion(0.25, 0.5, 0, 0),
                                Quaternion(-0.1, -0.7, 0, 0), Quaternion(0.2, 0, 0.3, -0.4)}) {
        const Json json = toJson(cyclesReport(cyclesScene("z^2 + c", c, 1)));
        ASSERT_EQ(json["cycles"].size(), 2u) << c;
        const Json& axis = json["plane_axis"];
        const std::complex<double> inPlane(c.w, c.x * axis[1].get<double>() +
                                                    c.y * axis[2].get<double>() +
                                                    c.z * axis[3].get<double>());
        const std::complex<double> root = std::sqrt(1.0 - 4.0 * inPlane);
        std::vector<std::complex<double>> multipliers;
        for (const Json& cycle : json["cycles"])
            multipliers.push_back(complexOf(cycle["multiplier"]));
        if (std::abs(multipliers[0] - (1.0 + root)) > 1e-9)
            std::swap(multipliers[0], multipliers[1]);
        EXPECT_NEAR(std::abs(multipliers[0] - (1.0 + root)), 0, 1e-9) << c;
        EXPECT_NEAR(std::abs(multipliers[1] - (1.0 - root)), 0, 1e-9) << c;
    }
}

TEST(CyclesReport, AMapInAnotherPlaneIsTabledInItsCoordinates) {
    // c = j: the map is complex on C_j, and the table says in which plane x+yi stands.
    const CyclesReport report = cyclesReport(cyclesScene("z^2 + c", Quaternion(0, 0, 1, 0), 1));
    EXPECT_EQ(toJson(report)["plane_axis"], Json({0.0, 0.0, 1.0, 0.0}));
    EXPECT_NE(
        toText(report).find("(complex numbers x+yi stand for x + y u in the plane C_u, u = j)\n"),
        std::string::npos)
        << toText(report);
}

// The UserError that cyclesReport throws for `scene`, or a failure.
UserError reportError(const Scene& scene, const std::string& formulaName = "fractal.formula",
                      const std::string& periodName = "cycles.period") {
    try {
        cyclesReport(scene, formulaName, periodName);
    } catch (const UserError& e) {
        return e;
    }
    ADD_FAILURE() << "no UserError";
    return UserError("", "");
}

TEST(CyclesReport, RejectsAPeriodBeyondTheTableNamingCyclesPeriod) {
    // degree^period <= 1024: period 10 for a quadratic, but only 6 for a cubic (3^7 = 2187).
    UserError error = reportError(cyclesScene("z^3 + c", -1.0, 7));
    EXPECT_EQ(error.key(), "cycles.period");
    EXPECT_STREQ(error.what(),
                 "cycles.period must be at least 1 with degree^period <= 1024 (degree 3), got 7");
    EXPECT_EQ(reportError(cyclesScene("z^2 + c", -1.0, 0)).key(), "cycles.period");
    // A front end whose flag set the period names the flag.
    error = reportError(cyclesScene("z^3 + c", -1.0, 7), "fractal.formula", "--period");
    EXPECT_EQ(error.key(), "--period");
    EXPECT_TRUE(std::string(error.what()).starts_with("--period must be at least 1"))
        << error.what();
}

TEST(CyclesReport, RejectsAMapThatIsNotComplexAndOtherAlgebras) {
    // z^2 + j z + i: the coefficients j and i share no plane C_u.
    UserError error = reportError(cyclesScene("z^2 + j*z + c", Quaternion(0, 1, 0, 0), 1));
    EXPECT_EQ(error.key(), "fractal.formula");
    EXPECT_TRUE(std::string(error.what()).starts_with("fractal.formula: cycles needs a complex"))
        << error.what();
    Scene bicomplex = cyclesScene("z^2 + c", -1.0, 2);
    setParameter(bicomplex, "fractal.algebra", std::string("bicomplex"));
    EXPECT_EQ(reportError(bicomplex).key(), "fractal.algebra");
}

}  // namespace
}  // namespace quaternia
