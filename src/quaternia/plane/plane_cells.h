// The filled Julia set itself, not K_N, on a complex plane image (`quaternia certify` with a PNG
// output): every pixel's square classified by cell mapping (cellmap/cell_mapping.h) as
// certainly outside K (0: every point's orbit tends to infinity), certainly inside K (255:
// every point's orbit stays bounded, in a region the map traps) or undecided (128: the pixel
// may hold a point of the Julia set, or lie too near it for cells of its size to decide). The
// undecided pixels are therefore a proven cover of the part of J in the view.
//
// The cells are the pixels' squares (plane.center, plane.width, plane.rotation and the image
// size, PlaneView), continued beyond the view to cover the escape disc, coarser away from the
// view. The map is the scene's complex polynomial (plane.kind = "julia" or "julia-boundary",
// complexRestrictionOfScene); plane.max_iterations and fractal.bailout play no part (the set
// is K, not K_N).
#pragma once

#include <cstdint>
#include <vector>

#include "quaternia/cellmap/cell_mapping.h"
#include "quaternia/cellmap/undecided_band.h"
#include "quaternia/scene/scene.h"

namespace quaternia {

struct PlaneCells {
    int width = 0, height = 0;
    std::vector<uint8_t> classes;  // per pixel, row 0 at the top (the plane image's order)
    int64_t outside = 0, inside = 0, undecided = 0;  // pixels
    double pixelArea = 0;                            // plane units^2
    UndecidedBand band;
    std::vector<double> coefficients;  // the polynomial's, as re, im pairs lowest degree first
    double escapeRadius = 0;
    CellMappingReport report;
    bool completed = true;
};

// validatePlaneScene, then what the cell mapping takes: plane.kind julia or julia-boundary
// (UserError naming plane.kind otherwise), a complex restriction of degree 2 or more.
void validatePlaneCells(const Scene& scene);

// Validates, then classifies. `memoryLimitBytes` caps the cells (MemoryLimitError naming
// render.width).
PlaneCells certifyPlaneCells(const Scene& scene, const WorkOptions& work,
                             uint64_t memoryLimitBytes = uint64_t(4) << 30);

}  // namespace quaternia
