// Films (animation.h, animation_file.h): frames at their times, keys read from scene files and
// --set, the shortcut motions, and every bad input as one UserError naming it.
#include "quaternia/scene/animation.h"

#include <gtest/gtest.h>

#include <cmath>

#include "quaternia/algebra/test_helpers.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_file.h"

namespace quaternia {
namespace {

using testing::thrownError;

constexpr const char* kTwoKeys = R"([animation]
fps = 10

[[animation.keys]]
time = 0
"fractal.c" = [-0.2, 0.6, 0.2, 0.2]
fractal.max_iterations = 8

[[animation.keys]]
time = 2
interpolation = "linear"
"fractal.c" = [-0.4, 0.4, 0, 0]
fractal.max_iterations = 13

[[animation.keys]]
time = 3
"fractal.c" = [-0.4, 0.2, 0, 0]
)";

TEST(Animation, FramesUpToTheLastKeyAtTheirTimes) {
    Scene film = parseScene(kTwoKeys);
    validateAnimation(film);
    EXPECT_EQ(filmFrameCount(film), 31);  // t = 0, 0.1, ..., 3.0
    Scene first = sceneAtFrame(film, 1), atKey = sceneAtFrame(film, 21),
          last = sceneAtFrame(film, 31);
    EXPECT_EQ(first.fractal.c, Quaternion(-0.2, 0.6, 0.2, 0.2));
    EXPECT_EQ(atKey.fractal.c, Quaternion(-0.4, 0.4, 0, 0));
    EXPECT_EQ(last.fractal.c, Quaternion(-0.4, 0.2, 0, 0));
    EXPECT_EQ(first.fractal.maxIterations, 8);
    EXPECT_EQ(atKey.fractal.maxIterations, 13);
    EXPECT_EQ(last.fractal.maxIterations, 13);  // held after its last key
    // The linear segment from t = 2: half way at t = 2.5, frame 26.
    testing::expectNear(sceneAtFrame(film, 26).fractal.c, Quaternion(-0.4, 0.3, 0, 0));
    // Integers are rounded: 8 -> 13 smoothly over two seconds, never a fraction.
    for (int frame = 1; frame <= 21; ++frame) {
        int n = sceneAtFrame(film, frame).fractal.maxIterations;
        EXPECT_GE(n, 8);
        EXPECT_LE(n, 13);
    }
    // What no key names keeps the scene's value; the frame has no animation left.
    EXPECT_EQ(atKey.camera.position, defaultScene().camera.position);
    EXPECT_TRUE(atKey.animation.keys.empty());
    EXPECT_FALSE(isAnimated(atKey));
}

TEST(Animation, FrameCountFromFramesOrDuration) {
    Scene film = parseScene(kTwoKeys);
    applyOverride(film, "animation.duration=4");
    EXPECT_EQ(filmFrameCount(film), 40);
    applyOverride(film, "animation.frames=7");
    EXPECT_EQ(filmFrameCount(film), 7);
}

TEST(Animation, KeysRoundTripThroughTheSceneFileAndSet) {
    Scene film = parseScene(kTwoKeys);
    Scene again = parseScene(sceneToToml(film));
    ASSERT_EQ(again.animation.keys.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(again.animation.keys[i].time, film.animation.keys[i].time);
        EXPECT_EQ(again.animation.keys[i].values, film.animation.keys[i].values);
        EXPECT_EQ(again.animation.keys[i].interpolation, film.animation.keys[i].interpolation);
    }
    Scene set = defaultScene();
    applyOverride(set, "animation.fps=10");
    applyOverride(set,
                  "animation.keys=[{time = 0, \"fractal.c\" = [0, 1, 0, 0]}, "
                  "{time = 1, fractal.c = [0, 0.5, 0, 0], interpolation = \"ease\"}]");
    ASSERT_EQ(set.animation.keys.size(), 2u);
    EXPECT_EQ(set.animation.keys[1].interpolation, Interpolation::Ease);
    EXPECT_EQ(sceneAtFrame(set, 11).fractal.c, Quaternion(0, 0.5, 0, 0));
}

TEST(Animation, TextChangesOnlyAtAStepKey) {
    Scene film = parseScene(
        "[[animation.keys]]\ntime = 0\ninterpolation = \"step\"\n\"fractal.formula\" = \"z^2 + "
        "c\"\n"
        "[[animation.keys]]\ntime = 1\ninterpolation = \"step\"\n\"fractal.formula\" = \"z^3 + "
        "c\"\n");
    EXPECT_EQ(sceneAtTime(film, 0.99).fractal.formula, "z^2 + c");
    EXPECT_EQ(sceneAtTime(film, 1).fractal.formula, "z^3 + c");
    UserError error = thrownError(
        [] { parseScene("[[animation.keys]]\ntime = 0\n\"fractal.formula\" = \"z^3 + c\"\n"); });
    EXPECT_EQ(error.key(), "fractal.formula");
    EXPECT_NE(std::string(error.what()).find("interpolation = \"step\""), std::string::npos);
}

TEST(Animation, HiddenDimensionTurnsOnceOverTheFilm) {
    Scene film = defaultScene();
    applyOverride(film, "animation.turn_plane=jk");
    applyOverride(film, "animation.frames=8");
    EXPECT_EQ(sceneAtFrame(film, 1).slice.anglesDegrees[5], 0);
    EXPECT_DOUBLE_EQ(sceneAtFrame(film, 3).slice.anglesDegrees[5], 90);  // the quarter turn
    EXPECT_DOUBLE_EQ(sceneAtFrame(film, 8).slice.anglesDegrees[5], 315);
    // Added to what the keys say.
    applyOverride(film, "animation.keys=[{time = 0, \"slice.angles\" = [0, 0, 0, 0, 0, 10]}]");
    EXPECT_DOUBLE_EQ(sceneAtFrame(film, 3).slice.anglesDegrees[5], 100);
}

TEST(Animation, CameraOrbitKeepsItsDistanceAndHeight) {
    Scene film = defaultScene();
    applyOverride(film, "animation.orbit_turns=1");
    applyOverride(film, "animation.frames=4");
    Vector3d start = film.camera.position - film.camera.lookAt;
    for (int frame = 1; frame <= 4; ++frame) {
        Vector3d v = sceneAtFrame(film, frame).camera.position - film.camera.lookAt;
        EXPECT_NEAR(length(v), length(start), 1e-12);
        EXPECT_NEAR(v.y, start.y, 1e-12);  // camera.up is y
    }
    Vector3d quarter = sceneAtFrame(film, 2).camera.position - film.camera.lookAt;
    EXPECT_NEAR(quarter.x * start.x + quarter.z * start.z, 0, 1e-12);  // turned 90 degrees
}

TEST(Animation, CTravelsACircleAboutItsValue) {
    Scene film = defaultScene();
    applyOverride(film, "animation.c_radius=0.1");
    applyOverride(film, "animation.c_plane=1j");
    applyOverride(film, "animation.duration=2");
    for (int frame = 1; frame <= 60; frame += 7) {
        Quaternion d = sceneAtFrame(film, frame).fractal.c - film.fractal.c;
        EXPECT_NEAR(std::hypot(d.w, d.y), 0.1, 1e-12);
        EXPECT_EQ(d.x, 0);
        EXPECT_EQ(d.z, 0);
    }
}

TEST(Animation, BadKeysAreOneErrorNamingTheProblem) {
    auto keyError = [](const std::string& keys) {
        return thrownError([&] { parseScene("[animation]\nfps = 24\n" + keys); });
    };
    UserError unknown = keyError("[[animation.keys]]\ntime = 0\n\"fractal.cc\" = 1\n");
    EXPECT_EQ(unknown.key(), "fractal.cc");
    EXPECT_NE(std::string(unknown.what()).find("did you mean 'fractal.c'"), std::string::npos);
    UserError order = keyError(
        "[[animation.keys]]\ntime = 2\nfractal.bailout = 3\n[[animation.keys]]\ntime = 1\n"
        "fractal.bailout = 4\n");
    EXPECT_EQ(order.key(), "animation.keys");
    EXPECT_NE(std::string(order.what()).find("increasing time order"), std::string::npos);
    EXPECT_EQ(keyError("[[animation.keys]]\ntime = 1\nfractal.bailout = 3\n[[animation.keys]]\n"
                       "time = 1\nfractal.bailout = 4\n")
                  .key(),
              "animation.keys");
    EXPECT_EQ(keyError("[[animation.keys]]\nfractal.bailout = 3\n").key(), "animation.keys");
    EXPECT_EQ(keyError("[[animation.keys]]\ntime = 0\n\"animation.fps\" = 3\n").key(),
              "animation.fps");
    EXPECT_EQ(keyError("[[animation.keys]]\ntime = 0\n\"render.width\" = 0\n").key(),
              "render.width");
    EXPECT_EQ(thrownError([] { parseScene("[animation]\nfps = 0\n"); }).key(), "animation.fps");
    EXPECT_EQ(thrownError([] { filmFrameCount(defaultScene()); }).key(), "animation");
    Scene shortcutOnly = defaultScene();
    applyOverride(shortcutOnly, "animation.orbit_turns=1");
    EXPECT_EQ(thrownError([&] { filmFrameCount(shortcutOnly); }).key(), "animation.duration");
}

TEST(Animation, EightComponentsOfCMoveComponentByComponent) {
    Scene film = parseScene(R"([fractal]
algebra = "octonion"
c = [0, 0, 0, 0, 0, 0, 0, 0]

[animation]
fps = 10

[[animation.keys]]
time = 0
interpolation = "linear"
"fractal.c" = [0, 0, 0, 0, 0, 0, 0, 0]

[[animation.keys]]
time = 1
"fractal.c" = [0.2, 0, 0, 0, 0.4, 0, 0, -1]
)");
    validateAnimation(film);
    Scene half = sceneAtFrame(film, 6);  // t = 0.5
    EXPECT_EQ(half.fractal.cComponents, 8);
    testing::expectNear(half.fractal.c, Quaternion(0.1, 0, 0, 0));
    EXPECT_NEAR(half.fractal.cUpper[0], 0.2, 1e-12);
    EXPECT_NEAR(half.fractal.cUpper[3], -0.5, 1e-12);
    EXPECT_NO_THROW(validateScene(half));
}

TEST(Animation, KeysWithDifferentLengthsOfCAreAnErrorNamingIt) {
    Scene film = parseScene(R"([animation]
fps = 10

[[animation.keys]]
time = 0
"fractal.c" = [0, 0, 0, 0]

[[animation.keys]]
time = 1
"fractal.c" = [0, 0, 0, 0, 0, 0, 0, 1]
)");
    UserError error = thrownError([&] { validateAnimation(film); });
    EXPECT_EQ(error.key(), "fractal.c");
    EXPECT_STREQ(error.what(),
                 "animation key 2 (time 1.0): fractal.c has 8 components, but an earlier key "
                 "gives it 4; every key of a parameter needs as many");
    EXPECT_EQ(thrownError([&] { sceneAtTime(film, 0.5); }).key(), "fractal.c");
}

TEST(Animation, CCircleKeepsTheUpperComponents) {
    Scene film = defaultScene();
    applyOverride(film, "fractal.algebra=octonion");
    applyOverride(film, "fractal.c=[0, 0, 0, 0, 0.1, 0.2, 0.3, 0.4]");
    applyOverride(film, "animation.c_radius=0.1");
    applyOverride(film, "animation.duration=2");
    Scene frame = sceneAtFrame(film, 16);
    EXPECT_EQ(frame.fractal.cComponents, 8);
    EXPECT_EQ(frame.fractal.cUpper, film.fractal.cUpper);
    EXPECT_NEAR(std::hypot(frame.fractal.c.w, frame.fractal.c.x), 0.1, 1e-12);
    EXPECT_NO_THROW(validateScene(frame));
}

}  // namespace
}  // namespace quaternia
