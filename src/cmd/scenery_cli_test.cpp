// The scene around the set on the command line: the looks render, and bad values of the
// lights, the material and the ground are one line, exit 2, and no file.
#include "cmd/cli_fixture.h"
#include "quaternia/image/hdr_image.h"
#include "quaternia/util/atomic_file.h"

namespace quaternia {
namespace {

using SceneryCli = testing::CliFixture;
using testing::CommandResult;
namespace fs = std::filesystem;

TEST_F(SceneryCli, LooksRenderAndNameTheirLights) {
    for (const char* look : {"studio", "chrome", "glass", "sunset"}) {
        const CommandResult r = run(std::string("render --preset ") + look +
                                    " --width 48 --height 32 -o " + output("look.png"));
        EXPECT_EQ(r.exitCode, 0) << look << ": " << r.err;
    }
}

TEST_F(SceneryCli, MoreLightsThanTheLimitIsOneLine) {
    CommandResult r = run("render --set light8.enabled=true -o " + output("out.png"));
    expectUserError(r, "too many lights: [light8] is past the limit of 7");
    const std::string scene = write("lights.toml", "[light12]\nenabled = true\n").string();
    r = run("render " + scene + " -o " + output("out.png"));
    expectUserError(r, "too many lights: [light12]");
}

TEST_F(SceneryCli, OutOfRangeMaterialsAndLightsAreOneLine) {
    expectUserError(run("render --set material.ior=0.9 -o " + output("out.png")),
                    "material.ior = 0.9 is out of range [1, 4]");
    expectUserError(run("render --set material.reflectivity=1.5 -o " + output("out.png")),
                    "material.reflectivity = 1.5 is out of range [0, 1]");
    expectUserError(run("render --set ground.reflectivity=-0.1 -o " + output("out.png")),
                    "ground.reflectivity");
    expectUserError(run("render --set light3.intensity=-2 -o " + output("out.png")),
                    "light3.intensity = -2");
    expectUserError(run("render --set light1.kind=laser -o " + output("out.png")), "light1.kind");
}

// The double-precision engine draws the looks too (path_waves.h), and with them the algebras the
// lanes leave to it: a coquaternion set on a reflecting ground.
TEST_F(SceneryCli, ScalarEngineRendersTheLooks) {
    for (const char* look : {"studio", "chrome", "glass"}) {
        const CommandResult r =
            run(std::string("render --preset ") + look +
                " --set render.engine=scalar --width 32 --height 24 -o " + output("look.png"));
        EXPECT_EQ(r.exitCode, 0) << look << ": " << r.err;
    }
    const CommandResult r =
        run("render --set fractal.algebra=coquaternion --set ground.enabled=true "
            "--set ground.reflectivity=0.3 --width 24 --height 16 -o " +
            output("coquaternion.png"));
    EXPECT_EQ(r.exitCode, 0) << r.err;
}

// An environment map that cannot be used (issue 39): one line naming environment.map and the
// file, exit 2, nothing written, before the render. A good one renders.
TEST_F(SceneryCli, BadEnvironmentMapsAreOneLine) {
    const fs::path maps = testing::scratchPath("quaternia_environment_maps");
    fs::create_directories(maps);
    auto writeMap = [&](const std::string& name, int width, int height) {
        AtomicFile file((maps / name).string());
        file.write(encodeRadianceHdr(
            HdrImage{width, height, std::vector<float>(size_t(width) * size_t(height) * 3, 0.5f)}));
        file.commit();
        return maps / name;
    };
    auto renderWith = [&](const fs::path& map) {
        return "render --set environment.enabled=true --set 'environment.map=\"" + map.string() +
               "\"' --width 32 --height 24 -o " + output("out.png");
    };
    const fs::path missing = maps / "missing.hdr";
    expectUserError(run(renderWith(missing)),
                    "environment.map: '" + missing.string() + "': no such file");
    std::ofstream(maps / "picture.png") << "\x89PNG\r\n\x1a\n and not much more";
    expectUserError(run(renderWith(maps / "picture.png")), "is not an HDR image");
    expectUserError(run(renderWith(writeMap("square.hdr", 16, 16))),
                    "is 16 x 16 pixels; a latitude-longitude map is twice as wide as high");
    const fs::path big = writeMap("big.hdr", 512, 256);
    expectUserError(run(renderWith(big) + " --memory-budget 64K"),
                    "environment.map: the map '" + big.string() + "' needs about");
    expectUserError(run("animate --preset hidden-turn --set environment.enabled=true "
                        "--set 'environment.map=\"" +
                        missing.string() + "\"' --width 16 --height 16 -o " + output("film")),
                    "no such file");
    const CommandResult r = run(renderWith(big));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    fs::remove_all(maps);
}

}  // namespace
}  // namespace quaternia
