// The table entries of the scene around the set: the lights besides the key light
// ([light1] .. [light7], each section built by the same function), the set's material
// ([material]), the ground plane ([ground]) and the world around them ([environment]).
#include <iterator>
#include <string>
#include <vector>

#include "quaternia/scene/parameter_builders.h"

namespace quaternia::parameter_builders {
namespace {

std::vector<std::pair<std::string, LightKind>> lightKinds() {
    return {{"directional", LightKind::Directional},
            {"point", LightKind::Point},
            {"spot", LightKind::Spot}};
}

std::vector<std::pair<std::string, Shadows>> shadowKinds() {
    return {{"soft", Shadows::Soft}, {"hard", Shadows::Hard}, {"none", Shadows::None}};
}

// [lightN]: light N besides the key light; off until enabled.
void appendLight(std::vector<Parameter>& table, std::size_t index) {
    using G = LightSettings;
    const std::string section = "light" + std::to_string(index + 1);
    const LightSlot slot{index};
    table.push_back(booleanParameter(section, "enabled", slot, &G::enabled, false,
                                     "Whether this light shines (lights besides the key light of "
                                     "[shading]; at most 7)"));
    table.push_back(choiceParameter(section, "kind", slot, &G::kind, "point", lightKinds(),
                                    "directional (from direction, infinitely far), point (at "
                                    "position, inverse-square falloff) or spot (a point light "
                                    "shining into a cone towards spot_target)"));
    table.push_back(vectorParameter(section, "direction", slot, &G::direction, {0.5, 0.6, 0.4},
                                    -1e3, 1e3,
                                    "Direction towards a directional light; any length"));
    table.push_back(vectorParameter(section, "position", slot, &G::position, {4.0, 4.0, -3.0}, -1e3,
                                    1e3, "Position of a point or spot light"));
    table.push_back(vectorParameter(section, "color", slot, &G::color, {1.0, 1.0, 1.0}, 0, 100,
                                    "Linear RGB colour of the light"));
    table.push_back(realParameter(section, "intensity", slot, &G::intensity, 20, 0, 1e6,
                                  "Multiplies color; point and spot lights give color x "
                                  "intensity / distance^2"));
    table.push_back(vectorParameter(section, "spot_target", slot, &G::spotTarget, {0.0, 0.0, 0.0},
                                    -1e3, 1e3, "The point a spot light aims at"));
    table.push_back(realParameter(section, "spot_angle", slot, &G::spotAngle, 25, 0.1, 90,
                                  "Half-angle of a spot light's cone in degrees"));
    table.push_back(realParameter(section, "spot_softness", slot, &G::spotSoftness, 0.2, 0, 1,
                                  "Fraction of spot_angle over which the spot's edge fades out"));
    table.push_back(choiceParameter(section, "shadows", slot, &G::shadows, "soft", shadowKinds(),
                                    "Shadows of this light: soft (the penumbra of its radius), "
                                    "hard or none"));
    table.push_back(realParameter(section, "radius", slot, &G::radius, 0.3, 0, 1e3,
                                  "Radius of a point or spot light in world units: the size of "
                                  "its soft shadows' penumbrae (0 gives hard shadows)"));
    table.push_back(realParameter(section, "angular_radius", slot, &G::angularRadius, 2, 0, 45,
                                  "Angular radius of a directional light in degrees (the sun's "
                                  "is 0.27): the size of its soft shadows' penumbrae"));
}

// [material]: what the surface of the set is made of: reflection, gloss and glass.
std::vector<Parameter> materialParameters() {
    using S = Scene;
    using M = MaterialSettings;
    return {
        realParameter("material", "reflectivity", &S::material, &M::reflectivity, 0, 0, 1,
                      "Reflectance of the surface at normal incidence, rising to 1 at grazing "
                      "angles (Schlick's Fresnel); 1 is a mirror"),
        realParameter("material", "roughness", &S::material, &M::roughness, 0, 0, 1,
                      "Glossy reflection: the spread of reflected rays (0 is a sharp mirror); "
                      "the pixel's samples share it out"),
        realParameter("material", "transparency", &S::material, &M::transparency, 0, 0, 1,
                      "Part of the light not reflected that enters the set as through glass "
                      "(refraction by ior); 0 is opaque"),
        realParameter("material", "ior", &S::material, &M::ior, 1.5, 1, 4,
                      "Index of refraction of a transparent set (glass 1.5, water 1.33, "
                      "diamond 2.42)"),
        vectorParameter("material", "absorption", &S::material, &M::absorption, {0.0, 0.0, 0.0}, 0,
                        1000,
                        "Absorption per unit of distance inside a transparent set, per RGB "
                        "channel (Beer-Lambert: exp(-absorption x length) passes)"),
        integerParameter("material", "max_depth", &S::material, &M::maxDepth, 4, 1, 16,
                         "Bounces (reflections and refractions) a path may take; what is left "
                         "after them sees the background"),
        integerParameter("material", "inside_steps", &S::material, &M::insideSteps, 32, 8, 4096,
                         "Fixed steps across the set's bounding sphere that refracted rays take "
                         "inside the set (no distance estimate holds inside); gaps narrower than "
                         "a step are crossed as glass"),
    };
}

// [ground]: a plane under the set, to stand on, reflect it or catch its shadow.
std::vector<Parameter> groundParameters() {
    using S = Scene;
    using G = GroundSettings;
    return {
        booleanParameter("ground", "enabled", &S::ground, &G::enabled, false,
                         "Whether a horizontal ground plane lies under the set"),
        realParameter("ground", "height", &S::ground, &G::height, -1.2, -1e3, 1e3,
                      "The plane's height: the plane y = height"),
        vectorParameter("ground", "color", &S::ground, &G::color, {0.5, 0.5, 0.5}, 0, 100,
                        "Linear RGB colour of the ground"),
        realParameter("ground", "reflectivity", &S::ground, &G::reflectivity, 0, 0, 1,
                      "Reflectance of the ground at normal incidence, rising to 1 at grazing "
                      "angles (Schlick's Fresnel)"),
        booleanParameter("ground", "shadow_catcher", &S::ground, &G::shadowCatcher, false,
                         "Draw the ground only where the set shadows it, as alpha over the "
                         "background (for compositing)"),
    };
}

// [environment]: the world around the scene as light: a map or the built-in sky or studio.
std::vector<Parameter> environmentParameters() {
    using S = Scene;
    using E = EnvironmentSettings;
    const std::vector<std::pair<std::string, EnvironmentBuiltin>> builtins = {
        {"sky", EnvironmentBuiltin::Sky}, {"studio", EnvironmentBuiltin::Studio}};
    return {
        booleanParameter("environment", "enabled", &S::environment, &E::enabled, false,
                         "Whether an environment surrounds the scene: what reflections, "
                         "refractions and the background see, and light on the set"),
        textParameter("environment", "map", &S::environment, &E::map, "", 0, 4096,
                      "A latitude-longitude HDR image (OpenEXR .exr or Radiance .hdr, twice as "
                      "wide as high), its top row towards camera.up; empty: the built-in"),
        choiceParameter("environment", "builtin", &S::environment, &E::builtin, "sky", builtins,
                        "Without a map: sky (a gradient and a sun, the sun_* and *_color keys) "
                        "or studio (soft boxes over a dark floor)"),
        realParameter("environment", "intensity", &S::environment, &E::intensity, 1, 0, 1e4,
                      "Multiplies the environment's radiance (not the sun's)"),
        realParameter("environment", "rotation", &S::environment, &E::rotation, 0, -3600, 3600,
                      "Turns the environment by this many degrees about camera.up's axis"),
        booleanParameter("environment", "background", &S::environment, &E::background, true,
                         "Show the environment behind the set (false: the shading.background "
                         "gradient; reflections still see the environment)"),
        booleanParameter("environment", "lighting", &S::environment, &E::lighting, true,
                         "Light the set and the ground with the environment's diffuse light"),
        integerParameter("environment", "samples", &S::environment, &E::samples, 4, 0,
                         kMaxEnvironmentSamples,
                         "Shadow rays per hit towards the environment (importance-sampled): the "
                         "set's occlusion of its light; 0 lights without occlusion"),
        vectorParameter("environment", "sun_direction", &S::environment, &E::sunDirection,
                        {0.6, 0.5, -0.4}, -1e3, 1e3,
                        "Direction towards the built-in sky's sun; any length"),
        realParameter("environment", "sun_intensity", &S::environment, &E::sunIntensity, 2, 0, 1e4,
                      "The sun's irradiance, as a directional light's intensity (0: no sun)"),
        realParameter("environment", "sun_size", &S::environment, &E::sunSize, 0.8, 0.05, 20,
                      "The sun's angular radius in degrees (the real sun's is 0.27): its disc and "
                      "its shadows' penumbrae"),
        vectorParameter("environment", "sun_color", &S::environment, &E::sunColor,
                        {1.0, 0.95, 0.85}, 0, 100, "Linear RGB colour of the sun"),
        vectorParameter("environment", "sky_color", &S::environment, &E::skyColor,
                        {0.25, 0.42, 0.8}, 0, 1e3,
                        "Linear RGB radiance of the built-in sky overhead"),
        vectorParameter("environment", "horizon_color", &S::environment, &E::horizonColor,
                        {0.75, 0.8, 0.85}, 0, 1e3,
                        "Linear RGB radiance of the built-in sky at the horizon"),
        vectorParameter("environment", "ground_color", &S::environment, &E::groundColor,
                        {0.18, 0.16, 0.14}, 0, 1e3,
                        "Linear RGB radiance of the built-in sky below the horizon"),
    };
}

}  // namespace

std::vector<Parameter> sceneryParameters() {
    std::vector<Parameter> table;
    for (std::size_t i = 0; i < std::size_t(kExtraLights); ++i)
        appendLight(table, i);
    for (auto section : {materialParameters, groundParameters, environmentParameters}) {
        std::vector<Parameter> entries = section();
        table.insert(table.end(), std::make_move_iterator(entries.begin()),
                     std::make_move_iterator(entries.end()));
    }
    return table;
}

}  // namespace quaternia::parameter_builders
