#include "quaternia/scene/presets.h"

#include <algorithm>

#include "quaternia/scene/parameter_text.h"
#include "quaternia/util/edit_distance.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

using Values = std::vector<std::pair<std::string, ParameterValue>>;

Values quadratic(std::vector<double> c) {
    return {{"fractal.formula", std::string("z^2 + c")}, {"fractal.c", std::move(c)}};
}

}  // namespace

const std::vector<Preset>& scenePresets() {
    static const std::vector<Preset> presets = {
        {"rabbit", "Douady's rabbit, c = -0.122561+0.744862i: an attracting 3-cycle",
         quadratic({-0.122561, 0.744862, 0, 0})},
        {"dendrite", "c = i: a dendrite, connected without interior (0 is strictly preperiodic)",
         quadratic({0, 1, 0, 0})},
        {"basilica", "c = -1: the basilica, a superattracting 2-cycle 0 -> -1",
         quadratic({-1, 0, 0, 0})},
        {"4d-blob", "c = -0.2+0.4i-0.4j-0.4k, with j and k parts: a rounded blob",
         quadratic({-0.2, 0.4, -0.4, -0.4})},
        {"cubic",
         "z^3 + c with c = -0.5+0.5i: threefold symmetry",
         {{"fractal.formula", std::string("z^3 + c")},
          {"fractal.c", std::vector{-0.5, 0.5, 0.0, 0.0}}}},
        {"two-sided",
         "(1+2i) z (0.5-k) z + c: coefficients in different complex planes, a truly "
         "quaternion map",
         // |1+2i| |0.5-k| = 2.5 scales the set down by as much, and c with it: the default c,
         // 2.5 times farther out than a c of this size, leaves only dust (nothing drawn).
         {{"fractal.formula", std::string("(1+2i) z (0.5-k) z + c")},
          {"fractal.c", std::vector{-0.1, 0.25, 0.1, 0.1}},
          {"camera.fov", 18.0}}},
        // One per algebra (algebras.md), each with a c that shows its character rather than
        // dust; fractal.algebra alone takes the default c (a shorter c is filled with zeros).
        {"bicomplex",
         "the bicomplex numbers: the product of the rabbit and the basilica, the duplex "
         "components of c = -0.5613+0.3724i+0.3724j-0.4387k",
         {{"fractal.algebra", std::string("bicomplex")},
          {"fractal.formula", std::string("z^2 + c")},
          {"fractal.c", std::vector{-0.5613, 0.3724, 0.3724, -0.4387}},
          {"camera.fov", 36.0}}},
        {"coquaternion",
         "the split quaternions: a closed shell, on a slice turned 90 degrees in the ik plane "
         "so that the null lines (along i+j) leave it",
         {{"fractal.algebra", std::string("coquaternion")},
          {"fractal.formula", std::string("z^2 + c")},
          {"fractal.c", std::vector{-0.3, 0.5, 0.2, -0.2}},
          {"slice.angles", std::vector{0.0, 0.0, 0.0, 0.0, 90.0, 0.0}}}},
        {"biquaternion",
         "the complexified quaternions: c = -0.2+0.6i+0.2j+0.2k+0.1ih on the slice spanned "
         "by i, ih and jh, fluted arms along the null lines",
         {{"fractal.algebra", std::string("biquaternion")},
          {"fractal.formula", std::string("z^2 + c")},
          {"fractal.c", std::vector{-0.2, 0.6, 0.2, 0.2, 0.0, 0.1, 0.0, 0.0}},
          {"slice.axes", std::vector{0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,  //
                                     0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0,  //
                                     0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0}}}},
        {"octonion",
         "the octonions: c with every imaginary part, Re c = -0.1226 and |Im c| = 0.7461 (the "
         "rabbit's), on the slice e0, e1, e6",
         {{"fractal.algebra", std::string("octonion")},
          {"fractal.formula", std::string("z^2 + c")},
          {"fractal.c", std::vector{-0.1226, 0.5, 0.2, 0.2, 0.35, 0.1, 0.29, 0.1}},
          {"slice.axes", std::vector{1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,  //
                                     0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,  //
                                     0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0}}}},
        // Looks (materials and lights, issue 20): the default set, as studio photographs.
        {"studio",
         "a look: the set on a grey floor under a soft key light and a cool rim light",
         {{"ground.enabled", true},
          {"ground.color", std::vector{0.55, 0.55, 0.57}},
          {"shading.background_top", std::vector{0.55, 0.58, 0.65}},
          {"shading.background_bottom", std::vector{0.25, 0.26, 0.28}},
          {"light1.enabled", true},
          {"light1.kind", std::string("point")},
          {"light1.position", std::vector{3.0, 3.0, 4.0}},
          {"light1.color", std::vector{0.6, 0.75, 1.0}},
          {"light1.intensity", 12.0},
          {"render.alpha", std::string("opaque")}}},
        {"chrome",
         "a look: a mirror-polished set over a reflecting floor in a studio of soft boxes",
         {{"material.reflectivity", 0.85},
          {"environment.enabled", true},
          {"environment.builtin", std::string("studio")},
          // Its light without shadow rays: a mirror's own diffuse part is small, and the
          // floor's contact shadow comes from the key light.
          {"environment.samples", int64_t{0}},
          {"shading.light_intensity", 0.6},
          {"shading.ambient", 0.0},
          {"shading.coloring", std::string("solid")},
          {"shading.base_color", std::vector{0.75, 0.76, 0.8}},
          {"ground.enabled", true},
          {"ground.color", std::vector{0.3, 0.3, 0.32}},
          {"ground.reflectivity", 0.2},
          {"shading.background_top", std::vector{0.6, 0.7, 0.9}},
          {"shading.background_bottom", std::vector{0.08, 0.08, 0.1}},
          {"render.alpha", std::string("opaque")}}},
        {"glass",
         "a look: the set as tinted glass (index 1.5) on a floor in a studio of soft boxes",
         {{"material.transparency", 1.0},
          {"environment.enabled", true},
          {"environment.builtin", std::string("studio")},
          // Its light without shadow rays: a mirror's own diffuse part is small, and the
          // floor's contact shadow comes from the key light.
          {"environment.samples", int64_t{0}},
          {"shading.light_intensity", 0.6},
          {"shading.ambient", 0.0},
          {"material.ior", 1.5},
          {"material.absorption", std::vector{0.6, 0.25, 0.1}},
          {"shading.coloring", std::string("solid")},
          {"ground.enabled", true},
          {"ground.color", std::vector{0.55, 0.55, 0.57}},
          {"shading.background_top", std::vector{0.6, 0.7, 0.9}},
          {"shading.background_bottom", std::vector{0.2, 0.2, 0.22}},
          {"render.alpha", std::string("opaque")}}},
        {"sunset",
         "a look: the set on open ground under a low evening sun and the sky's light",
         {{"environment.enabled", true},
          {"environment.builtin", std::string("sky")},
          {"environment.sun_direction", std::vector{-0.7, 0.22, -0.55}},
          {"environment.sun_intensity", 2.5},
          {"environment.sun_color", std::vector{1.0, 0.62, 0.32}},
          {"environment.sky_color", std::vector{0.16, 0.22, 0.45}},
          {"environment.horizon_color", std::vector{0.95, 0.55, 0.3}},
          {"environment.ground_color", std::vector{0.12, 0.08, 0.06}},
          {"shading.light_intensity", 0.0},
          {"shading.fill_color", std::vector{0.0, 0.0, 0.0}},
          {"shading.ambient", 0.0},
          {"shading.base_color", std::vector{0.85, 0.82, 0.78}},
          {"ground.enabled", true},
          {"ground.color", std::vector{0.45, 0.4, 0.35}},
          {"render.alpha", std::string("opaque")}}},
        // Films (`quaternia animate`): the default scene set moving by a shortcut, 30 fps,
        // opaque (over the background gradient), as a video shows it.
        {"hidden-turn",
         "a film: the slice turns a full turn in the jk plane over 4 s, bringing the hidden k "
         "axis into view and back",
         {{"animation.turn_plane", std::string("jk")},
          {"animation.turns", 1.0},
          {"animation.duration", 4.0},
          {"animation.fps", 30.0},
          {"render.alpha", std::string("opaque")}}},
        {"orbit",
         "a film: the camera circles the set once over 6 s",
         {{"animation.orbit_turns", 1.0},
          {"animation.duration", 6.0},
          {"animation.fps", 30.0},
          {"render.alpha", std::string("opaque")}}},
    };
    return presets;
}

