#include "quaternia/scene/presets.h"

#include <set>

#include <gtest/gtest.h>

#include "quaternia/algebra/test_helpers.h"
#include "quaternia/scene/scene_file.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

using namespace quaternia::testing;

TEST(Presets, EachIsNamedOnceDescribedAndValidThroughTheTable) {
    std::set<std::string> names;
    for (const Preset& preset : scenePresets()) {
        SCOPED_TRACE(preset.name);
        EXPECT_TRUE(names.insert(preset.name).second) << "declared twice";
        EXPECT_EQ(findPreset(preset.name), &preset);
        EXPECT_FALSE(preset.description.empty());
        EXPECT_EQ(preset.description.find('\n'), std::string::npos);
        ASSERT_FALSE(preset.values.empty());
        Scene scene = defaultScene();
        EXPECT_NO_THROW(applyPreset(scene, preset.name));
        EXPECT_NO_THROW(validateScene(scene));
        // Every key it names now holds its value, exactly as the table reads it back.
        for (const auto& [key, value] : preset.values) {
            const Parameter* p = findParameter(key);
            ASSERT_NE(p, nullptr) << key;
            EXPECT_EQ(p->read(scene), checkedValue(*p, value)) << key;
        }
    }
    // The explorer's list: the same names, in the same order.
    std::vector<std::string> order;
    for (const Preset& preset : scenePresets())
        order.push_back(preset.name);
    EXPECT_EQ(order, (std::vector<std::string>{"rabbit", "dendrite", "basilica", "4d-blob", "cubic",
                                               "two-sided", "bicomplex", "coquaternion",
                                               "biquaternion", "octonion", "studio", "chrome",
                                               "glass", "sunset", "hidden-turn", "orbit"}));
}

TEST(Presets, RabbitIsTheSceneWithItsKeysSetByHand) {
    Scene preset = defaultScene();
    applyPreset(preset, "rabbit");
    Scene byHand = defaultScene();
    applyOverride(byHand, "fractal.formula=z^2 + c");
    applyOverride(byHand, "fractal.c=[-0.122561, 0.744862, 0, 0]");
    EXPECT_EQ(sceneToToml(preset), sceneToToml(byHand));
    EXPECT_NE(sceneToToml(preset), sceneToToml(defaultScene()));
}

TEST(Presets, LeaveKeysTheyDoNotNameAlone) {
    Scene scene = defaultScene();
    applyOverride(scene, "render.width=64");
    applyOverride(scene, "fractal.max_iterations=20");
    applyPreset(scene, "cubic");
    EXPECT_EQ(scene.render.width, 64);
    EXPECT_EQ(scene.fractal.maxIterations, 20);
    EXPECT_EQ(scene.fractal.formula, "z^3 + c");
}

TEST(Presets, AnUnknownNameSuggestsTheNearest) {
    Scene scene = defaultScene();
    UserError error = thrownError([&] { applyPreset(scene, "rabit"); });
    EXPECT_EQ(error.key(), "preset");
    EXPECT_STREQ(error.what(), "unknown preset 'rabit' (did you mean 'rabbit'?)");
    EXPECT_STREQ(thrownError([&] { applyPreset(scene, "basilisk"); }).what(),
                 "unknown preset 'basilisk' (did you mean 'basilica'?)");
    EXPECT_EQ(sceneToToml(scene), sceneToToml(defaultScene()));
}

TEST(Presets, HelpListsEveryNameWithItsDescription) {
    std::string help = presetHelp();
    for (const Preset& preset : scenePresets())
        EXPECT_NE(help.find("  " + preset.name + " "), std::string::npos) << preset.name;
    EXPECT_NE(help.find("  rabbit        Douady's rabbit"), std::string::npos) << help;
}

// docs/parameters.md's presets: a row of each, with its line and every key it sets.
TEST(PresetReference, HasARowOfEveryPresetWithTheKeysItSets) {
    const std::string reference = presetReference();
    EXPECT_EQ(reference.rfind("\n## Presets\n", 0), 0u);
    for (const Preset& preset : scenePresets()) {
        SCOPED_TRACE(preset.name);
        const std::size_t row = reference.find("| `" + preset.name + "` | ");
        ASSERT_NE(row, std::string::npos);
        const std::string line = reference.substr(row, reference.find('\n', row) - row);
        for (const auto& [key, value] : preset.values)
            EXPECT_NE(line.find("`" + key + " = " + formatValue(value) + "`"), std::string::npos);
    }
    EXPECT_NE(reference.find("`fractal.c = [-1.0, 0.0, 0.0, 0.0]`"), std::string::npos);
}

}  // namespace
}  // namespace quaternia
