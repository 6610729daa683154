// `quaternia plane` as a user meets it.
#include "cmd/cli_fixture.h"
#include "cmd/cli_library_results.h"
#include "quaternia/image/png_io.h"
#include "quaternia/scene/json.h"
#include "quaternia/scene/scene_file.h"

namespace quaternia {
namespace {

using PlaneCli = testing::CliFixture;
using testing::CommandResult;
using testing::readFile;

const std::string kSmall = " --width 32 --height 24 --set render.samples=1 --threads 2";

TEST_F(PlaneCli, DrawsJuliaSetWithConnectednessNote) {
    CommandResult r = run("plane -o " + output() + kSmall + " --set 'fractal.c=[-1, 0, 0, 0]'");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    Scene scene = testing::tinyScene(32, 24);
    applyOverride(scene, "fractal.c=[-1, 0, 0, 0]");
    testing::expectPngIsLibrarys(readFile(output()), testing::libraryPlanePng(scene));
    EXPECT_NE(r.out.find("32x24"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("K is connected"), std::string::npos) << r.out;
    r = run("plane -o " + output() + kSmall + " --set 'fractal.c=[0.5, 0.5, 0, 0]'");
    EXPECT_NE(r.out.find("Cantor set"), std::string::npos) << r.out;
}

TEST_F(PlaneCli, MandelbrotAndSliceWithJsonSummary) {
    CommandResult r = run("plane --json -o " + output() + kSmall +
                          " --set plane.kind=mandelbrot --set 'plane.center=[-0.5, 0]'");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    Json summary = Json::parse(r.out);
    EXPECT_EQ(summary["kind"], "mandelbrot") << r.out;
    EXPECT_TRUE(summary["note"].is_null()) << r.out;
    r = run("plane --json -o " + output() + kSmall +
            " --set plane.kind=slice --set 'fractal.formula=\"i*z*j*z + c\"'"
            " --set 'plane.v=[0, 0, 1, 0]'");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(Json::parse(r.out)["kind"], "slice") << r.out;
    Scene scene = testing::tinyScene(32, 24);
    for (const char* assignment :
         {"plane.kind=\"slice\"", "fractal.formula=\"i*z*j*z + c\"", "plane.v=[0, 0, 1, 0]"})
        applyOverride(scene, assignment);
    testing::expectPngIsLibrarys(readFile(output()), testing::libraryPlanePng(scene));
}

TEST_F(PlaneCli, CertifyWritesTheThreeClassesAndCountsThem) {
    const std::string classes = output("classes.png");
    CommandResult r = run("plane --json -o " + output() + " --certify " + classes +
                          " --width 64 --height 48 --threads 2 --set 'fractal.c=[-1, 0, 0, 0]'");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    Json certificate = Json::parse(r.out)["certificate"];
    EXPECT_EQ(certificate["output"], classes) << r.out;
    const int64_t missed = certificate["missed"], hit = certificate["hit"],
                  undecided = certificate["undecided"];
    EXPECT_EQ(missed + hit + undecided, 64 * 48) << r.out;
    EXPECT_DOUBLE_EQ(double(certificate["undecided_fraction"]), double(undecided) / (64 * 48));
    const Image image = readPng(classes);
    ASSERT_EQ(image.width(), 64);
    ASSERT_EQ(image.height(), 48);
    std::map<int, int64_t> counts;
    for (const Rgba& p : image.pixels())
        ++counts[int(std::lround(p.r * 255))];
    EXPECT_EQ(counts, (std::map<int, int64_t>{{0, missed}, {128, undecided}, {255, hit}}));
    EXPECT_GT(missed, 0);
    EXPECT_GT(hit, 0);
    EXPECT_GT(undecided, 0);
    // Without --json: one more line names the file and the counts.
    r = run("plane -o " + output() + " --certify " + classes + kSmall);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("undecided"), std::string::npos) << r.out;
}

TEST_F(PlaneCli, CertifyRefusesBasinsAndItsOwnImage) {
    const std::string o = "plane -o " + output() + kSmall;
    expectUserError(run(o + " --certify " + output("classes.png") + " --set plane.kind=basins"),
                    "basins");
    expectUserError(run(o + " --certify " + output()), "--certify");
}

TEST_F(PlaneCli, HelpListsThePlaneKeys) {
    CommandResult r = run("plane --help");
    EXPECT_EQ(r.exitCode, 0);
    for (const char* key :
         {"plane.kind", "plane.center", "plane.width", "plane.rotation", "plane.origin", "plane.u",
          "plane.v", "julia-boundary", "--threads", "--certify"})
        EXPECT_NE(r.out.find(key), std::string::npos) << key;
}

TEST_F(PlaneCli, BadInputIsOneLineErrorWithoutOutput) {
    const std::string o = "plane -o " + output() + kSmall;
    expectUserError(run(o + " --set plane.kind=spiral"), "plane.kind");
    expectUserError(run(o + " --set plane.width=0"), "plane.width");
    expectUserError(run("plane -o " + output() + " --width 0"), "render.width");
    expectUserError(run(o + " --set plane.kind=slice --set 'plane.u=[0, 0, 0, 0]'"), "plane.u");
    expectUserError(run(o + " --set plane.kind=slice --set 'plane.v=[-3, 0, 0, 0]'"), "plane.v");
    expectUserError(run(o + " --set 'fractal.formula=\"i*z*j*z + c\"'"), "fractal.formula");
    expectUserError(run(o + " --set plane.kind=mandelbrot --set 'fractal.formula=\"z^2 + z\"'"),
                    "fractal.formula");
    expectUserError(run("plane -o " + (dir_ / "missing" / "out.png").string() + kSmall),
                    "missing/out.png");
}

}  // namespace
}  // namespace quaternia
