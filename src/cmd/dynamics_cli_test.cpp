// `quaternia orbit` and `quaternia cycles` as a user meets them: the facts of docs/facts.md
// (Cycles and multipliers of z^2 + c) in text and JSON, and bad input as one line with exit code 2.
#include "cmd/cli_fixture.h"
#include "quaternia/scene/json.h"

namespace quaternia {
namespace {

namespace fs = std::filesystem;
using testing::CommandResult;

class DynamicsCli : public testing::CliFixture {
  protected:
    // Runs a command that must succeed and returns its standard output.
    std::string ok(const std::string& arguments) {
        CommandResult r = run(arguments);
        EXPECT_EQ(r.exitCode, 0) << arguments << ": " << r.err;
        EXPECT_TRUE(r.err.empty()) << r.err;
        return r.out;
    }
};

void expectHas(const std::string& text, const std::string& needle) {
    EXPECT_NE(text.find(needle), std::string::npos) << "'" << needle << "' in:\n" << text;
}

TEST_F(DynamicsCli, OrbitOfMinusOneIsSuperattracting2Cycle) {
    std::string out = ok("orbit --c -1");
    expectHas(out, "fate: periodic with period 2");
    expectHas(out, "cycle: 0 -> -1");
    expectHas(out, "multiplier: 0 (|lambda| = 0), superattracting");
    expectHas(out, "K: connected");
    Json json = Json::parse(ok("orbit --c -1 --json"));
    EXPECT_EQ(json["fate"], "periodic") << json;
    EXPECT_EQ(json["cycle"]["period"], 2) << json;
    EXPECT_EQ(json["cycle"]["points"], Json::parse("[[0, 0, 0, 0], [-1, 0, 0, 0]]")) << json;
    EXPECT_EQ(json["connectedness"]["connected"], true) << json;
    EXPECT_EQ(json["connectedness"]["cantor"], false) << json;
}

TEST_F(DynamicsCli, OrbitOfIIsStrictlyPreperiodicAndSaddleFixedPoint) {
    std::string out = ok("orbit --c i");
    expectHas(out, "strictly preperiodic with preperiod 2 and period 2");
    expectHas(out, "cycle: -1+i -> -i");
    expectHas(out, "multiplier: 4+4i (|lambda| = 5.656854249), repelling");
    // The fixed point (1 - sqrt(1 - 4i)) / 2 to 17 digits: a saddle in H.
    std::string saddle = ok("orbit --c i --z0 '-0.30024259022012045+0.6248105338438266i'");
    expectHas(saddle, "fate: fixed point");
    expectHas(saddle, "|lambda| = 1.386410929), repelling");
    expectHas(saddle, "-0.6004851804, -0.6004851804, saddle");
}

TEST_F(DynamicsCli, OrbitInQuaternionSliceAndEscape) {
    Json rabbit =
        Json::parse(ok("orbit --c '-0.12256116687665+0.74486176661974i' --z0 "
                       "'0.05+0.02i+0.03j' --json"));
    EXPECT_EQ(rabbit["fate"], "attracted") << rabbit;
    EXPECT_EQ(rabbit["period"], 3) << rabbit;
    EXPECT_EQ(rabbit["cycle"]["class_in_h"], "superattracting") << rabbit;
    std::string escape = ok("orbit --c 1");
    expectHas(escape, "escapes at iteration 2");
    expectHas(escape, "K: a Cantor set");
}

TEST_F(DynamicsCli, CyclesOfMinusOne) {
    std::string fixed = ok("cycles --c -1 --period 1");
    expectHas(fixed, "2 points of period 1 in 2 cycles");
    expectHas(fixed, "3.236067977                  3.236067977   repelling        1.618033989");
    expectHas(fixed, "-1.236067977                 1.236067977   repelling        -0.6180339887");
    Json two = Json::parse(ok("cycles --c -1 --period 2 --json"));
    ASSERT_EQ(two["cycles"].size(), 1u) << two;
    EXPECT_EQ(two["cycles"][0]["period"], 2) << two;
    EXPECT_EQ(two["cycles"][0]["points"], Json::parse("[[0, 0], [-1, 0]]")) << two;
    EXPECT_EQ(two["cycles"][0]["class"], "superattracting") << two;
}

TEST_F(DynamicsCli, CyclesOfIAndInPlaneOfJ) {
    expectHas(ok("cycles --c i --period 2"),
              "4+4i                         5.656854249   "
              "repelling        -i -> -1+i");
    // c in C_j: the same cycle, written in the coordinates of C_j.
    std::string j = ok("cycles --c j --period 2");
    expectHas(j, "u = j");
    expectHas(j, "-i -> -1+i");
}

TEST_F(DynamicsCli, WithoutFlagsTheMapIsTheDefaultScenes) {
    // fractal.c's default, -0.2+0.6i+0.2j+0.2k, not 0: the commands read the scene.
    expectHas(ok("orbit"), "orbit of z0 = 0 under z^2 + c, c = -0.2+0.6i+0.2j+0.2k\n");
    EXPECT_EQ(Json::parse(ok("orbit --json"))["max_iterations"], 1000);
    expectHas(ok("cycles"), "z^2 + c with c = -0.2+0.6i+0.2j+0.2k: 2 points of period 1");
}

TEST_F(DynamicsCli, SceneFileAndSetDriveOrbitAndCycles) {
    fs::path scene = write("basilica.toml",
                           "[fractal]\nc = [-1, 0, 0, 0]\n[orbit]\nz0 = [0.5, 0, 0, 0]\n"
                           "max_iterations = 500\n[cycles]\nperiod = 2\n");
    Json orbit = Json::parse(ok("orbit " + scene.string() + " --json"));
    EXPECT_EQ(orbit["c"], Json::parse("[-1, 0, 0, 0]")) << orbit;
    EXPECT_EQ(orbit["z0"], Json::parse("[0.5, 0, 0, 0]")) << orbit;
    EXPECT_EQ(orbit["max_iterations"], 500) << orbit;
    EXPECT_EQ(orbit["fate"], "attracted") << orbit;
    Json cycles = Json::parse(ok("cycles " + scene.string() + " --json"));
    EXPECT_EQ(cycles["cycles"][0]["period"], 2) << cycles;
    EXPECT_EQ(cycles["cycles"][0]["points"], Json::parse("[[0, 0], [-1, 0]]")) << cycles;
    // --set: the same as the file, and the same as --c.
    std::string set = "--set 'fractal.c=[-1, 0, 0, 0]' ";
    EXPECT_EQ(ok("orbit " + set), ok("orbit --c -1"));
    expectHas(ok("orbit " + set), "fate: periodic with period 2");
    EXPECT_EQ(ok("cycles " + set + "--set cycles.period=2"), ok("cycles --c -1 --period 2"));
    EXPECT_EQ(ok("orbit --set 'orbit.z0=[0, 1, 0, 0]' --set orbit.max_iterations=50 --c -1"),
              ok("orbit --z0 i --max-iterations 50 --c -1"));
}

TEST_F(DynamicsCli, PresetsAndPrecedence) {
    EXPECT_EQ(ok("orbit --preset basilica"), ok("orbit --c -1 --formula 'z^2 + c'"));
    EXPECT_EQ(ok("cycles --preset dendrite --period 2"), ok("cycles --c i --period 2"));
    // The scene file, then the preset, then --set, then the short flags.
    fs::path scene = write("cubic.toml", "[fractal]\nformula = \"z^3 + c\"\nc = [1, 0, 0, 0]\n");
    auto formulaAndC = [&](const std::string& arguments) {
        Json json = Json::parse(ok(arguments));
        return std::make_pair(json["formula"].get<std::string>(),
                              json["c"].get<std::vector<double>>());
    };
    using FormulaAndC = std::pair<std::string, std::vector<double>>;
    EXPECT_EQ(formulaAndC("orbit " + scene.string() + " --json"),
              FormulaAndC("z^3 + c", {1, 0, 0, 0}));
    EXPECT_EQ(formulaAndC("orbit " + scene.string() + " --preset basilica --json"),
              FormulaAndC("z^2 + c", {-1, 0, 0, 0}));
    EXPECT_EQ(formulaAndC("orbit --preset basilica --set 'fractal.c=[0.25, 0, 0, 0]' --json"),
              FormulaAndC("z^2 + c", {0.25, 0, 0, 0}));
    EXPECT_EQ(formulaAndC("orbit --set 'fractal.c=[0.25, 0, 0, 0]' --c 0.5 --json"),
              FormulaAndC("z^2 + c", {0.5, 0, 0, 0}));
}

TEST_F(DynamicsCli, BadInputIsOneLineWithExitCode2) {
    expectUserError(run("orbit --c 1+*2"), "--c");
    expectUserError(run("orbit --c z"), "--c");
    expectUserError(run("orbit --z0 c+1"), "--z0");
    expectUserError(run("orbit --max-iterations 0"), "--max-iterations");
    expectUserError(run("orbit --formula 'sin(z)'"), "--formula");
    expectUserError(run("orbit --formula 'z + c'"), "--formula");
    expectUserError(run("cycles --period -1"), "--period");
    expectUserError(run("cycles --period 11"), "--period");
    expectUserError(run("cycles --formula 'z^3 + c' --period 7"), "--period");
    expectUserError(run("cycles --formula 'i*z*j*z + c' --c 0.1"), "complex polynomial");
    expectUserError(run("cycles --c abc"), "--c");
    expectUserError(run("orbit --c 100"), "--c: fractal.c[0] = 100.0 is out of range");
    // Keys set by --set or a scene file are named as keys.
    expectUserError(run("orbit --set orbit.max_iterations=0"), "orbit.max_iterations = 0");
    expectUserError(run("orbit --set 'fractal.formula=z + c'"), "fractal.formula");
    expectUserError(run("cycles --set cycles.period=11"), "cycles.period = 11 is out of range");
    expectUserError(run("cycles --set 'fractal.formula=z^3 + c' --set cycles.period=7"),
                    "cycles.period must be at least 1 with degree^period <= 1024 (degree 3)");
    expectUserError(run("cycles --set orbit.period=2"), "did you mean 'cycles.period'?");
    expectUserError(run("orbit " + write("bad.toml", "[orbit]\nz0 = 1\n").string()), "orbit.z0");
}

TEST_F(DynamicsCli, OrbitsThatRecurBeforeTheyArriveAnswerInsteadOfCrashing) {
    // Issue 41's reproductions (each ended in a segmentation fault): the fate and period are
    // those of the orbits iterated far past the analysis (orbit_test.cpp, OrbitRegression).
    Json coquaternion = Json::parse(ok("orbit --set fractal.algebra=coquaternion --json"));
    EXPECT_EQ(coquaternion["fate"], "attracted") << coquaternion;
    EXPECT_EQ(coquaternion["period"], 1) << coquaternion;
    Json program =
        Json::parse(ok("orbit --set 'fractal.c=[-0.611, -0.038, 0.029, -0.075]' --set "
                       "'fractal.formula=\"z^2 + 0.1*z + c\"' --set "
                       "'orbit.z0=[-0.712, 0.459, -0.789, -0.537]' --json"));
    EXPECT_EQ(program["fate"], "escapes") << program;
    EXPECT_EQ(program["connectedness"]["connected"], true) << program;
    Json sine = Json::parse(
        ok("orbit --set fractal.algebra=bicomplex --set 'fractal.c=[0.079, 0.147, -0.152, "
           "0.109]' --set 'fractal.formula=\"sin(z) + c\"' --set 'orbit.z0=[0.931, 0.358, "
           "0.125, 0.567]' --json"));
    EXPECT_EQ(sine["fate"], "attracted") << sine;
    EXPECT_EQ(sine["period"], 1) << sine;
    std::string plane =
        ok("plane --set 'fractal.c=[0.139, 0.542, -0.304, 0.195]' --set "
           "'fractal.formula=\"z^3 + c\"' --set plane.kind=julia --width 64 "
           "--height 36 -o " +
           output());
    expectHas(plane, "K is connected");
}

}  // namespace
}  // namespace quaternia
