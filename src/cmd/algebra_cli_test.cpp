// Issue 16 at the command line: every algebra renders and meshes, and every bad combination of
// algebra, c and slice keys is one line, exit 2, and no file.
#include "cmd/cli_fixture.h"

namespace quaternia::testing {
namespace {

class AlgebraCli : public CliFixture {
  protected:
    static constexpr const char* kTiny = " --width 48 --height 36";
    std::string render(const std::string& settings) {
        return "render -o " + output() + kTiny + " " + settings;
    }
};

TEST_F(AlgebraCli, EveryAlgebraRendersTheDefaultScene) {
    for (const char* settings :
         {"--set 'fractal.algebra=\"bicomplex\"'", "--set 'fractal.algebra=\"coquaternion\"'",
          "--set 'fractal.algebra=\"octonion\"' --set 'fractal.c=[-0.2, 0.6, 0.2, 0.2, 0.1, 0, 0, "
          "0]'",
          "--set 'fractal.algebra=\"biquaternion\"' --set 'fractal.c=[-0.2, 0.6, 0.2, 0.2, 0, 0, "
          "0, 0]' --set 'slice.axes=[[1, 0, 0, 0, 0, 0, 0, 0], [0, 1, 0, 0, 0, 0, 0, 0], [0, 0, 0, "
          "0, 0, 0, 1, 0]]'"}) {
        CommandResult r = run(render(settings) + " --json");
        EXPECT_EQ(r.exitCode, 0) << settings << ": " << r.err;
        EXPECT_NE(r.out.find("\"hits\""), std::string::npos) << r.out;
        EXPECT_EQ(r.out.find("\"hits\":0,"), std::string::npos) << settings << ": " << r.out;
        EXPECT_TRUE(fs::exists(output())) << settings;
        fs::remove(output());
    }
}

// A shorter c is filled with zeros (docs/algebras.md): fractal.algebra alone switches the
// default scene to every algebra; the octonions and biquaternions then iterate c = -0.2 + 0.6i
// + 0.2j + 0.2k, whose set through the default slice is the quaternions' (the octonion product
// of two quaternions is theirs, as is the biquaternion product of two real ones).
TEST_F(AlgebraCli, SwitchingTheAlgebraAloneRenders) {
    CommandResult quaternion = run(render("--json"));
    ASSERT_EQ(quaternion.exitCode, 0) << quaternion.err;
    const auto hitsOf = [](const std::string& json) {
        const size_t at = json.find("\"hits\":");
        return at == std::string::npos ? -1L : std::stol(json.substr(at + 7));
    };
    for (const char* algebra : {"bicomplex", "coquaternion", "biquaternion", "octonion"}) {
        CommandResult r =
            run(render("--set 'fractal.algebra=\"" + std::string(algebra) + "\"' --json"));
        EXPECT_EQ(r.exitCode, 0) << algebra << ": " << r.err;
        EXPECT_GT(hitsOf(r.out), 0) << algebra << ": " << r.out;
        if (std::string(algebra) == "octonion" || std::string(algebra) == "biquaternion") {
            EXPECT_NEAR(double(hitsOf(r.out)), double(hitsOf(quaternion.out)),
                        0.01 * double(hitsOf(quaternion.out)))
                << algebra;
        }
    }
}

TEST_F(AlgebraCli, BadAlgebraInputIsOneLineAndNoFile) {
    expectUserError(run(render("--set 'fractal.algebra=\"sedenion\"'")), "fractal.algebra");
    // Eight components of c for a 4-component algebra would lose four (a shorter c is filled
    // with zeros: AlgebraCli.SwitchingTheAlgebraAloneRenders).
    CommandResult r = run(render("--set 'fractal.c=[-0.2, 0.6, 0.2, 0.2, 0, 0, 0, 0]'"));
    expectUserError(r, "fractal.c");
    EXPECT_NE(r.err.find("has 4"), std::string::npos) << r.err;
    expectUserError(run(render("--set 'fractal.c=[1, 2, 3]'")), "fractal.c");
    // 8-component slice keys with a 4-component algebra, and the reverse.
    expectUserError(run(render("--set 'slice.origin=[0, 0, 0, 0, 0, 0, 0, 0]'")), "slice.origin");
    expectUserError(run(render("--set 'fractal.algebra=\"octonion\"' --set 'fractal.c=[-0.2, 0.6, "
                               "0.2, 0.2, 0, 0, 0, 0]' --set 'slice.normal=[0, 0, 1, 1]'")),
                    "slice.normal");
    expectUserError(
        run(render(
            "--set 'fractal.algebra=\"octonion\"' --set 'fractal.c=[-0.2, 0.6, 0.2, 0.2, "
            "0, 0, 0, 0]' --set 'slice.axes=[[1, 0, 0, 0, 0, 0, 0, 0], [2, 0, 0, 0, 0, 0, 0, "
            "0], [0, 0, 1, 0, 0, 0, 0, 0]]'")),
        "slice.axes");
    // A formula whose octonion escape radius is not derived needs a bailout.
    expectUserError(run(render("--set 'fractal.algebra=\"octonion\"' --set 'fractal.c=[-0.2, 0.6, "
                               "0.2, 0.2, 0, 0, 0, 0]' --set 'fractal.formula=\"z i z - i z^2 + "
                               "c\"'")),
                    "fractal.bailout");
    // Functions are the bicomplex numbers' only.
    expectUserError(run(render("--set 'fractal.formula=\"sin(z) + c\"'")), "fractal.formula");
    // `cycles` and the complex plane kinds work in the quaternions only, and say so.
    expectUserError(run("cycles --set 'fractal.algebra=\"bicomplex\"'"), "fractal.algebra");
    r = run("plane -o " + output() + " --set 'fractal.algebra=\"bicomplex\"'");
    expectUserError(r, "plane.kind");
    EXPECT_NE(r.err.find("bicomplex"), std::string::npos) << r.err;
    // An 8-component algebra's plane lies in the 3D slice: three coordinates.
    expectUserError(run("plane -o " + output() +
                        " --set plane.kind=slice --set 'fractal.algebra=\"octonion\"' --set "
                        "'fractal.c=[-0.2, 0.6, 0.2, 0.2, 0, 0, 0, 0]' --set "
                        "'plane.origin=[0, 0, 0, 0.5]'"),
                    "plane.origin");
}

TEST_F(AlgebraCli, PlaneSlicesEveryAlgebra) {
    for (const char* settings :
         {"--set 'fractal.algebra=\"bicomplex\"'", "--set 'fractal.algebra=\"coquaternion\"'",
          "--set 'fractal.algebra=\"octonion\"' --set 'fractal.c=[-0.2, 0.6, 0.2, 0.2, 0.1, 0, 0, "
          "0]' --set 'slice.axes=[[1, 0, 0, 0, 0, 0, 0, 0], [0, 1, 0, 0, 0, 0, 0, 0], [0, 0, 0, "
          "0, 1, 0, 0, 0]]'",
          "--set 'fractal.algebra=\"biquaternion\"' --set 'fractal.c=[-0.2, 0.6, 0.2, 0.2, 0, 0, "
          "0, 0]'"}) {
        CommandResult r = run("plane -o " + output() + kTiny + " --set plane.kind=slice " +
                              settings + " --set plane.max_iterations=64 --json");
        EXPECT_EQ(r.exitCode, 0) << settings << ": " << r.err;
        EXPECT_TRUE(fs::exists(output())) << settings;
        fs::remove(output());
    }
}

TEST_F(AlgebraCli, OrbitInEveryAlgebra) {
    // Bicomplex c = -1 is (-1, -1) in duplex form: 0 -> -1 -> 0 in both components.
    CommandResult r = run("orbit --set 'fractal.algebra=\"bicomplex\"' --c -1");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("periodic with period 2"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("in bicomplex (4x4): Jacobian eigenvalues 0, 0, 0, 0, superattracting"),
              std::string::npos)
        << r.out;
    // span{1, i} is a copy of C holding c: the complex multiplier and K's connectedness.
    EXPECT_NE(r.out.find("multiplier: 0 (|lambda| = 0), superattracting"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("K: connected"), std::string::npos) << r.out;
    // Octonions: an 8x8 Jacobian, 8 eigenvalues and 8 components per point in the JSON.
    r =
        run("orbit --set 'fractal.algebra=\"octonion\"' --set 'fractal.c=[-1, 0, 0, 0, 0, 0, 0, "
            "0]' --json");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("\"algebra\":\"octonion\""), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\"fate\":\"periodic\""), std::string::npos) << r.out;
    EXPECT_NE(
        r.out.find(
            "\"points\":[[0.0,0.0,0.0,0.0,0.0,0.0,0.0,0.0],[-1.0,0.0,0.0,0.0,0.0,0.0,0.0,0.0]]"),
        std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("\"eigenvalues\":[[0.0,0.0],[0.0,0.0],[0.0,0.0],[0.0,0.0],[0.0,0.0],[0.0,"
                         "0.0],[0.0,0.0],[0.0,0.0]]"),
              std::string::npos)
        << r.out;
    // Coquaternions and biquaternions escape past the bailout (K_N's test).
    r = run("orbit --set 'fractal.algebra=\"coquaternion\"' --c 1");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("fate: escapes at iteration 3 (|z| > escape radius 2)"), std::string::npos)
        << r.out;
}

