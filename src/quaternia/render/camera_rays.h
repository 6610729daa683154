// One job of the SIMD path (lane_tile_renderer.h): a tile's camera rays. Cone marching
// (Amanatides 1984; as in demoscene "cone marching"): one cone per block of kConeBlock^2 pixels
// marched to where the set may be near, so that the pixels' own rays start there, or are known
// to miss it. Then the rays of one sample of every pixel of the tile, row by row, or of queued
// samples of any pixels (adaptive sampling), go into a batch with the pixel and cone block of
// each; the rays whose cone or bounding sphere missed go to a bypass list where the caller wants
// them (the ground and the glow still see them).
#pragma once

#include <vector>

#include "quaternia/render/camera.h"
#include "quaternia/render/lanes/march_lanes.h"
#include "quaternia/util/parallel.h"

namespace quaternia {

// A camera ray that skips the set, for the pixel (of the tile) it serves.
struct BypassRay {
    Ray ray;
    int pixel;
};

// Where the camera rays go: the batch to march, each ray's pixel of the tile and cone block,
// and (where not null) the rays that skip the set.
struct CameraRayBatch {
    RayBatch& rays;
    std::vector<int>& pixel;
    std::vector<int>& block;
    std::vector<BypassRay>* bypass;
};

class CameraRays {
  public:
    static constexpr int kConeBlock = 4;

    // The frame's camera, the set's bounding radius, the camera rays' march, the samples per
    // pixel, and whether a glow is drawn (then the rays of a block whose cone missed the set
    // are marched all the same: their least estimates are the glow's).
    void bind(const Camera& camera, double boundingRadius, const CameraMarch& march, int samples,
              bool glow);

    // The cones of the blocks of `tile` (on the image's grid when the tile's corner is on it):
    // each block's start, or infinity where its cone missed.
    void marchCones(const LaneFractal& lanes, const Tile& tile, int64_t& marchSteps,
                    LaneCounters& counters);
    // The camera rays of sample k of the tile's pixels (its cones marched), into `out`: none in
    // the blocks whose cones missed.
    void sampleRays(const Tile& tile, int k, const CameraRayBatch& out);
    // Sample k of pixel (px, py), for out.pixel = target: queued, then with the others queued
    // pushed by pushQueued (`blocks` the tile whose cones were marched).
    void queue(int px, int py, int k, int target) { queued_.push_back({px, py, k, target, 0, 0}); }
    void pushQueued(const Tile& blocks, const CameraRayBatch& out);

  private:
    // The cones' radius per unit of t, for every block of the image.
    static double coneRatio(const Camera& camera);
    // One sample per pixel: the rays through the centres of row py of the tile, in rowRays_,
    // for the pixels of the blocks whose start (the row's blocks) is finite (all of them where
    // `bypassing`).
    void rowRays(const Tile& tile, int py, const double* blockStart, bool bypassing);
    // Several samples per pixel: sample k (samplePosition) of each pixel of row py, in rowRays_.
    void sampleRowRays(const Tile& tile, int py, int k);
    // The rays of rowRays_ (row py) that may meet the set, into out: from their block's start
    // (blockStart, the row's blocks) to where they leave the bounding sphere.
    void pushRowRays(const Tile& tile, int py, const double* blockStart, const CameraRayBatch& out);

    const Camera* camera_ = nullptr;
    double boundingRadius_ = 0;
    CameraMarch march_;
    int samples_ = 1;
    bool glow_ = false;
    double coneRatio_ = 0;

    RayBatch cones_;
    std::vector<TraceResult> coneResults_;
    std::vector<int> coneBlock_;
    std::vector<double> blockStart_;
    std::vector<Ray> coneCentres_;
    // A row of the tile's rays (from the camera), and where each is inside the bounding sphere
    // (tNear > tFar where it misses).
    struct RowRay {
        Point3d origin;  // the camera's position, or a point of its thin lens
        Vector3d direction;
        double tNear, tFar;
    };
    std::vector<RowRay> rowRays_;
    struct QueuedSample {
        int px, py, k, target;
        double x, y;  // the image point (samplePosition)
    };
    std::vector<QueuedSample> queued_;
    std::vector<Ray> queuedRays_;
    std::vector<double> queuedNear_, queuedFar_;
};

}  // namespace quaternia
