// Surface shading of a hit: a key light with Blinn-Phong highlights and DE soft shadows
// (Quilez's penumbra estimate min k h / t along the shadow ray), a shadowless fill light,
// ambient light darkened by ambient occlusion from a few distance estimates along the normal,
// and an albedo coloured by the orbit (orbit trap or smooth escape count). Colours are linear;
// toDisplay() applies exposure and gamma.
#pragma once

#include "fractal.h"
#include "march.h"
#include "scene.h"

namespace quaternia {

struct ShadingStats {
    int64_t estimates = 0;   // extra distance estimates (shadow and occlusion)
    int64_t iterations = 0;  // their polynomial evaluations
};

class Shader {
  public:
    Shader(const ShadingSettings& settings, const Fractal& fractal);

    // Linear colour of the surface at `hit`, seen along `ray`. `footprint` is the pixel
    // footprint at the hit, the scale of the offsets that leave the surface.
    Color shade(const Hit& hit, const Ray& ray, double footprint, ShadingStats& stats) const;
    // The background seen along a ray that misses: a vertical gradient.
    Color background(const Ray& ray) const;
    // Visibility of the key light from p in [0, 1] (1 = lit).
    double shadow(const Point3d& p, ShadingStats& stats) const;
    // 1 = open, 0 = fully occluded.
    double ambientOcclusion(const Point3d& p, const Vector3d& normal, ShadingStats& stats) const;
    Color albedo(const DistanceEstimate& estimate) const;
    // Exposure, clamp to [0, 1] and gamma: the values written to an 8- or 16-bit image.
    Color toDisplay(const Color& linear) const;

  private:
    ShadingSettings settings_;
    const Fractal& fractal_;
    Vector3d lightDirection_, fillDirection_;
    double occlusionStep_;
};

}  // namespace quaternia
