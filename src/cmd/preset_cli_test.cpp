// --preset as a user meets it on every command that reads a scene: the same picture as its keys
// set by hand, applied after the scene file and before --set, listed by --help, and an unknown
// name as one line with the nearest name, exit code 2 and no output.
#include "cmd/cli_fixture.h"
#include "cmd/cli_library_results.h"

#include "quaternia/scene/json.h"
#include "quaternia/scene/presets.h"

namespace quaternia {
namespace {

namespace fs = std::filesystem;
using testing::CommandResult;
using testing::readFile;

class PresetCli : public testing::CliFixture {
  protected:
    // Runs a command that must succeed and returns its standard output.
    std::string ok(const std::string& arguments) {
        CommandResult r = run(arguments);
        EXPECT_EQ(r.exitCode, 0) << arguments << ": " << r.err;
        return r.out;
    }
};

const std::string kTiny = " --width 24 --height 18 --set render.samples=1 --threads 2";
const std::string kRabbitByHand =
    " --set 'fractal.formula=z^2 + c' --set 'fractal.c=[-0.122561, 0.744862, 0, 0]'";

TEST_F(PresetCli, EveryPresetRenders) {
    for (const Preset& preset : scenePresets()) {
        std::string png = output(preset.name + ".png");
        ok("render --preset " + preset.name + " -o " + png + kTiny);
        SCOPED_TRACE(preset.name);
        Scene scene = defaultScene();
        applyPreset(scene, preset.name);
        setParameter(scene, "render.samples", int64_t(1));
        setParameter(scene, "render.width", int64_t(24));
        setParameter(scene, "render.height", int64_t(18));
        testing::expectPngIsLibrarys(readFile(png), testing::libraryRenderPng(scene));
    }
}

TEST_F(PresetCli, RabbitIsItsKeysSetByHandInRenderPlaneAndMesh) {
    ok("render --preset rabbit -o " + output("preset.png") + kTiny);
    ok("render -o " + output("hand.png") + kTiny + kRabbitByHand);
    EXPECT_EQ(readFile(output("preset.png")), readFile(output("hand.png")));
    EXPECT_NE(readFile(output("preset.png")), "");

    ok("plane --preset rabbit -o " + output("preset.png") + kTiny);
    ok("plane -o " + output("hand.png") + kTiny + kRabbitByHand);
    EXPECT_EQ(readFile(output("preset.png")), readFile(output("hand.png")));

    ok("mesh --preset rabbit --resolution 12 -o " + output("preset.stl"));
    ok("mesh --resolution 12 -o " + output("hand.stl") + kRabbitByHand);
    EXPECT_EQ(readFile(output("preset.stl")), readFile(output("hand.stl")));
}

TEST_F(PresetCli, ComesAfterTheSceneFileAndBeforeSet) {
    fs::path scene = write("scene.toml", "[fractal]\nformula = \"z^3 + c\"\nmax_iterations = 9\n");
    std::string json =
        ok("render " + scene.string() + " --preset basilica --json -o " + output() + kTiny);
    EXPECT_EQ(Json::parse(json)["formula"], "z^2 + c") << json;
    json = ok("render --preset basilica --set 'fractal.formula=z^4 + c' --json -o " + output() +
              kTiny);
    EXPECT_EQ(Json::parse(json)["formula"], "z^4 + c") << json;
}

TEST_F(PresetCli, HelpListsEveryPresetWithItsDescription) {
    for (const char* command : {"--help", "render --help", "plane --help", "mesh --help",
                                "orbit --help", "cycles --help", "explore --help"}) {
        std::string help = ok(command);
        for (const Preset& preset : scenePresets())
            EXPECT_NE(help.find(preset.description), std::string::npos)
                << preset.name << " in " << command;
    }
    EXPECT_NE(ok("render --help").find("--preset"), std::string::npos);
}

TEST_F(PresetCli, UnknownPresetIsOneLineWithTheNearestName) {
    for (const std::string& command :
         {"render -o " + output(), "plane -o " + output(), "mesh -o " + output("out.stl"),
          std::string("orbit"), std::string("cycles"), std::string("explore --port 0")}) {
        CommandResult r = run(command + " --preset rabit");
        expectUserError(r, "unknown preset 'rabit' (did you mean 'rabbit'?)");
        EXPECT_TRUE(r.out.empty()) << command << ": " << r.out;
    }
}

}  // namespace
}  // namespace quaternia
