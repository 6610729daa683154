// The table's sections of how the set is seen and lit: [camera], [render] and [shading]
// (parameter_sections.h).
#include "quaternia/scene/parameter_builders.h"
#include "quaternia/scene/parameter_sections.h"

namespace quaternia::parameter_builders {

// [camera]: where the set is seen from: POV-Ray's camera, with a thin lens.
std::vector<Parameter> cameraParameters() {
    using S = Scene;
    using C = CameraSettings;
    return {
        vectorParameter("camera", "position", &S::camera, &C::position, {1.25, 1.875, -5}, -1e4,
                        1e4, "Camera location in world space (POV-Ray's location)"),
        vectorParameter("camera", "look_at", &S::camera, &C::lookAt, {0, 0, 0}, -1e4, 1e4,
                        "The point the camera looks at, drawn at the image centre"),
        vectorParameter("camera", "up", &S::camera, &C::up, {0, 1, 0}, -1e4, 1e4,
                        "Sky vector, the image's up direction; must not be parallel to the view "
                        "direction"),
        realParameter("camera", "aperture", &S::camera, &C::aperture, 0, 0, 100,
                      "Depth of field: diameter of a thin lens in world units; points off the "
                      "focal plane blur into discs of aperture x |depth - focus| / depth (seen "
                      "on the focal plane); 0 is a pinhole, everything sharp. Takes its lens "
                      "samples from render.samples"),
        realParameter("camera", "focus_distance", &S::camera, &C::focusDistance, 0, 0, 1e4,
                      "Distance from the camera to the plane in focus, along the view axis; 0 "
                      "focuses on look_at"),
        realParameter("camera", "fov", &S::camera, &C::fovDegrees, 45, 0.01, 179,
                      "Horizontal field of view in degrees"),
    };
}

// [render]: the image's size and samples, and the ray marcher that finds the surface.
std::vector<Parameter> renderParameters() {
    using S = Scene;
    using R = RenderSettings;
    return {
        integerParameter("render", "width", &S::render, &R::width, 1280, 1, 16384,
                         "Image width in pixels"),
        integerParameter("render", "height", &S::render, &R::height, 720, 1, 16384,
                         "Image height in pixels"),
        integerParameter("render", "samples", &S::render, &R::samples, 4, 1, 1024,
                         "Stratified samples per pixel (anti-aliasing); 1 is one ray through "
                         "each pixel centre"),
        booleanParameter("render", "adaptive", &S::render, &R::adaptive, false,
                         "With several samples: one per pixel first, the others only where "
                         "that pixel and its neighbours disagree (edges, shadows, detail); "
                         "false takes every sample in every pixel"),
        choiceParameter(
            "render", "method", &S::render, &R::method, "sphere",
            {{"sphere", MarchMethod::SphereTracing}, {"fixed-step", MarchMethod::FixedStep}},
            "Ray marcher: sphere tracing steps by the distance estimate, fixed-step "
            "tests a point every render.step (Algorithm 2)"),
        realParameter("render", "step", &S::render, &R::step, 0.002, 1e-6, 1,
                      "Step length of the fixed-step marcher in world units; smaller finds "
                      "thinner parts, more slowly"),
        realParameter("render", "epsilon", &S::render, &R::epsilon, 0.25, 1e-4, 10,
                      "Sphere tracing stops where the distance estimate is below epsilon times "
                      "the pixel footprint"),
        realParameter("render", "relaxation", &S::render, &R::relaxation, 1.8, 1, 1.95,
                      "Sphere tracing's over-relaxation: steps of up to this many estimates, "
                      "checked against the plain step and taken back where they could skip "
                      "anything; 1 steps plainly"),
        integerParameter("render", "max_steps", &S::render, &R::maxSteps, 5000, 1, 10000000,
                         "Most marching steps along one ray, for either marcher"),
        integerParameter("render", "bit_depth", &S::render, &R::bitDepth, 8, 8, 16,
                         "Bits per channel of the PNG image", {8, 16}),
        choiceParameter("render", "engine", &S::render, &R::engine, "simd",
                        {{"simd", RenderEngine::Simd}, {"scalar", RenderEngine::Scalar}},
                        "simd marches many rays at once in SIMD lanes (sphere tracing of the "
                        "quaternions, bicomplex polynomials and octonion real forms; the rest "
                        "takes scalar); scalar is the double-precision reference, which draws "
                        "everything"),
        choiceParameter("render", "precision", &S::render, &R::precision, "single",
                        {{"single", Precision::Single}, {"double", Precision::Double}},
                        "Floating-point precision of the simd engine: single is fastest, double "
                        "(half as many lanes) holds deep zooms"),
        choiceParameter("render", "alpha", &S::render, &R::alpha, "coverage",
                        {{"coverage", AlphaMode::Coverage}, {"opaque", AlphaMode::Opaque}},
                        "PNG alpha: coverage (the fraction of samples that hit, background "
                        "transparent) or opaque (composited over the background gradient)"),
        textParameter("render", "certified", &S::render, &R::certified, "", 0, 4096,
                      "A cells file of `quaternia certify` for this scene's formula and c: the "
                      "certificate (--certify, the explorer's Certify) then classifies each "
                      "pixel against the set K itself instead of K_N; empty: K_N"),
    };
}

// [shading]: the key and fill lights, the surface's colours, the background, fog and glow, and
// the encoding of the image.
std::vector<Parameter> shadingParameters() {
    using S = Scene;
    using H = ShadingSettings;
    return {
        choiceParameter("shading", "light_kind", &S::shading, &H::lightKind, "directional",
                        {{"directional", LightKind::Directional},
                         {"point", LightKind::Point},
                         {"spot", LightKind::Spot}},
                        "The key light: directional (from light_direction, infinitely far), point "
                        "(at light_position, falling off with the inverse square of the distance) "
                        "or spot (a point light shining into a cone towards spot_target)"),
        vectorParameter("shading", "light_direction", &S::shading, &H::lightDirection,
                        {-0.5, 0.8, -0.6}, -1e3, 1e3,
                        "Direction towards a directional key light in world space; any length"),
        vectorParameter("shading", "light_position", &S::shading, &H::lightPosition,
                        {-3.0, 5.0, -6.0}, -1e3, 1e3,
                        "Position of a point or spot key light in world space"),
        vectorParameter("shading", "light_color", &S::shading, &H::lightColor, {1.0, 0.92, 0.8}, 0,
                        100, "Linear RGB colour of the key light"),
        realParameter("shading", "light_intensity", &S::shading, &H::lightIntensity, 1, 0, 1e6,
                      "Multiplies light_color; a point or spot light gives light_color x "
                      "intensity / distance^2 (at distance 8, 64 matches a directional light of "
                      "intensity 1)"),
        vectorParameter("shading", "spot_target", &S::shading, &H::spotTarget, {0.0, 0.0, 0.0},
                        -1e3, 1e3, "The point a spot key light aims at"),
        realParameter("shading", "spot_angle", &S::shading, &H::spotAngle, 25, 0.1, 90,
                      "Half-angle of a spot light's cone in degrees"),
        realParameter("shading", "spot_softness", &S::shading, &H::spotSoftness, 0.2, 0, 1,
                      "Fraction of spot_angle over which the spot's edge fades out; 0 is a hard "
                      "edge"),
        choiceParameter("shading", "shadows", &S::shading, &H::shadows, "soft",
                        {{"soft", Shadows::Soft}, {"hard", Shadows::Hard}, {"none", Shadows::None}},
                        "Shadows of the key light: soft (distance-estimate penumbrae), hard or "
                        "none"),
        realParameter("shading", "shadow_softness", &S::shading, &H::shadowSoftness, 12, 1, 1000,
                      "Penumbra sharpness k of soft shadows; larger is harder"),
        realParameter("shading", "light_radius", &S::shading, &H::lightRadius, 0, 0, 1e3,
                      "Radius of a point or spot key light in world units: soft shadows then "
                      "have its penumbra (k = its distance from the set's centre / radius); 0 "
                      "keeps shadow_softness"),
        realParameter("shading", "light_angular_radius", &S::shading, &H::lightAngularRadius, 0, 0,
                      45,
                      "Angular radius of a directional key light in degrees (the sun's is "
                      "0.27): soft shadows then have its penumbra (k = 1 / tan); 0 keeps "
                      "shadow_softness"),
        vectorParameter("shading", "fill_direction", &S::shading, &H::fillDirection,
                        {0.6, 0.2, -0.4}, -1e3, 1e3,
                        "Direction towards the fill light in world space; any length"),
        vectorParameter("shading", "fill_color", &S::shading, &H::fillColor, {0.12, 0.16, 0.25}, 0,
                        100, "Linear RGB colour and intensity of the fill light"),
        realParameter("shading", "ambient", &S::shading, &H::ambient, 0.08, 0, 1,
                      "Ambient light reaching every point, as a fraction of full light"),
        realParameter("shading", "ambient_occlusion", &S::shading, &H::ambientOcclusion, 0.8, 0, 1,
                      "Strength of ambient occlusion darkening creases; 0 turns it off"),
        realParameter("shading", "specular", &S::shading, &H::specular, 0.3, 0, 10,
                      "Strength of the specular highlights"),
        realParameter("shading", "shininess", &S::shading, &H::shininess, 40, 1, 10000,
                      "Specular exponent; larger gives smaller, sharper highlights"),
        choiceParameter("shading", "coloring", &S::shading, &H::coloring, "orbit-trap",
                        {{"orbit-trap", Coloring::OrbitTrap},
                         {"iteration", Coloring::Iteration},
                         {"solid", Coloring::Solid}},
                        "Surface colour: mixed by orbit trap or by escape iteration from "
                        "base_color and accent_color, or solid base_color"),
        vectorParameter("shading", "base_color", &S::shading, &H::baseColor, {0.85, 0.42, 0.1}, 0,
                        100, "Main linear RGB colour of the surface"),
        vectorParameter("shading", "accent_color", &S::shading, &H::accentColor, {0.04, 0.16, 0.45},
                        0, 100,
                        "Second linear RGB surface colour, mixed in by orbit-trap and "
                        "iteration colouring"),
        vectorParameter("shading", "background_top", &S::shading, &H::backgroundTop,
                        {0.02, 0.025, 0.04}, 0, 100,
                        "Linear RGB background at the top of the image"),
        vectorParameter("shading", "background_bottom", &S::shading, &H::backgroundBottom,
                        {0.002, 0.002, 0.004}, 0, 100,
                        "Linear RGB background at the bottom of the image"),
        realParameter("shading", "fog_density", &S::shading, &H::fogDensity, 0, 0, 1000,
                      "Uniform fog per unit of distance: light from distance t keeps exp(-density "
                      "t) of its colour and takes the rest from fog_color, and the background, "
                      "infinitely far, is fog_color; 0 is no fog"),
        vectorParameter("shading", "fog_color", &S::shading, &H::fogColor, {0.5, 0.55, 0.6}, 0, 100,
                        "Linear RGB colour of the fog"),
        realParameter("shading", "glow_intensity", &S::shading, &H::glowIntensity, 0, 0, 100,
                      "A glow about the set: a ray that passes at distance d from the surface "
                      "takes glow_color with opacity intensity x exp(-d / glow_radius) (at most "
                      "1); 0 is no glow"),
        realParameter("shading", "glow_radius", &S::shading, &H::glowRadius, 0.05, 1e-4, 1,
                      "How far the glow reaches from the surface, in world units"),
        vectorParameter("shading", "glow_color", &S::shading, &H::glowColor, {0.4, 0.6, 1.0}, 0,
                        100, "Linear RGB colour of the glow"),
        realParameter("shading", "gamma", &S::shading, &H::gamma, 2.2, 0.1, 10,
                      "Display gamma of the encoded image (2.2 is close to sRGB)"),
        realParameter("shading", "exposure", &S::shading, &H::exposure, 1, 0, 100,
                      "Multiplies linear radiance before gamma encoding; 1 leaves it as is"),
    };
}

}  // namespace quaternia::parameter_builders
