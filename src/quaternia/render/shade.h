// Surface shading of a hit: a key light with Blinn-Phong highlights and DE soft shadows
// (Quilez's penumbra estimate min k h / t along the shadow ray), a shadowless fill light,
// ambient light darkened by ambient occlusion from a few distance estimates along the normal,
// and an albedo coloured by the orbit (orbit trap or smooth escape count). Colours are linear;
// toDisplay() applies exposure and gamma.
#pragma once

#include <algorithm>
#include <array>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "quaternia/fractal/fractal.h"
#include "quaternia/image/image.h"
#include "quaternia/render/environment.h"
#include "quaternia/render/lanes/shading_lanes.h"
#include "quaternia/render/march.h"
#include "quaternia/scene/scene.h"

namespace quaternia {

struct ShadingStats {
    int64_t estimates = 0;   // extra distance estimates (shadow and occlusion)
    int64_t iterations = 0;  // their polynomial evaluations
};

// What lighting a hit needs beyond its position: the scalar path computes these ray by ray, the
// SIMD path (lane_tile_renderer.h) in batches; both light them with Shader::light.
struct SurfaceSample {
    Vector3d normal;      // unit, facing the viewer
    Vector3d toLight;     // unit, towards the key light (Shader::keyLight)
    double keyScale = 1;  // the key light's factor there (Shader::keyLight)
    Color albedo;
    double visibility = 1;  // of the key light, after the penumbra's smoothstep
    double occlusion = 1;   // ambient light reaching the point, ambient occlusion applied
};

// The key light as a point of the surface sees it (Shader::keyLight): the unit direction
// towards it, the factor on its colour (intensity; over distance squared for point and spot
// lights, times the spot's cone), and how far it is (infinite for a directional light).
struct KeyLight {
    Vector3d toLight;
    double scale = 1;
    double distance = 0;
};

// A light of the scene as the shader uses it: the key light of [shading] (Shader::keySource) or
// one of [light1] .. [light7] (Shader::extraLights).
struct LightSource {
    LightKind kind = LightKind::Directional;
    Vector3d direction;  // unit, towards a directional light
    Point3d position;    // of a point or spot light
    Color color;
    double intensity = 1;
    Vector3d spotAxis;                              // unit, from a spot light to its target
    double spotCosOuter = -1, spotCosInner = -0.5;  // the cone's edge: dark beyond outer
    Shadows shadows = Shadows::Soft;
    double softness = 12;  // penumbra sharpness k of soft shadows (Shader::shadow)
};
// The light of [lightN].
LightSource lightSourceOf(const LightSettings& settings);

class Shader {
  public:
    // extraLights: [light1] .. [light7] (only the enabled ones shine). environment: the world
    // around the scene (environmentOf), or none; its sun shines as one more light.
    Shader(const ShadingSettings& settings, const Fractal& fractal,
           std::span<const LightSettings> extraLights = {},
           std::shared_ptr<const Environment> environment = nullptr);

