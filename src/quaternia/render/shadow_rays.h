// One job of the SIMD path (lane_tile_renderer.h): the shadow rays of a batch of surface points,
// marched in lanes (march_lanes.h, traceShadowRays) into each ray's visibility, and the two
// ways a cylinder or cone about the rays of one block of pixels spares most of their marching:
// - hard shadows of a directional key light at the set's hits (clipHardShadows): a cylinder
//   marched from the far side of the bounding sphere towards the block's origins proves the set
//   absent beyond where it stopped, so each ray is marched only up to there, and not at all
//   where the cylinder got past every origin;
// - a directional light's shadows on the ground (clearLitByCones): a cone from the origins along
//   the light that gets through proves its rays fully lit, so they are left out.
#pragma once

#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include "quaternia/render/lanes/march_lanes.h"
#include "quaternia/render/shade.h"

namespace quaternia {

class ShadowRays {
  public:
    // A block with fewer rays than this gets no cylinder: marching it costs more than it saves.
    static constexpr size_t kMinCylinderRays = 4;

    void clear() {
        rays_.clear();
        owners_.clear();
    }
    // A shadow ray from t = near to far, for the point `owner` (the caller's index, in order).
    void push(const Ray& ray, double near, double far, int owner) {
        rays_.push(ray, near, far);
        owners_.push_back(owner);
    }
    size_t size() const { return owners_.size(); }
    // Which point ray r belongs to, and what its march left (0 blocked .. 1; march's order).
    const std::vector<int>& owners() const { return owners_; }
    const std::vector<double>& visibility() const { return visibility_; }

    // Every ray marched (soft or hard, as `march` says), into visibility().
    void march(const LaneFractal& lanes, const ShadowMarch& march, LaneCounters& counters);

    // Hard shadows of a directional light (unit `toLight`) from the set's hits: a cylinder about
    // the rays of each of `blocks` blocks (blockOf(owner) of each ray, 0 .. blocks - 1; the hits
    // come in rows, so each block's rays stay in order) shortens them, then every ray is marched
    // (the ones cleared whole have visibility 1). `cameraMarch` is the camera's cone march.
    void marchClippedHardShadows(const LaneFractal& lanes, const CameraMarch& cameraMarch,
                                 const ShadowMarch& march, const Vector3d& toLight,
                                 double boundingRadius, int blocks,
                                 const std::function<int(int owner)>& blockOf,
                                 LaneCounters& counters);

    // A directional light's rays from ground points (blockOf(owner) their block, -1 for none):
    // the rays that a cone per block proves lit are left out (with their owners); the rest start
    // where their cone was last clear.
    void clearLitByCones(const LaneFractal& lanes, const CameraMarch& cameraMarch,
                         const LightSource& light, double boundingRadius,
                         const std::function<int(int owner)>& blockOf, LaneCounters& counters);

  private:
    Point3d origin(size_t r) const { return Point3d(rays_.ox[r], rays_.oy[r], rays_.oz[r]); }
    // The rays order_[first, end) about an axis along `direction` through their origins'
    // centre: the radius that holds every origin, and the extent along the axis from the
    // nearest origin to the farthest ray end (each as the offset from the centre).
    struct RayBundle {
        Point3d centre;
        double radius, nearest, farthest;
    };
    RayBundle bundleOf(size_t first, size_t end, const Vector3d& direction,
                       double boundingRadius) const;
    // clipHardShadows' steps: the rays block by block (order_, block b's from blockStarts_[b]);
    // one cylinder per block; each cylinder's rays shortened to where it stopped, those it
    // cleared whole flagged in cleared_ (returns how many).
    void orderByBlock(int blocks, const std::function<int(int owner)>& blockOf);
    void pushCylinder(size_t first, size_t end, const Vector3d& toLight, double boundingRadius);
    size_t shortenToCylinders(const Vector3d& toLight, int maxSteps);
    void clipHardShadows(const LaneFractal& lanes, const CameraMarch& cameraMarch,
                         const Vector3d& toLight, double boundingRadius, int blocks,
                         const std::function<int(int owner)>& blockOf, LaneCounters& counters);

    RayBatch rays_;
    std::vector<int> owners_;
    std::vector<double> visibility_, marchedVisibility_;
    std::vector<int> blockStarts_, blockFill_, order_, block_;
    RayBatch cylinders_;
    std::vector<std::pair<size_t, size_t>> cylinderRays_;  // each cylinder's range of order_
    std::vector<TraceResult> cylinderResults_;
    std::vector<uint8_t> cleared_;
};

}  // namespace quaternia
