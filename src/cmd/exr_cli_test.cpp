// `quaternia render -o out.exr` (issue 20, outputs for compositing): the file read back by
// readers independent of the OpenEXR library that wrote it (tests/tools/read_exr.py, which
// follows the file format's specification, and Debian's exrheader), held to the geometry of the
// unit ball, the set of z^2 + 0: every hit lies on the sphere, its normal is the radius, its
// orbit trap |z_0| is 1, and the colour is the PNG's before exposure and gamma.
#include <cmath>

#include "cmd/cli_fixture.h"
#include "quaternia/image/png_io.h"
#include "quaternia/render/camera.h"
#include "quaternia/render/render.h"
#include "quaternia/scene/json.h"
#include "quaternia/scene/scene_file.h"

namespace quaternia {
namespace {

using ExrCli = testing::CliFixture;
using testing::CommandResult;
using testing::readFile;

constexpr int kWidth = 96, kHeight = 72;
const char* kBall = R"([fractal]
c = [0, 0, 0, 0]
[camera]
position = [0.0, 0.5, -4.0]
look_at = [0.0, 0.0, 0.0]
fov = 45.0
[render]
width = 96
height = 72
samples = 1
)";

// Both engines: the SIMD lanes' passes and the scalar reference's.
class ExrEngines : public testing::CliFixture, public ::testing::WithParamInterface<const char*> {};

TEST_P(ExrEngines, PassesOfTheUnitBallReadBackIndependently) {
    const std::string scene =
        write("ball.toml", kBall).string() + " --set render.engine=" + GetParam();
    CommandResult r = run("render " + scene + " -o " + output("ball.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    r = run("render " + scene + " -o " + output("ball.png"));
    ASSERT_EQ(r.exitCode, 0) << r.err;

    const std::string header = output("header.txt");
    ASSERT_EQ(std::system(("exrheader " + output("ball.exr") + " >" + header).c_str()), 0);
    const std::string headerText = readFile(header);
    EXPECT_NE(headerText.find("zip"), std::string::npos) << headerText;
    EXPECT_NE(headerText.find("id, 32-bit unsigned integer"), std::string::npos) << headerText;
    EXPECT_NE(headerText.find("N.X, 32-bit floating-point"), std::string::npos) << headerText;

    const std::string json = output("ball.json");
    const std::string reader = std::string(QUATERNIA_SOURCE_DIR) + "/tests/tools/read_exr.py";
    ASSERT_EQ(std::system(("python3 " + reader + " " + output("ball.exr") + " >" + json).c_str()),
              0);
    const Json file = Json::parse(readFile(json));
    ASSERT_EQ(file["width"], kWidth);
    ASSERT_EQ(file["height"], kHeight);
    const Json& c = file["channels"];
    std::vector<std::string> names;
    for (const auto& [name, values] : c.items())
        names.push_back(name);
    EXPECT_EQ(names, (std::vector<std::string>{"A", "B", "G", "N.X", "N.Y", "N.Z", "R", "Z", "id",
                                               "trap"}));

    const Scene parsed = parseScene(kBall);
    const Camera camera(parsed.camera, kWidth, kHeight);
    const Image png = readPng(output("ball.png"));
    int hits = 0;
    double worstRadius = 0, worstNormal = 0, worstTrap = 0;
    int colourOff = 0;
    for (int py = 0; py < kHeight; ++py) {
        for (int px = 0; px < kWidth; ++px) {
            const size_t i = size_t(py * kWidth + px);
            const double z = c["Z"][i], alpha = c["A"][i];
            const Vector3d n(c["N.X"][i], c["N.Y"][i], c["N.Z"][i]);
            if (c["id"][i] == 0) {
                EXPECT_EQ(alpha, 0.0);
                EXPECT_EQ(z, double(RenderPasses::kNoHitDistance));
                EXPECT_EQ(length(n), 0.0);
                EXPECT_EQ(double(c["R"][i]), 0.0);  // premultiplied by alpha 0
                continue;
            }
            ++hits;
            EXPECT_EQ(alpha, 1.0);
            const Ray ray = camera.generateRay(px + 0.5, py + 0.5);
            const Point3d p = ray.at(z);
            worstRadius = std::max(worstRadius, std::abs(length(p) - 1));
            worstNormal = std::max(worstNormal, length(n - Vector3d(p) / length(p)));
            worstTrap = std::max(worstTrap, std::abs(double(c["trap"][i]) - length(p)));
            // The PNG holds clamp(R)^(1 / 2.2) in 8 bits (exposure 1, gamma 2.2).
            const double red = c["R"][i];
            const double expected = std::pow(std::clamp(red, 0.0, 1.0), 1 / 2.2);
            colourOff += std::abs(png.at(px, py).r - expected) > 1.0 / 255;
        }
    }
    // The ball's outline: radius f tan(asin(1 / d)) pixels, f the focal length in pixels
    // (POV-Ray's horizontal angle), d the camera's distance.
    const double f = 0.5 * kWidth / std::tan(0.5 * 45 * M_PI / 180);
    const double radius = f * std::tan(std::asin(1 / std::sqrt(4.0 * 4.0 + 0.5 * 0.5)));
    EXPECT_NEAR(hits, M_PI * radius * radius, 0.04 * M_PI * radius * radius);
    EXPECT_LT(worstRadius, 0.01) << "a hit off the unit sphere";
    EXPECT_LT(worstNormal, 0.03) << "a normal off the radius";
    EXPECT_LT(worstTrap, 0.01) << "a trap other than |z_0|";
    EXPECT_EQ(colourOff, 0) << "EXR colour that is not the PNG's before gamma";
}

INSTANTIATE_TEST_SUITE_P(Engine, ExrEngines, ::testing::Values("simd", "scalar"));

TEST_F(ExrCli, UnwritableExrIsOneLineAndNoFile) {
    CommandResult r = run("render --width 16 --height 12 -o " + output("missing/out.exr"));
    expectUserError(r, "cannot write");
}

}  // namespace
}  // namespace quaternia
