// The scalar path's cones of proof: Algorithm 2's fixed steps through a set that proves empty
// segments (march.h, firstSampleInside) cross empty space for a whole block of pixels at once.
// The rays through a block of the image leave the camera's pinhole within a cone about the
// block's central ray: at distance t along it every such ray lies within t rho of the central
// ray's point, rho the largest chord between the central direction and a corner's (the angle
// from the central direction is largest at a corner of the block, whose image-plane points
// within a given angle form a convex conic). So a tube about the central ray of radius rho t1
// holds every ray's points from t0 to t1 (Fractal::excludesTube proves it outside K_N), and
// each ray of the block may start past the proven part. Runs of the central ray are proven as
// the rays' own runs are (ProofRuns, march.h); where a run of 16 steps fails the block splits
// into four, each going on from there, down to blocks of 2 x 2 pixels: far from the set a block of
// 16 x 16 pixels takes the proofs that one ray took, and near it the pixels' own rays take over.
// Amanatides's cone tracing (1984) with proofs in place of distance bounds, as Knoll et al. 2009
// cast frusta of rays through interval arithmetic ("Fast ray tracing of arbitrary implicit surfaces
// with interval and affine arithmetic", Computer Graphics Forum 28(1)).
//
// Blocks lie on the image's grid of kBlock pixels whatever the tile, and a ray's first inside
// sample does not depend on where it starts among samples proven outside: the picture is the
// plain fixed steps' (Marching.ConesOfProofKeepTheRaysSamples).
#pragma once

#include <cstdint>
#include <vector>

#include "quaternia/fractal/fractal.h"
#include "quaternia/render/camera.h"
#include "quaternia/render/march.h"
#include "quaternia/util/parallel.h"

namespace quaternia {

// Proves the cone of `slope` about `ray` (radius slope t at distance t; 0: the ray alone)
// outside K_N by runs of `runs.span` units, from t on, until tFar or a run shorter than
// `shortest` units fails; returns how far it got. The block cones here and the certificates'
// (pixel_certificate.h) go the same way.
double proveCone(const Fractal& fractal, const Ray& ray, double t, double tFar, double unit,
                 double slope, int64_t shortest, ProofRuns& runs, int64_t& tests);

class ProvenCones {
  public:
    static constexpr int kBlock = 16;

    // For `fractal` seen by `camera` (a pinhole: no cones through a thin lens) at fixed steps
    // of `step`.
    ProvenCones(const Fractal& fractal, const Camera& camera, double step);
    // Whether the cones can prove anything here (the set proves empty segments, the camera is
    // a pinhole).
    bool active() const { return active_; }

    // For each pixel of `tile` (row by row), a distance up to which every ray through the pixel
    // is proven outside K_N (0 where nothing is, and everywhere where the cones are not active;
    // infinity where the whole ray is); returns the tubes tested.
    int64_t clear(const Tile& tile, std::vector<double>& provenUntil) const;

  private:
    void clearBlock(int x0, int y0, int size, double from, const Tile& tile,
                    std::vector<double>& provenUntil, int64_t& tests) const;
    // The pixels of the block (those in the tile) proven up to `until`.
    static void markPixels(int x0, int y0, int size, double until, const Tile& tile,
                           std::vector<double>& provenUntil);

    const Fractal& fractal_;
    const Camera& camera_;
    double step_;
    double boundingRadius_;
    bool active_;
};

}  // namespace quaternia
