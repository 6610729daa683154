// `quaternia orbit` and `quaternia cycles` as a user meets them: the facts of docs/facts.md
// (Cycles and multipliers of z^2 + c) in text and JSON, and bad input as one line with exit code 2.
#include "cmd/cli_fixture.h"
#include "quaternia/scene/json.h"

namespace quaternia {
namespace {

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
}

}  // namespace
}  // namespace quaternia
