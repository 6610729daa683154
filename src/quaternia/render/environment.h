// The world around the scene ([environment], scene.h): a latitude-longitude radiance map (a file
// or a built-in sky or studio, environment_builtin.cpp) that rays leaving the scene see, and its
// diffuse light on surfaces, occluded by the set (environment_light.cpp). One immutable object
// per scene, shared by both engines through the Shader.
//
// Directions map to the image as is usual for light probes (Debevec, "Rendering synthetic
// objects into real scenes", SIGGRAPH 1998; the format Blender, Mitsuba and Mandelbulber2 read):
// the top row looks along camera.up, the bottom row away from it, the centre column along the
// world's -z turned `rotation` degrees about camera.up (counter-clockwise seen from above), u
// growing to the east.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "quaternia/image/hdr_image.h"
#include "quaternia/image/image.h"
#include "quaternia/scene/scene.h"
#include "quaternia/util/memory_budget.h"

namespace quaternia {

// A shadow ray towards the environment from a surface point: its unit direction and its weight
// in the occlusion's ratio estimate (EnvironmentLight).
struct EnvironmentDirection {
    Vector3d direction;
    double weight = 0;
};

class Environment {
  public:
    // From a map (HdrImage, linear RGB, its sides 2:1) or, for `map` empty, the settings'
    // built-in. `up` is camera.up (any length). Throws UserError naming environment.map for a
    // map that is not 2:1.
    Environment(const EnvironmentSettings& settings, const Vector3d& up, HdrImage map = {});

    // The radiance seen along unit direction `d`, blurred over about `spread` radians (the
    // pre-filtered levels of the map; 0 the map itself, bilinear), the sun's disc included.
    Color radiance(const Vector3d& d, double spread = 0) const;
    // radiance() without blur for the pixel centres of a camera row (Camera::rowDirections:
    // first + step * (x0 + i), i < count, any length), into `out` with the given alpha: the
    // angles by a polynomial arctangent in float (error below 1e-5 radians, far under a texel)
    // in a loop the compiler vectorises, then the bilinear reads. What a frame's background
    // costs is then small beside its marching.
    void radianceRow(const Vector3d& first, const Vector3d& step, int x0, int count, float alpha,
                     Rgba* out) const;
    // radiance() of many rays at once: out[i] for unit directions[i] and spreads[i], the
    // unblurred ones as radianceRow reads its pixels (vectorised), the blurred by radiance().
    void radianceBatch(std::span<const Vector3d> directions, std::span<const double> spreads,
                       std::span<Color> out) const;
    // Whether camera rays that miss see it (else the background gradient), and whether it
    // lights surfaces.
    bool background() const { return settings_.background; }
    bool lighting() const { return settings_.lighting; }
    // The built-in sky's sun as a directional light (soft shadows of its angular size), where
    // it shines: Shader lights surfaces with it as with [lightN].
    const std::optional<LightSettings>& sun() const { return sun_; }

    // ---- Diffuse light (environment_light.cpp) ----
    // The irradiance on a surface of unit normal n, unoccluded: the map convolved with the
    // cosine (a low-resolution irradiance map, exact for a constant map), divided by pi, i.e.
    // the radiance a white Lambertian surface sends back.
    Color diffuse(const Vector3d& n) const;
    // diffuse() of many normals (vectorised as radianceBatch; equal within float rounding).
    void diffuseBatch(std::span<const Vector3d> normals, std::span<Color> out) const;
    // How many shadow rays each surface point takes (environment.samples; 0: none, lit
    // unoccluded).
    int samples() const { return settings_.samples; }
    // The shadow rays of a point of unit normal n: samples() directions, half drawn from the
    // cosine about n and half from the map's light (a piecewise-constant distribution over a
    // low-resolution level), each weighted by the light it carries over the pdf of that mix
    // (the balance heuristic, Veach and Guibas, SIGGRAPH 1995). `seed` makes them
    // deterministic: a hash of where the point is (EnvironmentLight::seedOf).
    void shadowDirections(uint32_t seed, const Vector3d& n,
                          std::span<EnvironmentDirection> out) const;
    // The light of the point from the visibility of each of those rays (1 open, 0 blocked):
    // diffuse(n) times the ratio sum(weight visibility) / sum(weight), times the albedo. An
    // unoccluded point gets diffuse(n) exactly; the noise is in the occlusion alone. The ratio
    // is consistent, its bias falling as 1 / samples (an unbiased difference estimate, clamped
    // to [0, 1], was measured far worse in deep occlusion under a bright patch: the clamp);
    // with one ray, the cosine's, a point weighs its occlusion by the cosine alone.
    Color occludedDiffuse(const Vector3d& n, const Color& albedo,
                          std::span<const EnvironmentDirection> directions,
                          std::span<const double> visibility) const {
        return albedo * diffuse(n) * openFraction(directions, visibility);
    }
    // That ratio alone (1 without rays).
    static double openFraction(std::span<const EnvironmentDirection> directions,
                               std::span<const double> visibility);
    // A deterministic seed from a point's coordinates (the same hit, the same rays).
    static uint32_t seedOf(const Point3d& p);

