// `quaternia certify` as a user meets it.
#include <cmath>
#include <map>

#include "cmd/cli_fixture.h"
#include "quaternia/image/png_io.h"
#include "quaternia/scene/json.h"

namespace quaternia {
namespace {

using CertifyCli = testing::CliFixture;
using testing::CommandResult;
namespace fs = std::filesystem;

const std::string kBasilica =
    " --set 'fractal.c=[-1, 0, 0, 0]' --set plane.width=3.4 --width 64 --height 48 --threads 2";

TEST_F(CertifyCli, WritesClassesPngAndJsonSummary) {
    CommandResult r = run("certify -o " + output() + " --json" + kBasilica);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const Json summary = Json::parse(r.out);
    EXPECT_EQ(summary["command"], "certify") << r.out;
    EXPECT_EQ(summary["output"], output()) << r.out;
    EXPECT_EQ(summary["width"], 64);
    EXPECT_EQ(summary["height"], 48);
    const int64_t outside = summary["pixels"]["outside"], inside = summary["pixels"]["inside"],
                  undecided = summary["pixels"]["undecided"];
    EXPECT_EQ(outside + inside + undecided, 64 * 48) << r.out;
    EXPECT_GT(outside, 0);
    EXPECT_GT(inside, 0);
    EXPECT_GT(undecided, 0);
    EXPECT_DOUBLE_EQ(double(summary["pixels"]["undecided_fraction"]),
                     double(undecided) / (64 * 48));
    // Areas: pixels times the pixel's area (3.4 / 64)^2, summing to the view's 3.4 x 2.55.
    const double pixelArea = (3.4 / 64) * (3.4 / 64);
    EXPECT_NEAR(double(summary["areas"]["outside"]), double(outside) * pixelArea, 1e-9);
    EXPECT_NEAR(double(summary["areas"]["inside"]), double(inside) * pixelArea, 1e-9);
    EXPECT_NEAR(double(summary["areas"]["undecided"]), double(undecided) * pixelArea, 1e-9);
    const Json& band = summary["undecided_band_pixels"];
    const int median = band["median"], p99 = band["p99"], max = band["max"];
    EXPECT_GE(median, 1) << r.out;
    EXPECT_LE(median, p99);
    EXPECT_LE(p99, max);
    EXPECT_NEAR(double(summary["escape_radius"]), (1 + std::sqrt(5.0)) / 2, 1e-8);
    // The PNG holds the three classes as counted.
    const Image image = readPng(output());
    ASSERT_EQ(image.width(), 64);
    ASSERT_EQ(image.height(), 48);
    std::map<int, int64_t> counts;
    for (const Rgba& p : image.pixels())
        ++counts[int(std::lround(p.r * 255))];
    EXPECT_EQ(counts, (std::map<int, int64_t>{{0, outside}, {128, undecided}, {255, inside}}));
    // Corner pixels lie beyond |z| = 1.62: outside. The centre pixel, z near 0, lies in the
    // basin of the attracting cycle {0, -1}: inside.
    const auto grey = [&](int x, int y) { return int(std::lround(image.at(x, y).r * 255)); };
    EXPECT_EQ(grey(0, 0), 0);
    EXPECT_EQ(grey(63, 47), 0);
    EXPECT_EQ(grey(32, 24), 255);
}

TEST_F(CertifyCli, WithoutJsonPrintsOneSummaryLine) {
    CommandResult r = run("certify -o " + output() + kBasilica);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("undecided"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("64x48"), std::string::npos) << r.out;
    EXPECT_TRUE(fs::exists(output()));
}

TEST_F(CertifyCli, RefusesBadInputAndWritesNothing) {
    const std::string o = "certify -o " + output() + kBasilica;
    expectUserError(run(o + " --set plane.kind=basins"), "plane.kind");
    expectUserError(run(o + " --set plane.kind=mandelbrot"), "plane.kind");
    expectUserError(run(o + " --resolution 5"), "--resolution");
    const std::string missing = (dir_ / "missing" / "out.png").string();
    CommandResult r = run("certify -o " + missing + kBasilica);
    expectUserError(r, missing);
    EXPECT_FALSE(fs::exists(dir_ / "missing"));
}

}  // namespace
}  // namespace quaternia
