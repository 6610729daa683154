// One job of the SIMD path (lane_tile_renderer.h): the ground plane's own light at the points
// where rays meet it, as the set's hits are lit (shadow rays in lanes, lightSurfaces for the key
// light, Shader::lightOther for the others), the shadow rays of a directional light cleared by a
// cone per block where it proves them lit (ShadowRays::clearLitByCones).
#pragma once

#include <vector>

#include "quaternia/render/lane_environment.h"
#include "quaternia/render/lanes/shading_lanes.h"
#include "quaternia/render/path_waves.h"
#include "quaternia/render/shadow_rays.h"

namespace quaternia {

// The shadow march of a light's rays (soft or hard, its sharpness).
ShadowMarch shadowMarchOf(const LightSource& light, const Shader& shader);

class GroundLighting {
  public:
    struct Frame {
        const LaneFractal& lanes;
        const Shader& shader;
        const GroundSettings& ground;
        const LightConstants& lightConstants;
        const CameraMarch& march;
        double boundingRadius;
        // Whether a cone per block may clear a directional light's rays: only in a uniform pass
        // (one sample of every pixel of the tile in the batch; see LaneTileRenderer).
        bool cones;
    };
    // The light at every point: colour() and the key light's visibility (1 where the key light
    // is behind the plane: no shadow to catch there). `shadows` is the batch to use.
    void light(const std::vector<GroundPoint>& points, const Frame& frame, ShadowRays& shadows,
               LaneCounters& counters);
    const std::vector<Color>& colour() const { return colour_; }
    const std::vector<double>& keyVisibility() const { return keyVisibility_; }

  private:
    // One light's visibility at every point into `out` (1 where it needs no shadow ray).
    void visibilities(const std::vector<GroundPoint>& points, const Frame& frame,
                      const LightSource& light, ShadowRays& shadows, LaneCounters& counters,
                      std::vector<double>& out) const;

    std::vector<double> keyVisibility_, otherVisibility_;
    std::vector<Color> colour_;
    SurfaceBatch surfaces_;
    EnvironmentShadows environment_;
    std::vector<EnvironmentPoint> environmentPoints_;
};

}  // namespace quaternia