    // The map's level 0 (for tests): its width and height.
    int width() const { return levels_.front().width; }
    int height() const { return levels_.front().height; }

  private:
    // A level of the pyramid: linear RGB floats, wrapping in u, clamped in v.
    struct Level {
        int width = 0, height = 0;
        std::vector<float> rgb;
        Color texel(int x, int y) const;
        Color bilinear(double u, double v) const;
    };
    // A level at n <= kLookUpChunk directions given by their components along east_,
    // centre_ and up_ (any length; arrays of kLookUpChunk) and, where `sun` is given, their
    // cosine with the sun times their length, into rgb (3 floats each), the sun's disc added
    // (environment_lookup.cpp).
    static constexpr int kLookUpChunk = 64;
    void lookUp(const Level& level, int n, const float* e, const float* c, const float* h,
                const float* sun, float* rgb) const;
    // lookUp of any number of unit directions, chunk by chunk (withSun: the disc added).
    void lookUpDirections(const Level& level, bool withSun, std::span<const Vector3d> directions,
                          std::span<Color> out) const;
    // The map's (u, v) in [0, 1]^2 of a unit world direction, and back.
    void toMap(const Vector3d& d, double& u, double& v) const;
    Vector3d fromMap(double u, double v) const;
    void buildPyramid(HdrImage image);
    void buildIrradiance();    // irradiance_ from a level of about 64 x 32
    void buildDistribution();  // the sampling distribution from a level of about 64 x 32
    double mapPdf(const Vector3d& d) const;  // per steradian

    EnvironmentSettings settings_;
    Vector3d up_, east_, centre_;  // the map's frame in world space (rotation applied)
    std::vector<Level> levels_;
    Level irradiance_;  // diffuse(n) over pi, a low-resolution lat-long map
    // The light distribution: per texel of a low level, its share of the map's power.
    int distributionWidth_ = 0, distributionHeight_ = 0;
    std::vector<double> rowCdf_, texelCdf_, texelPdf_;  // texelPdf_ per steradian
    double power_ = 0;  // sum of luminance times solid angle over the texels
    std::optional<LightSettings> sun_;
    Vector3d sunDirection_;
    double sunCosine_ = 1;  // of its angular radius
    Color sunRadiance_;
};

// The environment of a scene, or none where [environment] is off. The map is read (checked:
// readable, HDR, 2:1, within `budget`); the last environment made is kept while scenes ask for
// the same one (films, the explorer, repeated renders) and its file is unchanged. Throws
// UserError naming environment.map.
std::shared_ptr<const Environment> environmentOf(const Scene& scene,
                                                 const MemoryBudget& budget = {});

// The built-in radiance of the settings along a direction of the map's frame (y up, -z at
// the map's centre): the sky or the studio (environment_builtin.cpp). Without the sun.
Color builtinRadiance(const EnvironmentSettings& settings, const Vector3d& d);
// The built-in rasterised as a map of the given width (height width / 2), as shipped in
// data/environments (tests read the file back).
HdrImage builtinMap(const EnvironmentSettings& settings, int width);

}  // namespace quaternia
