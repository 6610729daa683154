// A scene: everything a render, a mesh or the explorer needs, as plain values that
// travel by copy, so a server can hold many at once. The defaults, ranges and help of every
// field are declared once, in the parameter table (parameters.cpp); use defaultScene() rather
// than a default-constructed Scene, whose fields are merely zero.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "quaternia/algebra/hypercomplex.h"
#include "quaternia/algebra/quaternion.h"
#include "quaternia/algebra/vecmath.h"
#include "quaternia/fractal/fractal_settings.h"
#include "quaternia/scene/interpolation.h"

namespace quaternia {

using Color = Vector3d;  // linear RGB

// The value of one parameter of the table (parameters.h): reals are double, integers int64_t,
// choices and text std::string, vectors std::vector<double>.
using ParameterValue = std::variant<double, int64_t, bool, std::string, std::vector<double>>;

struct CameraSettings {
    Point3d position, lookAt;
    Vector3d up;               // POV-Ray's sky vector
    double fovDegrees = 0;     // horizontal field of view
    double aperture = 0;       // thin lens diameter, world units; 0: a pinhole
    double focusDistance = 0;  // to the plane in focus, along the view axis; 0: to look_at
};

enum class MarchMethod { SphereTracing, FixedStep };
// Coverage: alpha is the fraction of a pixel's samples that hit, colour that of the hits.
// Opaque: the image is composited over the background gradient, alpha 1.
enum class AlphaMode { Coverage, Opaque };

// Simd: the lanes (render/lanes/march_lanes.h) for s z^d + c with sphere tracing, in float or
// double lanes; everything else, and Scalar, runs the scalar double reference (march.h).
enum class RenderEngine { Simd, Scalar };
enum class Precision { Single, Double };

struct RenderSettings {
    int width = 0, height = 0;
    int samples = 0;  // per pixel, stratified
    // With samples > 1: every pixel's first sample, then the rest only where the first samples
    // of the pixel and its neighbours disagree (render/adaptive_sampling.h); false: all of them.
    // Off by default until it meets issue 17's bounds on every reference scene
    // (docs/benchmarks.md, Adaptive anti-aliasing).
    bool adaptive = false;
    MarchMethod method = MarchMethod::SphereTracing;
    double step = 0;        // fixed-step delta (Algorithm 2), world units
    double epsilon = 0;     // sphere tracing stops at epsilon * pixel footprint at distance t
    int maxSteps = 0;       // per ray, for either marcher
    double relaxation = 0;  // sphere tracing's over-relaxation (kMarchRelaxation); 1 = plain
    int bitDepth = 0;       // 8 or 16 bits per PNG channel
    AlphaMode alpha = AlphaMode::Coverage;
    RenderEngine engine = RenderEngine::Simd;
    Precision precision = Precision::Single;
    // A `quaternia certify` cells file (cellmap/certified_set.h); empty: certificates prove K_N.
    std::string certified;
};

enum class Shadows { None, Hard, Soft };
// The key light: a direction (infinitely far), a point, or a point shining into a cone.
enum class LightKind { Directional, Point, Spot };
enum class Coloring { OrbitTrap, Iteration, Solid };

struct ShadingSettings {
    LightKind lightKind = LightKind::Directional;
    Vector3d lightDirection;  // towards a directional key light, world space
    Vector3d lightPosition;   // of a point or spot key light, world space
    Color lightColor;
    double lightIntensity = 0;  // times lightColor; point and spot: over distance squared
    Vector3d spotTarget;        // where a spot light points
    double spotAngle = 0;       // half-angle of the spot's cone, degrees
    double spotSoftness = 0;    // fraction of spotAngle over which its edge fades
    Shadows shadows = Shadows::Soft;
    double shadowSoftness = 0;  // penumbra sharpness k of DE soft shadows (bigger = harder)
    // The key light's size, where given (> 0), sets k instead: as LightSettings'.
    double lightRadius = 0;
    double lightAngularRadius = 0;
    Vector3d fillDirection;
    Color fillColor;
    double ambient = 0;
    double ambientOcclusion = 0;  // strength in [0, 1]
    double specular = 0;
    double shininess = 0;
    Coloring coloring = Coloring::OrbitTrap;
    Color baseColor, accentColor;
    Color backgroundTop, backgroundBottom;
    Color fogColor;
    double fogDensity = 0;  // per unit of distance; 0: no fog
    // A glow about the set: a camera ray that passes at distance d takes glowColor with opacity
    // min(1, glowIntensity exp(-d / glowRadius)), d the least estimate along it; 0: none.
    Color glowColor;
    double glowIntensity = 0;
    double glowRadius = 0;
    double gamma = 0;
    double exposure = 0;
};

// [light1] .. [light7]: lights besides the key light of [shading], each its own kind, colour,
// intensity and shadows. A light's radius (point and spot, world units) or angular radius
// (directional, degrees) makes its shadows soft: the penumbra of a light of that size.
struct LightSettings {
    bool enabled = false;
    LightKind kind = LightKind::Directional;
    Vector3d direction;  // towards a directional light
    Vector3d position;   // of a point or spot light
    Color color;
    double intensity = 0;  // times color; point and spot: over distance squared
    Vector3d spotTarget;
    double spotAngle = 0;     // half-angle of the spot's cone, degrees
    double spotSoftness = 0;  // fraction of spotAngle over which its edge fades
    Shadows shadows = Shadows::Soft;
    double radius = 0;         // point and spot: the light's radius, world units
    double angularRadius = 0;  // directional: the light's angular radius, degrees
};
// Lights of the scene: the key light and at most this many more.
inline constexpr int kExtraLights = 7;

// [material]: the set's surface beyond its colour. Reflectivity is the reflectance at normal
// incidence (Schlick's Fresnel raises it towards 1 at grazing angles); transparency the part of
// the light that is not reflected which enters the set as through glass (index of refraction
// ior, exact dielectric Fresnel, Snell's law, total internal reflection, Beer-Lambert absorption
// inside). Rays split at every surface up to maxDepth bounces.
struct MaterialSettings {
    double reflectivity = 0;  // in [0, 1]
    double roughness = 0;     // glossy reflection: spread of the reflected rays
    double transparency = 0;  // in [0, 1]
    double ior = 1;           // index of refraction, at least 1
    Color absorption;         // per unit of distance inside, per channel (Beer-Lambert)
    int maxDepth = 0;         // bounces (reflections, refractions) a path may take
    int insideSteps = 0;      // fixed steps across the bounding sphere's diameter inside the set
};

// [ground]: an optional horizontal plane y = height under the set.
struct GroundSettings {
    bool enabled = false;
    double height = 0;
    Color color;
    double reflectivity = 0;     // at normal incidence (Schlick's Fresnel)
    bool shadowCatcher = false;  // drawn only where shadowed, as alpha over the background
};

// [environment]: the world around the scene, as light (issue 39). A latitude-longitude HDR
// map (OpenEXR or Radiance .hdr, 2:1) or, without one, a built-in: a sky (a gradient from the
// ground's colour through the horizon to the sky's, and a sun of an angular size that also
// shines as a directional light with soft shadows) or a studio (soft boxes over a dark floor).
// Every ray that leaves the scene sees it (reflections, refractions, the background where
// `background` is on); `lighting` lights the set and the ground with it, occluded by the set
// along `samples` shadow rays per hit.
enum class EnvironmentBuiltin { Sky, Studio };
// environment.samples' largest value: the shadow rays of one point fit on the stack.
inline constexpr int kMaxEnvironmentSamples = 64;

struct EnvironmentSettings {
    bool enabled = false;
    std::string map;  // a file; empty: the built-in
    EnvironmentBuiltin builtin = EnvironmentBuiltin::Sky;
    double intensity = 1;     // times the map's (or the built-in's) radiance
    double rotation = 0;      // degrees about camera.up's axis
    bool background = true;   // camera rays that miss see it (else the gradient)
    bool lighting = true;     // diffuse light from it on the set and the ground
    int samples = 0;          // shadow rays per hit (0: unoccluded)
    Vector3d sunDirection;    // towards the built-in sky's sun
    double sunIntensity = 0;  // the sun's irradiance (0: no sun)
    double sunSize = 0;       // its angular radius, degrees
    Color sunColor, skyColor, horizonColor, groundColor;
    bool operator==(const EnvironmentSettings&) const = default;
};

// `quaternia plane`: 2D images (plane_render.h). The filled Julia set K_c with smooth escape
// colouring, the Julia set J_c drawn by its distance estimate, the Mandelbrot set of z^d + c,
// basins of attraction, or a plane through H (origin + x u + y v). Image size, anti-aliasing
// and bit depth come from [render], the polynomial, c and bailout from [fractal].
enum class PlaneKind { Julia, JuliaBoundary, Mandelbrot, Basins, Slice };

struct PlaneSettings {
    PlaneKind kind = PlaneKind::Julia;
    std::array<double, 2> center{};  // the plane point at the image centre
    double width = 0;                // plane units across the image
    double rotationDegrees = 0;      // counter-clockwise turn of the view
    int maxIterations = 0;           // for every plane kind; fractal.max_iterations is the 3D one
    Quaternion origin, u, v;         // slice kind: the plane origin + x u + y v of H
    double boundaryWidth = 0;        // julia-boundary: J_c is lit where DE < this many pixels
};

// `quaternia mesh` (mesher.h): marching tetrahedra of the set on a sparse grid.
struct MeshSettings {
    int resolution = 0;       // grid cells along the longest side of the set's bounding box
    double iso = 0;           // surface offset outward, in cells (thickens thin parts for printing)
    double minComponent = 0;  // connected components of smaller |volume| are dropped (world^3)
};

// `quaternia orbit` and `quaternia cycles` (the dynamics of [fractal]'s map with its c): where
// an orbit starts and how long it is followed, and the period whose cycles are listed.
struct OrbitSettings {
    Quaternion z0;          // (1, i, j, k)
    int maxIterations = 0;  // far more than a render's: slow orbits settle late
};

struct CyclesSettings {
    int period = 0;
};

// [animation] (animation.h): a film of the scene. Keys come from the scene file's
// [[animation.keys]] tables (or --set animation.keys=[{...}, ...]); the rest are table parameters.
struct AnimationKey {
    double time = 0;  // seconds from the film's start
    // Of the segments from this key; unset: animation.interpolation.
    std::optional<Interpolation> interpolation;
    bool shortest = false;  // angles move from this key to their next by at most half a turn
    // "section.key" -> value, checked against the table and in canonical form.
    std::vector<std::pair<std::string, ParameterValue>> values;
};

// A plane of rotation of H, in slice.angles' order; None for no motion.
enum class RotationPlane { None, OneI, OneJ, OneK, IJ, IK, JK };

struct AnimationSettings {
    double fps = 0;
    double duration = 0;  // seconds; 0: from `frames`, or else up to the last key
    int frames = 0;       // 0: duration * fps
    Interpolation interpolation = Interpolation::Smooth;  // for keys that do not name one
    RotationPlane turnPlane = RotationPlane::None;        // the hidden dimension's turn
    double turns = 0;
    double orbitTurns = 0;  // camera turns about camera.look_at
    RotationPlane cPlane = RotationPlane::OneI;
    double cRadius = 0;  // c travels a circle of this radius about fractal.c
    std::vector<AnimationKey> keys;
};

struct Scene {
    FractalSettings fractal;
    SliceSettings slice;
    CameraSettings camera;
    RenderSettings render;
    ShadingSettings shading;
    std::array<LightSettings, kExtraLights> lights;
    MaterialSettings material;
    GroundSettings ground;
    EnvironmentSettings environment;
    PlaneSettings plane;
    MeshSettings mesh;
    OrbitSettings orbit;
    CyclesSettings cycles;
    AnimationSettings animation;
};

}  // namespace quaternia
