// A certified filled Julia set K of the scene's formula (`quaternia certify -o FILE.qcells`, read
// back by render.certified): the classified cells of cell mapping (cell_mapping.h) in one of two
// spaces, and what it takes to classify a point or a box of the algebra from them.
// - Reduced: a real polynomial sum a_k z^k + c in the quaternions or octonions, certified on the
//   3D space (x, a, r) of box_maps.h. A point z of the algebra has x = Re z, a = <Im z, n>,
//   r = |Im z - a n|, n = Im c / |Im c|; its class is its reduced point's.
// - Product: a bicomplex polynomial, K = K_1 x K_2 in duplex coordinates (hypercomplex.h,
//   duplexForm): two complex planes certified apiece; z is inside where both components are,
//   outside where either is.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "quaternia/algebra/hypercomplex.h"
#include "quaternia/cellmap/cell_grid.h"

namespace quaternia {

enum class CertifiedSpace : uint8_t { kReduced = 1, kProduct = 2 };

struct CertifiedSet {
    CertifiedSpace space = CertifiedSpace::kReduced;
    Algebra algebra = Algebra::kQuaternion;
    std::string formula;  // fractal.formula as certified
    Hypercomplex c{};     // fractal.c as certified
    // Reduced: the polynomial's real coefficients (lowest degree first, a_0 = 0), its constant's
    // real part and |Im|, and the axis n (a unit imaginary element; i where Im c = 0).
    std::vector<double> coefficients;
    double realConstant = 0, imaginaryConstant = 0;
    Hypercomplex axis{};
    double escapeRadius = 0;
    std::vector<CellGrid> grids;  // Reduced: one 3D grid; Product: the two components' planes

    // The class of every point of a box of the algebra (an interval per component, dimension
    // components): outside or inside where the cells prove it for the whole box, else
    // undecided. Points beyond the grids are outside (the grids hold the escape ball).
    CellClass classOfBox(const Interval* box, int dimension) const;
    CellClass classOfPoint(const Hypercomplex& z, int dimension) const;
    // Which classes the box's points may have (CellGrid::classesInBox's bits): kHasOutside
    // alone where all are outside, kHasInside alone where all are inside, and kHasInside among
    // others where some inside cell is touched.
    uint8_t classesOfBox(const Interval* box, int dimension) const;

    // The file: a magic line, then the set zlib-compressed.
    std::vector<uint8_t> encode() const;
    // Throws UserError(key, ...) naming the file for anything that is not a whole, valid set.
    static CertifiedSet decode(const std::vector<uint8_t>& bytes, const std::string& key,
                               const std::string& name = "");
    static CertifiedSet read(const std::string& path, const std::string& key);

  private:
    std::array<Interval, 3> reducedBox(const Interval* box, int dimension) const;
};

}  // namespace quaternia