TEST_F(AlgebraCli, BicomplexFunctionsRender) {
    // POV-Ray's hypercomplex functions, by Algorithm 2's fixed steps.
    // Fixed steps through a bounding sphere of radius 4 are slow: a small picture, coarse steps.
    CommandResult r = run("render -o " + output() +
                          " --width 16 --height 12 --set render.step=0.01 --set "
                          "'fractal.algebra=\"bicomplex\"' --set 'fractal.formula=\"sin(z) + "
                          "c\"' --set 'fractal.c=[0.2, 0.1, 0, 0]' --json");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out.find("\"hits\":0,"), std::string::npos) << r.out;
}

TEST_F(AlgebraCli, OctonionFormulasTooLargeToMultiplyOutStillRender) {
    // (z + i)^30 has 2^30 quaternion words: no expansion, so the octonion arithmetic draws it.
    CommandResult r = run("render -o " + output() +
                          " --width 8 --height 6 --set 'fractal.algebra=\"octonion\"' --set "
                          "'fractal.c=[-0.2, 0.6, 0.2, 0.2, 0.1, 0, 0, 0]' --set "
                          "'fractal.formula=\"(z + i)^30 + c\"'");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(output()));
}

TEST_F(AlgebraCli, EveryAlgebraMeshes) {
    CommandResult r = run("mesh -o " + output("set.stl") +
                          " --set 'fractal.algebra=\"bicomplex\"' --set mesh.resolution=24");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(output("set.stl")));
}

}  // namespace
}  // namespace quaternia::testing
