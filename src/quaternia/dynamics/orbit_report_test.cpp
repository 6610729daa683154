#include "quaternia/dynamics/orbit_report.h"

#include <gtest/gtest.h>

#include "quaternia/scene/parameters.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

// The orbit of z0 under z^2 + c in the default scene otherwise.
Scene quadraticScene(const Quaternion& c, const Quaternion& z0 = 0.0) {
    Scene scene = defaultScene();
    scene.fractal.formula = "z^2 + c";
    scene.fractal.c = c;
    scene.orbit.z0 = z0;
    return scene;
}

TEST(OrbitReport, DefaultSceneEscapesWithItsCriticalOrbitSoKIsACantorSet) {
    // z0 = 0 is the critical point of z^2 + c: the orbit escapes exactly when the one critical
    // orbit does, at the same iteration, and then K is a Cantor set (docs/facts.md, Mandelbrot
    // set). The default c = -0.2+0.6i+0.2j+0.2k lies in one plane C_u, so K is decided there.
    const Json json = toJson(orbitReport(defaultScene()));
    EXPECT_EQ(json["command"], "orbit");
    EXPECT_FALSE(json.contains("algebra"));  // written for the other algebras only
    EXPECT_EQ(json["formula"], defaultScene().fractal.formula);
    EXPECT_EQ(json["c"], Json({-0.2, 0.6, 0.2, 0.2}));
    EXPECT_EQ(json["fate"], "escapes");
    ASSERT_TRUE(json["escape_iteration"].is_number_integer());
    EXPECT_GT(json["escape_iteration"].get<int>(), 0);
    EXPECT_TRUE(json["period"].is_null());
    EXPECT_TRUE(json["cycle"].is_null());
    const Json& k = json["connectedness"];
    EXPECT_FALSE(k["connected"].get<bool>());
    EXPECT_TRUE(k["cantor"].get<bool>());
    ASSERT_EQ(k["critical_orbits"].size(), 1u);
    EXPECT_EQ(k["critical_orbits"][0]["point"], Json({0.0, 0.0}));
    EXPECT_EQ(k["critical_orbits"][0]["escape_iteration"], json["escape_iteration"]);
}

TEST(OrbitReport, MinusOneHasTheSuperattracting2CycleZeroMinusOne) {
    // docs/facts.md: at c = -1 the critical orbit 0 -> -1 -> 0 is a 2-cycle with multiplier
    // (2 * 0) * (2 * -1) = 0.
    const OrbitReport report = orbitReport(quadraticScene(-1.0));
    const Json json = toJson(report);
    EXPECT_EQ(json["fate"], "periodic");
    EXPECT_EQ(json["period"], 2);
    EXPECT_EQ(json["class"], "superattracting");
    const Json& cycle = json["cycle"];
    EXPECT_EQ(cycle["points"], Json({Json({0.0, 0.0, 0.0, 0.0}), Json({-1.0, 0.0, 0.0, 0.0})}));
    EXPECT_EQ(cycle["multiplier"][0].get<double>(), 0.0);
    EXPECT_EQ(cycle["multiplier"][1].get<double>(), 0.0);
    EXPECT_EQ(cycle["class_in_h"], "superattracting");
    EXPECT_TRUE(json["connectedness"]["connected"].get<bool>());
    EXPECT_EQ(toText(report),
              "orbit of z0 = 0 under z^2 + c, c = -1\n"
              "fate: periodic with period 2\n"
              "cycle: 0 -> -1\n"
              "multiplier: 0 (|lambda| = 0), superattracting\n"
              "in H: Jacobian eigenvalues 0, 0, 0, 0, superattracting\n"
              "K: connected (critical orbit 0: periodic)\n");
}