    // Linear colour of the surface at `hit`, seen along `ray`. `footprint` is the pixel
    // footprint at the hit, the scale of the offsets that leave the surface.
    // `surface`, where given, receives the normal, albedo, visibility and occlusion it used.
    // occlusion false: the ambient light unoccluded (reflected and refracted rays'
    // hits, path_waves.h).
    Color shade(const Hit& hit, const Ray& ray, double footprint, ShadingStats& stats,
                SurfaceSample* surface = nullptr, bool occlusion = true) const;
    // What a ray that leaves the scene sees: the environment (blurred over `spread` radians,
    // a glossy reflection's), or else the vertical gradient; the fog's colour where there is
    // fog (backgroundTop() and backgroundBottom() are then the fog's).
    Color background(const Ray& ray, double spread = 0) const;
    // Whether rays that leave the scene see the environment (there is one, and no fog); then
    // Environment::radianceBatch reads many at once.
    bool environmentSeen() const { return environment_ && !(settings_.fogDensity > 0); }
    // What a camera ray that misses sees, where backgroundRow gives it: the gradient, or the
    // environment where it is shown (environment.background).
    bool environmentBackground() const;
    // Whether every camera ray that misses sees the same colour (backgroundBottom()).
    bool uniformBackground() const {
        return !environmentBackground() && settings_.backgroundTop == settings_.backgroundBottom;
    }
    // The environment's diffuse light on surfaces (environment.lighting), and the light for
    // its shadow rays (hard, directional: Shader::shadowOf with the ray's direction).
    const Environment* environment() const { return environment_.get(); }
    bool environmentLighting() const { return environment_ && environment_->lighting(); }
    const LightSource& environmentShadows() const { return environmentShadows_; }
    // The environment's light at a surface point (unit normal n, facing the light), its shadow
    // rays marched from `origin` (a little off the surface) in double: what the lanes compute
    // in batches (lane_environment.h), the same directions and formula.
    Color environmentLight(const Point3d& point, const Point3d& origin, const Vector3d& n,
                           const Color& albedo, ShadingStats& stats) const;
    const Color& backgroundTop() const { return settings_.backgroundTop; }
    const Color& backgroundBottom() const { return settings_.backgroundBottom; }
    // Light of colour c from distance t seen through the fog (Beer-Lambert: exp(-density t) of
    // it, the rest the fog's colour); c itself without fog.
    Color throughFog(const Color& c, double t) const {
        if (!(settings_.fogDensity > 0)) return c;
        const double kept = std::exp(-settings_.fogDensity * t);
        return c * kept + settings_.fogColor * (1 - kept);
    }
    // What part of light from distance t passes the fog, and the fog's colour.
    double fogKept(double t) const {
        return settings_.fogDensity > 0 ? std::exp(-settings_.fogDensity * t) : 1.0;
    }
    const Color& fogColor() const { return settings_.fogColor; }
    double glowIntensity() const { return settings_.glowIntensity; }
    double glowRadius() const { return settings_.glowRadius; }
    // The glow's opacity in front of a camera ray whose least distance estimate was `closest`.
    double glowOpacity(double closest) const {
        return std::min(1.0, settings_.glowIntensity * std::exp(-closest / settings_.glowRadius));
    }
    const Color& glowColor() const { return settings_.glowColor; }
    // background() for the pixel centres px = x0 .. x0 + count - 1 of one camera row
    // (Camera::rowDirections), in float, with the given alpha: a loop the compiler vectorises.
    void backgroundRow(const Vector3d& first, const Vector3d& step, int x0, int count, float alpha,
                       Rgba* out) const;
    // Visibility of the key light from p in [0, 1] (1 = lit), the light as p sees it.
    double shadow(const Point3d& p, const KeyLight& key, ShadingStats& stats) const;
    // How far a shadow ray from p towards the key light goes: to the light, or to the far side
    // of the set's bounding sphere if that is nearer (nothing when it misses the sphere).
    std::optional<RayInterval> shadowInterval(const Ray& ray, const KeyLight& key) const;
    // shadow() for sets whose distance is a Lipschitz bound (Fractal::distanceKind): hard.
    double lipschitzShadow(const Ray& ray, const RayInterval& interval, ShadingStats& stats) const;
    // 1 = open, 0 = fully occluded.
    double ambientOcclusion(const Point3d& p, const Vector3d& normal, ShadingStats& stats) const;
    Color albedo(const DistanceEstimate& estimate) const;
    // Whether albedo() reads the estimate's smoothIteration (two logarithms to compute).
    bool albedoUsesSmoothIteration() const { return settings_.coloring == Coloring::Iteration; }
    // Whether albedo() reads the estimate at all (a solid colour does not).
    bool albedoUsesOrbit() const { return settings_.coloring != Coloring::Solid; }

