#include "quaternia/scene/scene_rules.h"

#include <functional>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "quaternia/algebra/test_helpers.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

using namespace quaternia::testing;

TEST(ParameterValidateScene, RejectsACameraLookingAtItsOwnPosition) {
    Scene s = defaultScene();
    s.camera.lookAt = s.camera.position;
    UserError error = thrownError([&] { validateScene(s); });
    EXPECT_EQ(error.key(), "camera.look_at");
    EXPECT_NE(std::string(error.what()).find("equals camera.position"), std::string::npos);
}

TEST(ParameterValidateScene, RejectsAnUpVectorParallelToTheView) {
    Scene s = defaultScene();
    s.camera.up = (s.camera.lookAt - s.camera.position) * -2.0;
    UserError error = thrownError([&] { validateScene(s); });
    EXPECT_EQ(error.key(), "camera.up");
    EXPECT_NE(std::string(error.what()).find("parallel to the view direction"), std::string::npos);
    s.camera.up = Vector3d(0, 0, 0);
    EXPECT_EQ(thrownError([&] { validateScene(s); }).key(), "camera.up");
}

TEST(ParameterValidateScene, RejectsASliceNormalWithoutAWComponent) {
    Scene s = defaultScene();
    s.slice.normal = Quaternion(0, 0, 0, 0);
    UserError error = thrownError([&] { validateScene(s); });
    EXPECT_EQ(error.key(), "slice.normal");
    EXPECT_STREQ(error.what(), "slice.normal must not be zero");

    setParameter(s, "slice.normal", std::vector<double>{1, 2, 3, 0});
    error = thrownError([&] { validateScene(s); });
    EXPECT_EQ(error.key(), "slice.normal");
    EXPECT_NE(std::string(error.what()).find("w = (distance - s.xyz) / s_w"), std::string::npos);

    setParameter(s, "slice.normal", std::vector<double>{1, 2, 3, 0.01});  // tilted is fine
    EXPECT_NO_THROW(validateScene(s));
}

TEST(ParameterValidateScene, RejectsZeroRotationsAndLightDirections) {
    const char* keys[] = {"slice.left", "slice.right", "shading.light_direction",
                          "shading.fill_direction"};
    for (const char* key : keys) {
        SCOPED_TRACE(key);
        Scene s = defaultScene();
        const Parameter* p = findParameter(key);
        p->apply(s, std::vector<double>(std::get<std::vector<double>>(p->defaultValue).size()));
        UserError error = thrownError([&] { validateScene(s); });
        EXPECT_EQ(error.key(), key);
        EXPECT_NE(std::string(error.what()).find("must not be zero"), std::string::npos);
    }
}

TEST(ParameterValidateScene, LimitsTheTotalNumberOfSamples) {
    Scene s = defaultScene();
    s.render.width = s.render.height = 16384;
    s.render.samples = 16;
    EXPECT_NO_THROW(validateScene(s));  // exactly the limit
    s.render.samples = 17;
    UserError error = thrownError([&] { validateScene(s); });
    EXPECT_EQ(error.key(), "render.samples");
    EXPECT_NE(std::string(error.what()).find("more than the limit of 4294967296"),
              std::string::npos);
}

TEST(ParameterValidateScene, RechecksTheRangesOfScenesBuiltInCode) {
    Scene s = defaultScene();
    s.render.width = 0;
    UserError error = thrownError([&] { validateScene(s); });
    EXPECT_EQ(error.key(), "render.width");
    EXPECT_STREQ(error.what(), "render.width = 0 is out of range [1, 16384]");

    s = defaultScene();
    s.render.method = static_cast<MarchMethod>(7);
    EXPECT_EQ(thrownError([&] { validateScene(s); }).key(), "render.method");
    EXPECT_THROW(validateScene(Scene{}), UserError);
}

TEST(SceneRules, EachAcceptsTheDefaultScene) {
    const Scene scene = defaultScene();
    std::set<std::string_view> names;
    for (const SceneRule& rule : sceneRules()) {
        EXPECT_NO_THROW(rule.check(scene)) << rule.name;
        EXPECT_FALSE(rule.name.empty());
        EXPECT_TRUE(names.insert(rule.name).second) << "twice: " << rule.name;
    }
    EXPECT_NO_THROW(validateScene(scene));
}

// A rule, a scene that breaks it alone, and the key of its message.
struct Breakage {
    std::string_view rule;
    std::function<void(Scene&)> breakScene;
    std::string key;
};