TEST(OrbitReport, ZeroIsTheSuperattractingFixedPointOfZSquared) {
    const Json json = toJson(orbitReport(quadraticScene(0.0)));
    EXPECT_EQ(json["fate"], "periodic");
    EXPECT_EQ(json["period"], 1);
    EXPECT_EQ(json["cycle"]["points"], Json({Json({0.0, 0.0, 0.0, 0.0})}));
    EXPECT_EQ(std::abs(json["cycle"]["multiplier"][0].get<double>()), 0.0);
    EXPECT_EQ(json["class"], "superattracting");
}

TEST(OrbitReport, FixedPointMultiplierIsOnePlusOrMinusRootOfOneMinus4c) {
    // The fixed points of z^2 + c are (1 +- sqrt(1 - 4c)) / 2 with multipliers 2z = 1 +- sqrt(1 -
    // 4c). At c = -2: z = 2 (multiplier 4) and z = -1 (multiplier -2), both repelling; starting
    // on one, the orbit stays there.
    const Json json = toJson(orbitReport(quadraticScene(-2.0, -1.0)));
    EXPECT_EQ(json["fate"], "periodic");
    EXPECT_EQ(json["period"], 1);
    EXPECT_NEAR(json["cycle"]["multiplier"][0].get<double>(), 1 - std::sqrt(9.0), 1e-12);
    EXPECT_EQ(json["class"], "repelling");
}

TEST(OrbitReport, TextSaysWhenTheOrbitEscapes) {
    // c = 1: 0 -> 1 -> 2, beyond the escape radius (1 + sqrt 5) / 2 of z^2 + 1.
    const std::string text = toText(orbitReport(quadraticScene(1.0)));
    EXPECT_NE(text.find("fate: escapes at iteration 2 (|z| > escape radius 1.618033989)\n"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("K: a Cantor set (critical orbit 0: escapes)\n"), std::string::npos)
        << text;
}

TEST(OrbitReport, OtherAlgebrasAreNamedAndWriteAllOfC) {
    Scene scene = quadraticScene(-1.0);
    setParameter(scene, "fractal.algebra", std::string("octonion"));
    setParameter(scene, "fractal.c", std::vector<double>{-1, 0, 0, 0, 0, 0, 0, 0});
    const OrbitReport report = orbitReport(scene);
    const Json json = toJson(report);
    EXPECT_EQ(json["algebra"], "octonion");
    EXPECT_EQ(json["c"].size(), 8u);
    // The real line is a copy of C in every algebra: the same 2-cycle, its points with 8
    // components, the Jacobian 8 x 8.
    EXPECT_EQ(json["period"], 2);
    EXPECT_EQ(json["cycle"]["points"][1].size(), 8u);
    EXPECT_EQ(json["cycle"]["eigenvalues"].size(), 8u);
    const std::string text = toText(report);
    EXPECT_EQ(text.substr(0, text.find('\n')),
              "orbit of z0 = 0 under z^2 + c in the octonion algebra, c = [-1, 0, 0, 0, 0, 0, 0, "
              "0]");
    EXPECT_NE(text.find("in octonion (8x8): Jacobian eigenvalues"), std::string::npos) << text;
}

TEST(OrbitReport, RejectsAMapWithoutEscapeRadiusNamingTheGivenName) {
    Scene scene = quadraticScene(0.0);
    scene.fractal.formula = "z + c";
    try {
        orbitReport(scene);
        FAIL() << "z + c has no escape radius";
    } catch (const UserError& e) {
        EXPECT_EQ(e.key(), "fractal.formula");
        EXPECT_TRUE(std::string(e.what()).starts_with("fractal.formula")) << e.what();
    }
    scene.fractal.formula = "z^";
    try {
        orbitReport(scene, "--formula");
        FAIL() << "z^ does not parse";
    } catch (const UserError& e) {
        EXPECT_EQ(e.key(), "--formula");
        EXPECT_TRUE(std::string(e.what()).starts_with("--formula: ")) << e.what();
    }
}

}  // namespace
}  // namespace quaternia
