// The scene's filled Julia set K certified by cell mapping (`quaternia certify -o FILE.qcells`):
// in the reduced space (x, a, r) for a real polynomial sum a_k z^k + c of the quaternions or
// octonions, or as the product of its duplex components' planes for a bicomplex polynomial
// (certified_set.h). What has no such reduction is refused in one line naming why: coefficients
// that are not real (two-sided or imaginary ones: no reduction is known), c inside a product,
// functions (exp, sin, ...), coquaternions and biquaternions (null elements: no escape radius).
#pragma once

#include <vector>

#include "quaternia/cellmap/cell_mapping.h"
#include "quaternia/cellmap/certified_set.h"
#include "quaternia/scene/scene.h"

namespace quaternia {

struct SetCertification {
    CertifiedSet set;
    std::vector<CellMappingReport> reports;  // one per grid
    std::vector<CellGrid::Census> census;    // one per grid (volumes in the grid's units)
    int64_t cellsPerAxis = 0;                // finest cells per axis, as made
    bool completed = true;
};

// Throws UserError naming fractal.formula or fractal.algebra where the set has no certificate.
void validateSetCertification(const Scene& scene);

// Validates, then certifies on grids of `resolution` finest cells per axis (rounded up to the
// levels' sizes). MemoryLimitError naming --resolution past `memoryLimitBytes`.
SetCertification certifySet(const Scene& scene, int resolution, const WorkOptions& work,
                            uint64_t memoryLimitBytes = uint64_t(4) << 30);

}  // namespace quaternia