const Preset* findPreset(std::string_view name) {
    for (const Preset& preset : scenePresets())
        if (preset.name == name) return &preset;
    return nullptr;
}

void applyPreset(Scene& scene, std::string_view name) {
    const Preset* preset = findPreset(name);
    if (preset == nullptr) {
        // Suggested as an unknown scene key is (NearestName): by edits, then the longer common
        // prefix, then the earlier preset.
        std::vector<std::string> names;
        for (const Preset& candidate : scenePresets())
            names.push_back(candidate.name);
        throw UserError("preset", "unknown preset '" + std::string(name) + "' (did you mean '" +
                                      nearestName(name, names) + "'?)");
    }
    for (const auto& [key, value] : preset->values)
        setParameter(scene, key, value);
}

std::string presetNames() {
    std::string names;
    for (const Preset& preset : scenePresets())
        names += (names.empty() ? "" : ", ") + preset.name;
    return names;
}

std::string presetHelp() {
    std::size_t width = 0;
    for (const Preset& preset : scenePresets())
        width = std::max(width, preset.name.size());
    std::string out = "Presets (--preset NAME):\n";
    for (const Preset& preset : scenePresets())
        out += "  " + preset.name + std::string(width + 2 - preset.name.size(), ' ') +
               preset.description + "\n";
    return out;
}

std::string presetReference() {
    std::string out =
        "\n## Presets\n\n`--preset NAME` (every command that reads a scene, and the explorer's "
        "buttons)\nsets these keys after the scene file and before each `--set`; every other key "
        "keeps its value.\n\n| preset | what | keys it sets |\n|---|---|---|\n";
    for (const Preset& preset : scenePresets()) {
        std::string keys;
        for (const auto& [key, value] : preset.values)
            keys += (keys.empty() ? "" : ", ") +
                    parameter_text::markdownCode(key + " = " + formatValue(value));
        out += "| `" + preset.name + "` | " + parameter_text::markdownCell(preset.description) +
               " | " + keys + " |\n";
    }
    return out;
}

}  // namespace quaternia