    // The pieces both paths share. The key light at point x.
    KeyLight keyLight(const Point3d& x) const { return illumination(lights_.front(), x); }
    // Any light at point x: its direction, its factor (intensity, inverse square, spot cone).
    static KeyLight illumination(const LightSource& light, const Point3d& x);
    const LightSource& keySource() const { return lights_.front(); }
    // The enabled lights of [light1] .. [light7], in order.
    std::span<const LightSource> extraLights() const {
        return std::span<const LightSource>(lights_).subspan(1);
    }
    // Visibility of `light` from p (1 lit), by its shadows and softness; shadow() for the key.
    double shadowOf(const Point3d& p, const KeyLight& at, const LightSource& light,
                    ShadingStats& stats) const;
    std::optional<RayInterval> shadowIntervalOf(const Ray& ray, const KeyLight& at,
                                                const LightSource& light) const;
    // What a light other than the key adds to a surface of this normal and albedo seen along
    // `view`: Lambert's diffuse and the key light's Blinn-Phong highlight, times its visibility.
    Color lightOther(const LightSource& light, const KeyLight& at, const Vector3d& normal,
                     const Color& albedo, const Vector3d& view, double visibility) const;
    // The visibility a shadow ray's march leaves as light, for `light`'s kind of shadows.
    double visibilityOf(const LightSource& light, double marched) const;
    // Whether the key light's shadows are rays towards a direction (parallel rays).
    bool keyLightIsDirectional() const { return settings_.lightKind == LightKind::Directional; }
    // The key light's diffuse term (0 where it does not reach the front of the surface, and no
    // shadow ray is needed).
    static double keyDiffuse(const Vector3d& normal, const KeyLight& key) {
        return key.scale > 0 ? std::max(0.0, dot(normal, key.toLight)) : 0.0;
    }
    // Where the shadow ray starts: a few footprints off the surface so that it does not hit the
    // surface it leaves.
    Point3d shadowOrigin(const Point3d& surface, const Vector3d& normal, double footprint) const {
        return surface + normal * (2 * footprint + 1e-6 * boundingRadius_);
    }
    // The marching settings of shadow rays (Shadows::None: no shadow rays at all).
    Shadows shadows() const { return settings_.shadows; }
    double shadowMinimumStep() const;
    double shadowSoftness() const { return keySource().softness; }
    // A directional key light's direction (keyLightIsDirectional()).
    const Vector3d& lightDirection() const { return lightDirection_; }
    // Shadow rays: at most kShadowSteps estimates, over-relaxed steps (shadow()).
    static constexpr int kShadowSteps = 256;
    static constexpr double kShadowRelaxation = 1.6;
    static constexpr double kShadowMaxRelaxation = 4;
    // The factor of the next shadow step, from the last step and the radii (estimates, at least
    // the minimum step) at both its ends. As sphereTrace's (march.h), kShadowRelaxation / (1 +
    // slope), but the slope may be negative: a shadow ray leaves the surface, its estimate grows
    // with t, and consecutive balls still touch after steps of many estimates (up to 2 / (1 -
    // growth)); capped at kShadowMaxRelaxation.
    static double shadowRelaxation(double radius, double newRadius, double step) {
        if (!(step > 0)) return kShadowRelaxation;
        const double slope = std::max(-0.8, (radius - newRadius) / step);
        return std::clamp(kShadowRelaxation / (1 + slope), 1.0, kShadowMaxRelaxation);
    }
    // The visibility a shadow ray's march leaves (0 blocked; the running penumbra or 1) as light.
    double visibilityFromMarch(double marched) const;
    // Ambient occlusion: kOcclusionSamples estimates at occlusionHeight(1..n) along the normal.
    static constexpr int kOcclusionSamples = 5;
    bool occlusionEnabled() const { return settings_.ambientOcclusion > 0; }
    double occlusionHeight(int k) const { return occlusionStep_ * k; }
    // Openness (1 open, 0 occluded) from those estimates (distances[k - 1] at height k), and the
    // ambient light it lets through at the configured strength.
    double occlusionFromEstimates(const double* distances) const;
    double ambientFromOpenness(double open) const;
    // The lit colour of a surface sample seen along `ray`.
    Color light(const SurfaceSample& sample, const Ray& ray) const;
    // light()'s constants for its SIMD form (shading_lanes.h, lightSurfaces).
    LightConstants lightConstants() const;
    // Exposure, clamp to [0, 1] and gamma: the values written to an 8- or 16-bit image.
    Color toDisplay(const Color& linear) const;
    // The same for the colours of many pixels in place, alpha kept (SIMD, shading_lanes.h;
    // equal to float rounding).
    void toDisplay(Rgba* pixels, size_t count) const;

  private:
    ShadingSettings settings_;
    const Fractal& fractal_;
    std::shared_ptr<const Environment> environment_;
    LightSource environmentShadows_;
    // fractal_.boundingRadius(), which per shaded point was a cost of its own (a virtual call).
    double boundingRadius_;
    Vector3d lightDirection_, fillDirection_;
    // The key light, then the enabled extra lights.
    std::vector<LightSource> lights_;
    double occlusionStep_;
    // occlusionFromEstimates' factors: 2 / height and the normalised weight of each sample.
    std::array<double, kOcclusionSamples> occlusionScale_, occlusionWeight_;
    // Below this cosine the highlight cos^shininess is under 1e-7, far below one step of a
    // 16-bit channel: light() skips the power there.
    double highlightCutoff_;
};

}  // namespace quaternia