std::vector<Breakage> breakages() {
    auto eightComponents = [](Scene& s) {
        setParameter(s, "fractal.algebra", std::string("octonion"));
        setParameter(s, "fractal.c", std::vector<double>(8, 0.1));
    };
    return {
        {"every value is in its range", [](Scene& s) { s.render.width = 0; }, "render.width"},
        {"the camera has a view direction", [](Scene& s) { s.camera.lookAt = s.camera.position; },
         "camera.look_at"},
        {"camera.up is not along the view",
         [](Scene& s) { s.camera.up = s.camera.lookAt - s.camera.position; }, "camera.up"},
        {"fractal.c has the algebra's number of components",
         [](Scene& s) { setParameter(s, "fractal.c", std::vector<double>(8, 0.1)); }, "fractal.c"},
        {"8-component slices keep the quaternion slice keys at their defaults",
         [&](Scene& s) {
             eightComponents(s);
             s.slice.distance = 0.5;
         },
         "slice.distance"},
        {"slice.axes are independent",
         [&](Scene& s) {
             eightComponents(s);
             s.slice.axes = std::vector<double>(24, 1.0);
         },
         "slice.axes"},
        {"only 8-component slices take slice.origin and slice.axes",
         [](Scene& s) { s.slice.origin = std::vector<double>(8, 0.0); }, "slice.origin"},
        {"slice.normal is not zero", [](Scene& s) { s.slice.normal = Quaternion(0, 0, 0, 0); },
         "slice.normal"},
        {"slice.normal has a w component",
         [](Scene& s) { s.slice.normal = Quaternion(1, 0, 0, 0); }, "slice.normal"},
        {"slice.left is not zero", [](Scene& s) { s.slice.left = Quaternion(0, 0, 0, 0); },
         "slice.left"},
        {"slice.right is not zero", [](Scene& s) { s.slice.right = Quaternion(0, 0, 0, 0); },
         "slice.right"},
        {"shading.light_direction is not zero",
         [](Scene& s) { s.shading.lightDirection = Vector3d(0, 0, 0); }, "shading.light_direction"},
        {"a spot light aims away from itself",
         [](Scene& s) {
             s.shading.lightKind = LightKind::Spot;
             s.shading.spotTarget = s.shading.lightPosition;
         },
         "shading.spot_target"},
        {"shading.fill_direction is not zero",
         [](Scene& s) { s.shading.fillDirection = Vector3d(0, 0, 0); }, "shading.fill_direction"},
        {"the total number of samples is within the limit",
         [](Scene& s) {
             s.render.width = s.render.height = 16384;
             s.render.samples = 17;
         },
         "render.samples"},
    };
}

// Each rule refuses its own breakage, and no rule before it does: validateScene's message is
// that rule's.
TEST(SceneRules, EachRefusesItsOwnBreakageFirst) {
    const auto rules = sceneRules();
    const std::vector<Breakage> all = breakages();
    ASSERT_EQ(all.size(), rules.size());
    for (std::size_t i = 0; i < rules.size(); ++i) {
        SCOPED_TRACE(rules[i].name);
        ASSERT_EQ(all[i].rule, rules[i].name);
        Scene s = defaultScene();
        all[i].breakScene(s);
        for (std::size_t before = 0; before < i; ++before)
            EXPECT_NO_THROW(rules[before].check(s)) << rules[before].name;
        const UserError own = thrownError([&] { rules[i].check(s); });
        const UserError reported = thrownError([&] { validateScene(s); });
        EXPECT_EQ(own.key(), all[i].key);
        EXPECT_EQ(reported.key(), own.key());
        EXPECT_STREQ(reported.what(), own.what());
    }
}

// A scene that breaks several rules is told of the first in sceneRules' order, and of the next
// once that is mended.
TEST(SceneRules, ReportsTheFirstBrokenRuleInOrder) {
    Scene s = defaultScene();
    s.shading.fillDirection = Vector3d(0, 0, 0);
    s.slice.left = Quaternion(0, 0, 0, 0);
    s.camera.lookAt = s.camera.position;
    EXPECT_EQ(thrownError([&] { validateScene(s); }).key(), "camera.look_at");
    s.camera.lookAt = defaultScene().camera.lookAt;
    EXPECT_EQ(thrownError([&] { validateScene(s); }).key(), "slice.left");
    s.slice.left = defaultScene().slice.left;
    EXPECT_STREQ(thrownError([&] { validateScene(s); }).what(),
                 "shading.fill_direction must not be zero");
}

}  // namespace
}  // namespace quaternia
