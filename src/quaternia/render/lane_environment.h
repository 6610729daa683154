// One job of the SIMD path (lane_tile_renderer.h): the environment's diffuse light at a batch of
// surface points (the set's hits, the ground's), their shadow rays (Environment::
// shadowDirections) marched together in lanes, then each point's light by Environment::
// occludedDiffuse: the same directions and formula as Shader::environmentLight, which marches
// them one by one in double.
#pragma once

#include <vector>

#include "quaternia/render/environment.h"
#include "quaternia/render/shadow_rays.h"

namespace quaternia {

struct EnvironmentPoint {
    Point3d point;   // on the surface: seeds its rays (Environment::seedOf)
    Point3d origin;  // where its shadow rays start, a little off the surface
    Vector3d normal;
    Color albedo;
};

class EnvironmentShadows {
  public:
    // The light at every point into light() (in order); `shadows` is the batch to march in.
    void light(const LaneFractal& lanes, const Shader& shader,
               const std::vector<EnvironmentPoint>& points, ShadowRays& shadows,
               LaneCounters& counters);
    const std::vector<Color>& colour() const { return colour_; }

  private:
    std::vector<EnvironmentDirection> directions_;
    std::vector<double> visibility_;
    std::vector<Vector3d> normals_;
    std::vector<Color> colour_;
};

}  // namespace quaternia
