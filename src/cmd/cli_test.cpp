// The command line as a user meets it: bad input gives one line naming the problem, exit code 2
// and no output file; good input writes a PNG and a summary.
#include "cmd/cli_fixture.h"
#include "cmd/cli_library_results.h"
#include "quaternia/scene/json.h"

#include <hwy/targets.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>

namespace quaternia {
namespace {

namespace fs = std::filesystem;
using testing::CommandResult;
using testing::readFile;

class Cli : public testing::CliFixture {};

const std::string kTiny = " --width 24 --height 18 --set render.samples=1 --threads 2";

TEST_F(Cli, RendersDefaultSceneWithSummary) {
    CommandResult r = run("render -o " + output() + kTiny);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(output()));
    EXPECT_NE(r.out.find("24x18"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("rays/s"), std::string::npos) << r.out;
    testing::expectPngIsLibrarys(readFile(output()),
                                 testing::libraryRenderPng(testing::tinyScene(24, 18)));
    EXPECT_TRUE(r.err.empty()) << "no progress bar when stderr is not a terminal: " << r.err;
}

TEST_F(Cli, PrintsJsonSummary) {
    CommandResult r =
        run("render --json -o " + output() + kTiny + " --depth " + (dir_ / "d.png").string());
    EXPECT_EQ(r.exitCode, 0) << r.err;
    Json summary = Json::parse(r.out);
    EXPECT_EQ(summary["width"], 24) << r.out;
    EXPECT_EQ(summary["height"], 18) << r.out;
    EXPECT_EQ(summary["rays"], 432) << r.out;
    EXPECT_TRUE(summary["rays_per_second"].is_number()) << r.out;
    EXPECT_TRUE(summary["seconds"].is_number()) << r.out;
    EXPECT_EQ(summary["depth_output"], (dir_ / "d.png").string()) << r.out;
    testing::expectPngIsLibrarys(readFile(dir_ / "d.png"),
                                 testing::libraryDepthPng(testing::tinyScene(24, 18)));
    testing::expectPngIsLibrarys(readFile(output()),
                                 testing::libraryRenderPng(testing::tinyScene(24, 18)));
}

TEST_F(Cli, ImageToStandardOutputKeepsTheSummaryOut) {
    // `-o /dev/stdout > file`: the file holds the PNG alone, the summary goes to stderr, and
    // /dev/stdout stays the system's link (it used to be renamed over).
    for (const std::string& json : {std::string(), std::string(" --json")}) {
        CommandResult r = run("render -o /dev/stdout" + kTiny + json);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        testing::expectPngIsLibrarys(r.out, testing::libraryRenderPng(testing::tinyScene(24, 18)));
        EXPECT_NE(r.err.find(json.empty() ? "quaternia: wrote /dev/stdout" : "\"rays\":432"),
                  std::string::npos)
            << r.err;
        EXPECT_TRUE(fs::is_symlink("/dev/stdout"));
    }
}

TEST_F(Cli, ChoosesTheLaneTargetHighwayChooses) {
    // quaternia answers Highway's dispatch itself (highway_runtime.cpp); this test links
    // Highway's own run time, whose choice is the best target both support and compiled.
    const int64_t targets = hwy::SupportedTargets() & HWY_TARGETS;
    ASSERT_NE(targets, 0);
    const std::string best = hwy::TargetName(targets & -targets);
    CommandResult r = run("render --json -o " + output() + kTiny);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(Json::parse(r.out)["engine"], best)
        << "Highway chooses " << best << "; quaternia said " << r.out;
}

TEST_F(Cli, IsaCapsTheLaneTarget) {
    // --isa NAME: the best target at most NAME's (better targets have lower bits), of those the
    // CPU supports and the build compiled; here the test's own Highway run time says which.
    const int64_t targets = hwy::SupportedTargets() & HWY_TARGETS;
    for (const auto& [name, cap] : {std::pair<const char*, int64_t>{"avx2", HWY_AVX2},
                                    {"sse4", HWY_SSE4},
                                    {"scalar", HWY_SCALAR}}) {
        const int64_t allowed = targets & ~(cap - 1);
        const std::string expected =
            allowed == 0 ? hwy::TargetName(HWY_STATIC_TARGET) : hwy::TargetName(allowed & -allowed);
        CommandResult r =
            run(std::string("--isa ") + name + " render --json -o " + output() + kTiny);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(Json::parse(r.out)["engine"], expected) << name << ": " << r.out;
    }
    fs::remove(output());
    CommandResult bad = run("--isa avx9 render -o " + output() + kTiny);
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.err.find("--isa"), std::string::npos) << bad.err;
    EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
    EXPECT_FALSE(fs::exists(output()));
}

TEST_F(Cli, SceneFileAndOverridesApply) {
    fs::path scene =
        write("scene.toml", "[fractal]\nformula = \"z^3 + c\"\nc = [-0.5, 0.5, 0, 0]\n");
    CommandResult r = run("render " + scene.string() + " --json -o " + output() + kTiny +
                          " --set fractal.max_iterations=9");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    Json summary = Json::parse(r.out);
    EXPECT_EQ(summary["formula"], "z^3 + c") << r.out;
    EXPECT_EQ(summary["c"], Json::array({-0.5, 0.5, 0, 0})) << r.out;
}

TEST_F(Cli, HelpListsEveryKeyWithDefault) {
    for (const char* args : {"--help", "render --help"}) {
        CommandResult r = run(args);
        EXPECT_EQ(r.exitCode, 0);
        for (const char* key : {"fractal.formula", "fractal.c", "slice.left", "camera.fov",
                                "render.epsilon", "render.method", "shading.ambient_occlusion"}) {
            EXPECT_NE(r.out.find(key), std::string::npos) << key << " in " << args;
        }
        EXPECT_NE(r.out.find("z^2 + c"), std::string::npos);
    }
    EXPECT_NE(run("render --help").out.find("--threads"), std::string::npos);
}

TEST_F(Cli, MalformedTomlIsOneLineError) {
    fs::path scene = write("bad.toml", "[render]\nwidth = = 3\n");
    expectUserError(run("render " + scene.string() + " -o " + output()), "bad.toml:2");
}

TEST_F(Cli, UnknownKeyIsNamedWithSuggestion) {
    fs::path scene = write("typo.toml", "[render]\nwidht = 30\n");
    CommandResult r = run("render " + scene.string() + " -o " + output());
    expectUserError(r, "render.widht");
    EXPECT_NE(r.err.find("render.width"), std::string::npos);
}

TEST_F(Cli, OutOfRangeSizesAreRefused) {
    expectUserError(run("render -o " + output() + " --width -5"), "render.width");
    expectUserError(run("render -o " + output() + " --width 0"), "render.width");
    expectUserError(run("render -o " + output() + " --height 20000"), "render.height");
    expectUserError(run("render -o " + output() + " --set render.width=16385"), "render.width");
}

TEST_F(Cli, IterationLimitIsEnforced) {
    expectUserError(run("render -o " + output() + " --set fractal.max_iterations=1000000000"),
                    "fractal.max_iterations");
}

TEST_F(Cli, NanAndInfinityAreRefused) {
    expectUserError(run("render -o " + output() + " --set fractal.bailout=nan"), "fractal.bailout");
    expectUserError(run("render -o " + output() + " --set 'fractal.c=[0, inf, 0, 0]'"),
                    "fractal.c");
    expectUserError(run("render -o " + output() + " --set camera.fov=-inf"), "camera.fov");
}

TEST_F(Cli, UnparsableFormulaNamesColumn) {
    CommandResult r = run("render -o " + output() + " --set 'fractal.formula=\"z^2 + * c\"'");
    expectUserError(r, "fractal.formula");
    EXPECT_NE(r.err.find("column 7"), std::string::npos) << r.err;
}

TEST_F(Cli, PossiblyUnboundedFormulaIsRefused) {
    expectUserError(
        run("render -o " + output() +
            " --set 'fractal.formula=\"z i z - i z^2 + c\"' --set 'fractal.c=[0.1, 0.2, 0, 0]'"),
        "fractal.formula");
}

TEST_F(Cli, UnwritableOutputIsRefusedBeforeRendering) {
    CommandResult r = run("render -o " + (dir_ / "missing" / "out.png").string() + kTiny);
    expectUserError(r, "missing/out.png");
}

TEST_F(Cli, MissingSceneFileIsNamed) {
    expectUserError(run("render " + (dir_ / "nope.toml").string() + " -o " + output()),
                    "nope.toml");
}

TEST_F(Cli, BadOptionValueIsOneLineError) {
    CommandResult r = run("render -o " + output() + " --width abc");
    expectUserError(r, "--width");
    expectUserError(run("render -o " + output() + " --set novalue"), "--set");
    expectUserError(run("render -o " + output() + " --threads -3"), "--threads");
}

}  // namespace
}  // namespace quaternia
