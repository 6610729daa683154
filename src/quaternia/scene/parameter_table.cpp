// The parameter table: every scene setting declared once, with its name, type, default, range
// and help. This one table drives scene files, --set, --help, validation and the explorer's
// controls (/api/parameters); parameters.cpp holds the machinery that reads it.
#include <algorithm>
#include <iterator>
#include <utility>

#include "quaternia/scene/parameter_builders.h"
#include "quaternia/scene/parameters.h"

namespace quaternia {
namespace {

using namespace parameter_builders;

// fractal.c: 4 components (1, i, j, k) for the 4-component algebras, 8 for biquaternions and
// octonions; the first 4 go to FractalSettings::c, the rest to cUpper, and cComponents records
// how many were given so that validateScene can check them against fractal.algebra.
Parameter constantParameter(std::string help) {
    Parameter p = makeParameter("fractal", "c", ParameterType::Components,
                                std::vector<double>{-0.2, 0.6, 0.2, 0.2}, -10, 10, std::move(help));
    p.lengths = {4, 8};
    p.apply = [](Scene& scene, const ParameterValue& value) {
        const auto& v = std::get<std::vector<double>>(value);
        FractalSettings& fractal = scene.fractal;
        for (std::size_t i = 0; i < 4; ++i) {
            fractal.c[int(i)] = v[i];
            fractal.cUpper[i] = v.size() == 8 ? v[4 + i] : 0.0;
        }
        fractal.cComponents = int(v.size());
    };
    p.read = [](const Scene& scene) -> ParameterValue {
        const FractalSettings& fractal = scene.fractal;
        std::vector<double> v(fractal.cComponents == 4 ? 4 : 8);
        for (std::size_t i = 0; i < v.size(); ++i)
            v[i] = i < 4 ? fractal.c[int(i)] : fractal.cUpper[i - 4];
        return v;
    };
    return p;
}

std::vector<std::pair<std::string, Algebra>> algebraChoices() {
    std::vector<std::pair<std::string, Algebra>> choices;
    for (Algebra algebra : allAlgebras())
        choices.emplace_back(std::string(algebraName(algebra)), algebra);
    return choices;
}

Parameter withMotion(Parameter p, Motion motion) {
    p.motion = motion;
    return p;
}

// The planes of rotation of H in slice.angles' order, for the animation's shortcuts.
std::vector<std::pair<std::string, RotationPlane>> rotationPlanes(bool withNone) {
    std::vector<std::pair<std::string, RotationPlane>> planes = {
        {"1i", RotationPlane::OneI}, {"1j", RotationPlane::OneJ}, {"1k", RotationPlane::OneK},
        {"ij", RotationPlane::IJ},   {"ik", RotationPlane::IK},   {"jk", RotationPlane::JK}};
    if (withNone) planes.insert(planes.begin(), {"none", RotationPlane::None});
    return planes;
}

// Every section but those of sceneryParameters().
std::vector<Parameter> coreParameters() {
    using S = Scene;
    using F = FractalSettings;
    using L = SliceSettings;
    using C = CameraSettings;
    using R = RenderSettings;
    using H = ShadingSettings;
    using P = PlaneSettings;
    using M = MeshSettings;
    using O = OrbitSettings;
    using Y = CyclesSettings;
    using A = AnimationSettings;
    return {
        // [fractal]
        textParameter("fractal", "formula", &S::fractal, &F::formula, "z^2 + c", 1, 1000,
                      "Quaternion polynomial in z iterated as z <- p(z) (eq. 2.10); c stands for "
                      "fractal.c, e.g. \"z^3 + c\" or \"i*z*j*z + c\""),
        choiceParameter("fractal", "algebra", &S::fractal, &F::algebra, "quaternion",
                        algebraChoices(),
                        "The algebra of z, c and the formula's constants (seed paper, section "
                        "2.3): quaternion, bicomplex (POV-Ray's hypercomplex), coquaternion, "
                        "biquaternion or octonion"),
        constantParameter("The constant c as its (1, i, j, k) components, 8 of them for the "
                          "biquaternion and octonion algebras; each c is another Julia set"),
        integerParameter("fractal", "max_iterations", &S::fractal, &F::maxIterations, 12, 1, 100000,
                         "Iterations before a point that has not escaped counts as inside; more "
                         "is finer detail and slower"),
        realParameter("fractal", "bailout", &S::fractal, &F::bailout, 0, 0, 1e6,
                      "A point escapes once |z| > bailout; 0 uses the polynomial's own escape "
                      "radius"),
        // [slice]
        vectorParameter("slice", "normal", &S::slice, &L::normal, {0, 0, 0, 1}, -1000, 1000,
                        "Normal s = (x, y, z, w) of the 4D hyperplane s . q = distance that is "
                        "drawn, as POV-Ray's slice; w must not be 0"),
        realParameter("slice", "distance", &S::slice, &L::distance, 0, -100, 100,
                      "Offset of the slice hyperplane along its normal; sweeping it morphs "
                      "through the 4D set"),
        withMotion(vectorParameter("slice", "left", &S::slice, &L::left, {1, 0, 0, 0}, -1000, 1000,
                                   "Quaternion l (1, i, j, k), made unit: a point p is drawn iff "
                                   "l * s(p) * r is in the set"),
                   Motion::Rotation),
        withMotion(
            vectorParameter("slice", "right", &S::slice, &L::right, {1, 0, 0, 0}, -1000, 1000,
                            "Quaternion r (1, i, j, k), made unit: a point p is drawn iff "
                            "l * s(p) * r is in the set"),
            Motion::Rotation),
        withMotion(vectorParameter("slice", "angles", &S::slice, &L::anglesDegrees,
                                   {0, 0, 0, 0, 0, 0}, -360, 360,
                                   "Extra 4D rotations of the slice in degrees, in the planes "
                                   "(1,i), (1,j), (1,k), (i,j), (i,k), (j,k)"),
                   Motion::Angle),
        componentsParameter("slice", "origin", &S::slice, &L::origin, {}, {0, 8}, -1000, 1000,
                            "Origin of the 3D slice in the 8-component algebras (biquaternion, "
                            "octonion): (x, y, z) stands for origin + x axes[0] + y axes[1] + "
                            "z axes[2]; empty: 0"),
        componentsParameter("slice", "axes", &S::slice, &L::axes, {}, {0, 24}, -1000, 1000,
                            "Three directions of the 8-component algebra spanning the slice, "
                            "orthonormalised in order; empty: e0, e1, e2 (the quaternion default "
                            "slice)",
                            8),
        // [camera]
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
        // [render]
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
                        "simd marches many rays at once in SIMD lanes (z^d + c with sphere "
                        "tracing; other formulas fall back); scalar is the double-precision "
                        "reference marcher"),
        choiceParameter("render", "precision", &S::render, &R::precision, "single",
                        {{"single", Precision::Single}, {"double", Precision::Double}},
                        "Floating-point precision of the simd engine: single is fastest, double "
                        "(half as many lanes) holds deep zooms"),
        choiceParameter("render", "alpha", &S::render, &R::alpha, "coverage",
                        {{"coverage", AlphaMode::Coverage}, {"opaque", AlphaMode::Opaque}},
                        "PNG alpha: coverage (the fraction of samples that hit, background "
                        "transparent) or opaque (composited over the background gradient)"),
        // [shading]
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
        // [plane]
        choiceParameter("plane", "kind", &S::plane, &P::kind, "julia",
                        {{"julia", PlaneKind::Julia},
                         {"julia-boundary", PlaneKind::JuliaBoundary},
                         {"mandelbrot", PlaneKind::Mandelbrot},
                         {"basins", PlaneKind::Basins},
                         {"slice", PlaneKind::Slice}},
                        "`quaternia plane` image: filled Julia set K_c (smooth escape colours), "
                        "its boundary J_c, the Mandelbrot set of z^d + c, basins of attraction, "
                        "or a slice plane.origin + x plane.u + y plane.v through the set (every "
                        "algebra)"),
        vectorParameter("plane", "center", &S::plane, &P::center, {0, 0}, -1e6, 1e6,
                        "The plane point (x, y) at the image centre; for julia, mandelbrot and "
                        "basins the complex number x + y i"),
        realParameter("plane", "width", &S::plane, &P::width, 4, 1e-12, 1e6,
                      "Width of the view in plane units (the height follows the image's aspect)"),
        withMotion(realParameter("plane", "rotation", &S::plane, &P::rotationDegrees, 0, -360, 360,
                                 "Counter-clockwise rotation of the view about its centre, in "
                                 "degrees"),
                   Motion::Angle),
        integerParameter("plane", "max_iterations", &S::plane, &P::maxIterations, 256, 1, 1000000,
                         "Iterations of every plane kind before a point counts as inside (the 3D "
                         "render's fractal.max_iterations is usually far fewer)"),
        vectorParameter("plane", "origin", &S::plane, &P::origin, {0, 0, 0, 0}, -1e6, 1e6,
                        "Slice kind: the point (1, i, j, k) at plane coordinates (0, 0); for the "
                        "8-component algebras a point (x, y, z, 0) of the 3D slice"),
        vectorParameter("plane", "u", &S::plane, &P::u, {1, 0, 0, 0}, -1e6, 1e6,
                        "Slice kind: the direction in H of the image's x axis; one plane unit "
                        "is its length"),
        vectorParameter("plane", "v", &S::plane, &P::v, {0, 1, 0, 0}, -1e6, 1e6,
                        "Slice kind: the direction in H of the image's y axis (up); must not be "
                        "parallel to plane.u"),
        realParameter("plane", "boundary_width", &S::plane, &P::boundaryWidth, 0.75, 0.01, 100,
                      "julia-boundary: J_c is drawn where the distance estimate is below this "
                      "many pixels"),
        // [mesh]
        integerParameter(
            "mesh", "resolution", &S::mesh, &M::resolution, 256, 1, 2048,
            "Grid cells of `quaternia mesh` along the longest side of the set's "
            "bounding box; time and memory grow with its square (1024: 1.5 GB, 2048: about 6 GB)"),
        realParameter("mesh", "iso", &S::mesh, &M::iso, 0, 0, 16,
                      "Moves the mesh's surface outward by this many cells, thickening thin "
                      "parts for 3D printing; 0 meshes the set itself"),
        realParameter("mesh", "min_component", &S::mesh, &M::minComponent, 0, 0, 1e6,
                      "Drops connected pieces of the mesh whose volume (world units cubed) is "
                      "below this; 0 keeps every piece"),
        // [orbit]
        vectorParameter("orbit", "z0", &S::orbit, &O::z0, {0, 0, 0, 0}, -1e6, 1e6,
                        "`quaternia orbit`: the starting point (1, i, j, k) whose orbit under "
                        "fractal.formula with fractal.c is followed"),
        integerParameter("orbit", "max_iterations", &S::orbit, &O::maxIterations, 1000, 1, 1000000,
                         "`quaternia orbit`: iterations before an orbit that neither escapes nor "
                         "settles counts as undecided (far more than fractal.max_iterations)"),
        // [cycles]
        // degree^period points are solved for, at most 1024 (kMaxPeriodicPoints): period 10
        // for a quadratic, less for higher degrees (checked by the command).
        integerParameter("cycles", "period", &S::cycles, &Y::period, 1, 1, 10,
                         "`quaternia cycles`: the period n whose periodic points are listed; "
                         "degree^n must be at most 1024"),
        // [animation]: keys are [[animation.keys]] tables (scene_file.h), not table entries
        realParameter("animation", "fps", &S::animation, &A::fps, 30, 0.01, 1000,
                      "Frames per second of `quaternia animate`; frame n is at (n - 1) / fps "
                      "seconds"),
        realParameter("animation", "duration", &S::animation, &A::duration, 0, 0, 86400,
                      "Length of the film in seconds; 0 takes it from animation.frames, or else "
                      "ends the film at the last key"),
        integerParameter("animation", "frames", &S::animation, &A::frames, 0, 0, 1000000,
                         "Number of frames; 0 means duration * fps"),
        choiceParameter("animation", "interpolation", &S::animation, &A::interpolation, "smooth",
                        interpolationChoices(),
                        "How values move from a key to the next, for keys that do not say: smooth "
                        "(through every key, no overshoot), linear, ease (stops at keys) or step"),
        choiceParameter(
            "animation", "turn_plane", &S::animation, &A::turnPlane, "none", rotationPlanes(true),
            "Turns the slice through 4D in this plane over the whole film (slice.angles' "
            "planes; 1k, ik or jk turn the hidden k axis into view)"),
        realParameter("animation", "turns", &S::animation, &A::turns, 1, -100, 100,
                      "Full turns of animation.turn_plane over the film; a quarter turn in 1k "
                      "shows what the slice hid, as the paper's g(qk) view does"),
        realParameter("animation", "orbit_turns", &S::animation, &A::orbitTurns, 0, -100, 100,
                      "Turns of the camera about camera.look_at, around camera.up, over the film"),
        choiceParameter("animation", "c_plane", &S::animation, &A::cPlane, "1i",
                        rotationPlanes(false),
                        "Plane of H in which c travels its circle (animation.c_radius)"),
        realParameter("animation", "c_radius", &S::animation, &A::cRadius, 0, 0, 10,
                      "c travels once around a circle of this radius about fractal.c over the "
                      "film; 0 keeps c still"),
    };
}

}  // namespace

std::vector<Parameter> buildParameterTable() {
    std::vector<Parameter> table = coreParameters();
    // The lights, the material and the ground come after [shading].
    const auto plane = std::find_if(table.begin(), table.end(),
                                    [](const Parameter& p) { return p.section == "plane"; });
    std::vector<Parameter> scenery = sceneryParameters();
    table.insert(plane, std::make_move_iterator(scenery.begin()),
                 std::make_move_iterator(scenery.end()));
    return table;
}

}  // namespace quaternia
