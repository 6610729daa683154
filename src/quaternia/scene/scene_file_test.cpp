#include "quaternia/scene/scene_file.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "quaternia/algebra/test_helpers.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/util/error.h"
#include "quaternia/util/test_scratch_path.h"

namespace quaternia {
namespace {

using namespace quaternia::testing;

UserError parseError(std::string_view text) {
    return thrownError([&] { parseScene(text, "scene.toml"); });
}

UserError overrideError(std::string_view assignment) {
    Scene scene = defaultScene();
    return thrownError([&] { applyOverride(scene, assignment); });
}

// Every field, compared through the table (which covers all of Scene, see parameters_test).
void expectSameScene(const Scene& a, const Scene& b) {
    for (const auto& p : parameterTable())
        EXPECT_EQ(p.read(a), p.read(b)) << p.name();
}

// A file in the temporary directory, removed at the end of the test.
class TemporaryFile {
  public:
    explicit TemporaryFile(const std::string& contents)
        : path_(quaternia::testing::scratchPath("quaternia_scene_file_test.toml")) {
        std::ofstream(path_) << contents;
    }
    ~TemporaryFile() { std::filesystem::remove(path_); }
    std::string path() const { return path_.string(); }

  private:
    std::filesystem::path path_;
};

TEST(SceneFile, ParsesAFullFile) {
    Scene s = parseScene(R"(# a scene
[fractal]
formula = "z^3 + c"
c = [-0.8, 0.156, 0, 0]
max_iterations = 20
bailout = 2

[slice]
normal = [0.2, -0.3, 0.4, 1]
distance = 0.15
angles = [0, 0, 0, 0, 0, 30]

[camera]
position = [0, 0, -3]
fov = 60.5

[render]
width = 320
height = 240
method = "fixed-step"
step = 0.001
bit_depth = 16

[shading]
shadows = "hard"
coloring = "solid"
base_color = [1, 0.5, 0.25]
)",
                         "scene.toml");
    EXPECT_EQ(s.fractal.formula, "z^3 + c");
    EXPECT_EQ(s.fractal.c, Quaternion(-0.8, 0.156, 0, 0));
    EXPECT_EQ(s.fractal.maxIterations, 20);
    EXPECT_EQ(s.fractal.bailout, 2.0);
    EXPECT_EQ(s.slice.normal, Quaternion(0.2, -0.3, 0.4, 1));
    EXPECT_EQ(s.slice.distance, 0.15);
    EXPECT_EQ(s.slice.anglesDegrees[5], 30.0);
    EXPECT_EQ(s.camera.position, Point3d(0, 0, -3));
    EXPECT_EQ(s.camera.fovDegrees, 60.5);
    EXPECT_EQ(s.render.width, 320);
    EXPECT_EQ(s.render.height, 240);
    EXPECT_EQ(s.render.method, MarchMethod::FixedStep);
    EXPECT_EQ(s.render.step, 0.001);
    EXPECT_EQ(s.render.bitDepth, 16);
    EXPECT_EQ(s.shading.shadows, Shadows::Hard);
    EXPECT_EQ(s.shading.coloring, Coloring::Solid);
    EXPECT_EQ(s.shading.baseColor, Color(1, 0.5, 0.25));
    // Keys left out keep their defaults.
    Scene defaults = defaultScene();
    EXPECT_EQ(s.camera.lookAt, defaults.camera.lookAt);
    EXPECT_EQ(s.render.samples, defaults.render.samples);
    EXPECT_EQ(s.shading.gamma, defaults.shading.gamma);
}

TEST(SceneFile, GivesTheDefaultSceneForAnEmptyFile) {
    expectSameScene(parseScene(""), defaultScene());
    expectSameScene(parseScene("# nothing\n[render]\n"), defaultScene());
}

TEST(SceneFile, AcceptsIntegersForRealsAndDottedKeys) {
    Scene s = parseScene("camera.fov = 60\n[fractal]\nbailout = 3\nc = [0, 1, 0.5, -1]\n");
    EXPECT_EQ(s.camera.fovDegrees, 60.0);
    EXPECT_EQ(s.fractal.bailout, 3.0);
    EXPECT_EQ(s.fractal.c, Quaternion(0, 1, 0.5, -1));
    EXPECT_EQ(parseScene("[render]\nwidth = 640.0\n").render.width, 640);
}

TEST(SceneFile, RejectsAnUnknownKeyNamingTheFileAndTheNearestKey) {
    UserError error = parseError("[render]\nwidth = 640\nwidht = 640\n");
    EXPECT_EQ(error.key(), "render.widht");
    EXPECT_STREQ(error.what(),
                 "scene.toml:3:1: unknown key 'render.widht' (did you mean 'render.width'?)");
    error = parseError("width = 640\n");
    EXPECT_EQ(error.key(), "width");
    EXPECT_STREQ(error.what(),
                 "scene.toml:1:1: unknown key 'width' (did you mean 'render.width'?)");
    error = parseError("[render.size]\nx = 1\n");
    EXPECT_EQ(error.key(), "render.size");
}

TEST(SceneFile, RejectsAnUnknownSectionWithTheNearestOne) {
    UserError error = parseError("[camera]\nfov = 50\n[rendr]\nwidth = 640\n");
    EXPECT_EQ(error.key(), "rendr");
    EXPECT_STREQ(error.what(), "scene.toml:3:2: unknown section [rendr] (did you mean [render]?)");
    error = parseError("render = 5\n");
    EXPECT_EQ(error.key(), "render");
    EXPECT_STREQ(error.what(),
                 "scene.toml:1:1: 'render' must be a section: write [render] above its keys");
}

TEST(SceneFile, ReportsTomlSyntaxErrorsWithLineAndColumn) {
    UserError error = parseError("[render]\nwidth = 640\nheight = = 3\n");
    EXPECT_EQ(error.key(), "scene.toml");
    std::string message = error.what();
    EXPECT_EQ(message.rfind("scene.toml:3:", 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_GT(message.size(), std::string("scene.toml:3:1: ").size());
}

TEST(SceneFile, RejectsAValueOfTheWrongType) {
    UserError error = parseError("[render]\nwidth = \"abc\"\n");
    EXPECT_EQ(error.key(), "render.width");
    EXPECT_STREQ(error.what(), "scene.toml:2:1: render.width must be an integer, got \"abc\"");
    EXPECT_STREQ(parseError("[fractal]\nc = [\"a\", 1, 2, 3]\n").what(),
                 "scene.toml:2:1: fractal.c must be an array of 4 or 8 numbers, got [\"a\", 1, 2, "
                 "3]");
    EXPECT_STREQ(parseError("[camera]\nfov = 1979-05-27\n").what(),
                 "scene.toml:2:1: camera.fov must be a number, got a date");
    EXPECT_STREQ(parseError("[camera]\nup = { x = 1 }\n").what(),
                 "scene.toml:2:1: camera.up must be an array of 3 numbers, got a table");
    EXPECT_STREQ(parseError("[render]\nmethod = 1\n").what(),
                 "scene.toml:2:1: render.method must be \"sphere\" or \"fixed-step\", got 1");
}

TEST(SceneFile, RejectsValuesOutOfRangeWithTheirLocation) {
    UserError error = parseError("[render]\n  samples = 0\n");
    EXPECT_EQ(error.key(), "render.samples");
    EXPECT_STREQ(error.what(), "scene.toml:2:3: render.samples = 0 is out of range [1, 1024]");
    EXPECT_STREQ(parseError("[render]\nstep = nan\n").what(),
                 "scene.toml:2:1: render.step must be finite, got nan");
}

TEST(SceneFile, ReportsTheFirstErrorInFileOrder) {
    // toml++ keeps keys sorted ("camera" < "render"); the error should be the first in the file.
    UserError error = parseError("[render]\nwidth = 0\n[camera]\nfov = 0\n");
    EXPECT_EQ(error.key(), "render.width");
}

TEST(SceneFileLoad, ReadsAFile) {
    TemporaryFile file("[render]\nwidth = 100\n");
    EXPECT_EQ(loadScene(file.path()).render.width, 100);
}

TEST(SceneFileLoad, NamesThePathOfAFileItCannotRead) {
    std::string path = "/nonexistent/quaternia/scene.toml";
    UserError error = thrownError([&] { loadScene(path); });
    EXPECT_EQ(error.key(), path);
    EXPECT_EQ(std::string(error.what()),
              "cannot read scene file '" + path + "': No such file or directory");
    std::string directory = std::filesystem::temp_directory_path().string();
    error = thrownError([&] { loadScene(directory); });
    EXPECT_EQ(std::string(error.what()),
              "cannot read scene file '" + directory + "': Is a directory");
}

TEST(SceneFileLoad, NamesThePathInParseErrors) {
    TemporaryFile file("[render]\nwidht = 100\n");
    UserError error = thrownError([&] { loadScene(file.path()); });
    EXPECT_EQ(std::string(error.what()), file.path() +
                                             ":2:1: unknown key 'render.widht' (did you mean "
                                             "'render.width'?)");
}

TEST(SceneFileOverride, ReadsTheValueAsToml) {
    Scene s = defaultScene();
    applyOverride(s, "render.width=640");
    applyOverride(s, "fractal.c=[0,1,0,0]");
    applyOverride(s, "fractal.formula=\"z^3 + c\"");
    applyOverride(s, " camera.fov = 30 ");
    EXPECT_EQ(s.render.width, 640);
    EXPECT_EQ(s.fractal.c, Quaternion(0, 1, 0, 0));
    EXPECT_EQ(s.fractal.formula, "z^3 + c");
    EXPECT_EQ(s.camera.fovDegrees, 30.0);
}

TEST(SceneFileOverride, TakesABareWordAsAString) {
    Scene s = defaultScene();
    applyOverride(s, "fractal.formula=z^3 + c");
    EXPECT_EQ(s.fractal.formula, "z^3 + c");
    applyOverride(s, "render.method=fixed-step");
    EXPECT_EQ(s.render.method, MarchMethod::FixedStep);
    applyOverride(s, "fractal.formula=2");  // valid TOML, but text is wanted
    EXPECT_EQ(s.fractal.formula, "2");
    applyOverride(s, "fractal.formula=z=z");  // only the first '=' separates
    EXPECT_EQ(s.fractal.formula, "z=z");
}

TEST(SceneFileOverride, RejectsAnAssignmentWithoutEquals) {
    UserError error = overrideError("render.width");
    EXPECT_EQ(error.key(), "--set");
    EXPECT_STREQ(error.what(), "--set expects section.key=value, got 'render.width'");
}

TEST(SceneFileOverride, ReportsBadKeysAndValues) {
    UserError error = overrideError("render.widht=640");
    EXPECT_EQ(error.key(), "render.widht");
    EXPECT_STREQ(error.what(), "unknown key 'render.widht' (did you mean 'render.width'?)");
    error = overrideError("render.width=abc");
    EXPECT_EQ(error.key(), "render.width");
    EXPECT_STREQ(error.what(), "render.width must be an integer, got \"abc\"");
    EXPECT_STREQ(overrideError("render.width=0").what(),
                 "render.width = 0 is out of range [1, 16384]");
    EXPECT_STREQ(overrideError("render.width=640\nrender.height=1").what(),
                 "render.width must be an integer, got \"640\\nrender.height=1\"");
}

TEST(SceneFileToToml, RoundTripsTheDefaultScene) {
    expectSameScene(parseScene(sceneToToml(defaultScene())), defaultScene());
}

TEST(SceneFileToToml, RoundTripsAModifiedSceneExactly) {
    Scene s = defaultScene();
    setParameter(s, "fractal.formula", std::string("i*z*j*z + c \"q\" \\ \t end"));
    setParameter(s, "fractal.c", std::vector<double>{0.1 + 0.2, 1.0 / 3, -2.0 / 7, 1e-300});
    setParameter(s, "fractal.bailout", 123456.789);
    setParameter(s, "slice.normal", std::vector<double>{0.2, -0.3, 0.4, 1});
    setParameter(s, "slice.distance", -0.0);
    setParameter(s, "slice.angles", std::vector<double>{1e-7, 359.99999999999994, 0, 0, 0, 0});
    setParameter(s, "camera.position", std::vector<double>{1.0 / 7, 9999.999999999998, -4});
    setParameter(s, "render.width", int64_t{16384});
    setParameter(s, "render.method", std::string("fixed-step"));
    setParameter(s, "render.step", 1e-6);
    setParameter(s, "render.bit_depth", int64_t{16});
    setParameter(s, "shading.shadows", std::string("none"));
    setParameter(s, "shading.coloring", std::string("iteration"));
    setParameter(s, "shading.gamma", 1.0 / 2.2);
    std::string toml = sceneToToml(s);
    expectSameScene(parseScene(toml), s);
    EXPECT_EQ(sceneToToml(parseScene(toml)), toml);
}

TEST(SceneFileToToml, WritesEveryKeyWithItsHelpUnderItsSection) {
    std::string toml = sceneToToml(defaultScene());
    for (const auto& p : parameterTable()) {
        SCOPED_TRACE(p.name());
        EXPECT_NE(toml.find("# " + p.help), std::string::npos);
        EXPECT_NE(toml.find("\n" + p.key + " = " + formatValue(p.defaultValue) + "\n"),
                  std::string::npos);
    }
    EXPECT_NE(toml.find("\n[render]\n"), std::string::npos);
    EXPECT_LT(toml.find("[fractal]"), toml.find("[slice]"));
    EXPECT_LT(toml.find("[camera]"), toml.find("[render]"));
    EXPECT_LT(toml.find("[render]"), toml.find("\nwidth = 1280\n"));
    EXPECT_LT(toml.find("\nwidth = 1280\n"), toml.find("[shading]"));
}

// ---- Issue 16: the algebra, c of 8 components and the slice of the 8-component algebras ----

constexpr const char* kOctonionScene = R"([fractal]
algebra = "octonion"
c = [-0.2, 0.6, 0.2, 0.2, 0.1, -0.3, 0.05, 0.4]

[slice]
origin = [0, 0, 0, 0.5, 0, 0, 0, -0.25]
)";

const std::vector<double> kFlatAxes = {1,   0, 0, 0, 0, 0, 0, 0,  //
                                       0.5, 1, 0, 0, 0, 0, 0, 0,  //
                                       0,   0, 0, 0, 1, 0, 0, 2};

TEST(SceneFile, ReadsAnOctonionScene) {
    Scene s = parseScene(kOctonionScene);
    EXPECT_EQ(s.fractal.algebra, Algebra::kOctonion);
    EXPECT_EQ(s.fractal.cComponents, 8);
    EXPECT_EQ(s.fractal.c, Quaternion(-0.2, 0.6, 0.2, 0.2));
    EXPECT_EQ(s.fractal.cUpper, (std::array<double, 4>{0.1, -0.3, 0.05, 0.4}));
    EXPECT_EQ(s.slice.origin, (std::vector<double>{0, 0, 0, 0.5, 0, 0, 0, -0.25}));
    EXPECT_TRUE(s.slice.axes.empty());
    EXPECT_NO_THROW(validateScene(s));
}

TEST(SceneFile, ReadsSliceAxesNestedOrFlatAlike) {
    const std::string nested = std::string(kOctonionScene) +
                               "axes = [[1, 0, 0, 0, 0, 0, 0, 0], [0.5, 1, 0, 0, 0, 0, 0, 0], "
                               "[0, 0, 0, 0, 1, 0, 0, 2]]\n";
    const std::string flat =
        std::string(kOctonionScene) +
        "axes = [1, 0, 0, 0, 0, 0, 0, 0, 0.5, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 2]\n";
    EXPECT_EQ(parseScene(nested).slice.axes, kFlatAxes);
    EXPECT_EQ(parseScene(flat).slice.axes, kFlatAxes);
    EXPECT_EQ(parseScene(std::string(kOctonionScene) + "axes = []\n").slice.axes,
              std::vector<double>{});
}

TEST(SceneFile, RejectsSliceAxesOfTheWrongShape) {
    // Three arrays of 8 numbers each, or of 4; nested arrays are for slice.axes alone.
    UserError error = parseError("[slice]\naxes = [[1, 0], [0, 1], [1, 1]]\n");
    EXPECT_EQ(error.key(), "slice.axes");
    EXPECT_STREQ(error.what(),
                 "scene.toml:2:1: slice.axes must be an empty array or an array of 12 or 24 "
                 "numbers (or 3 arrays of 4 or 8), got [1.0, 0.0, 0.0, 1.0, 1.0, 1.0]");
    EXPECT_EQ(parseError("[slice]\naxes = [[1, 0, 0, 0], [0, 1, 0, 0, 0, 0, 0, 0], [0, 0, 1, 0]]\n")
                  .key(),
              "slice.axes");
    error = parseError("[slice]\naxes = [[1, 0, 0, 0, 0, 0, 0, 0], [0, 1, 0, 0, 0, 0, 0, 0]]\n");
    EXPECT_EQ(error.key(), "slice.axes");
    EXPECT_NE(
        std::string(error.what()).find("must be an empty array or an array of 12 or 24 numbers"),
        std::string::npos)
        << error.what();
    EXPECT_EQ(parseError("[slice]\naxes = [[1, 0, 0, 0, 0, 0, 0, 0], 1]\n").key(), "slice.axes");
    error = parseError("[fractal]\nc = [[1, 2], [3, 4]]\n");
    EXPECT_EQ(error.key(), "fractal.c");
    EXPECT_STREQ(error.what(),
                 "scene.toml:2:1: fractal.c must be an array of 4 or 8 numbers, got [[1.0, 2.0], "
                 "[3.0, 4.0]]");
    EXPECT_STREQ(parseError("[fractal]\nalgebra = \"sedenion\"\n").what(),
                 "scene.toml:2:1: fractal.algebra must be \"quaternion\", \"bicomplex\", "
                 "\"coquaternion\", \"biquaternion\" or \"octonion\", got \"sedenion\"");
}

TEST(SceneFileOverride, ReadsTheAlgebraAndSliceAxesNestedOrFlat) {
    Scene s = defaultScene();
    applyOverride(s, "fractal.algebra=biquaternion");
    applyOverride(s, "fractal.c=[0, 1, 0, 0, 0, 0, 0, 0.5]");
    applyOverride(s,
                  "slice.axes=[[1, 0, 0, 0, 0, 0, 0, 0], [0.5, 1, 0, 0, 0, 0, 0, 0], "
                  "[0, 0, 0, 0, 1, 0, 0, 2]]");
    EXPECT_EQ(s.fractal.algebra, Algebra::kBiquaternion);
    EXPECT_EQ(s.fractal.cComponents, 8);
    EXPECT_EQ(s.slice.axes, kFlatAxes);
    EXPECT_NO_THROW(validateScene(s));
    applyOverride(s, "slice.axes=[]");
    EXPECT_TRUE(s.slice.axes.empty());
    applyOverride(s,
                  "slice.axes=[1, 0, 0, 0, 0, 0, 0, 0, 0.5, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, "
                  "1, 0, 0, 2]");
    EXPECT_EQ(s.slice.axes, kFlatAxes);
    UserError error = overrideError("slice.axes=[[1, 0], [0, 1], [1, 1]]");
    EXPECT_EQ(error.key(), "slice.axes");
    EXPECT_STREQ(overrideError("fractal.c=[1, 2, 3, 4, 5]").what(),
                 "fractal.c must be an array of 4 or 8 numbers, got [1.0, 2.0, 3.0, 4.0, 5.0]");
}

TEST(SceneFileToToml, RoundTripsAnOctonionSceneExactly) {
    Scene s = parseScene(kOctonionScene);
    setParameter(s, "fractal.c",
                 std::vector<double>{0.1 + 0.2, 1.0 / 3, -2.0 / 7, 1e-300, -9.5, 1.0 / 7, 0, -0.0});
    std::vector<double> axes = kFlatAxes;
    axes[17] = 1.0 / 3;
    setParameter(s, "slice.axes", axes);
    ASSERT_NO_THROW(validateScene(s));
    std::string toml = sceneToToml(s);
    EXPECT_NE(toml.find("\nalgebra = \"octonion\"\n"), std::string::npos) << toml;
    // The axes are written as three arrays of 8.
    EXPECT_NE(toml.find("\naxes = [[1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0], [0.5, 1.0, "),
              std::string::npos)
        << toml;
    Scene again = parseScene(toml);
    expectSameScene(again, s);
    EXPECT_EQ(again.fractal.algebra, Algebra::kOctonion);
    EXPECT_EQ(again.fractal.cUpper, s.fractal.cUpper);
    EXPECT_EQ(again.fractal.cComponents, 8);
    EXPECT_EQ(again.slice.origin, s.slice.origin);
    EXPECT_EQ(again.slice.axes, axes);
    EXPECT_NO_THROW(validateScene(again));
    EXPECT_EQ(sceneToToml(again), toml);
}

}  // namespace
}  // namespace quaternia
