// Certified plane images (`quaternia plane --certify`): each pixel of a plane image classified
// by a proof, not by sampling. The pixel's cell is its square of the image mapped by the
// PlaneView (rotation included) into the plane that plane.kind draws; K_N is the set the kind
// draws, with its N (plane.max_iterations), bailout and membership rule:
// - certainly missed (0): no point of the cell belongs to K_N, proven by iterating the cell in
//   interval arithmetic (interval/): for the julia kinds and the slice kind by the set's
//   JuliaSet::excludesSegment along the cell's middle line, thickened to the cell's half height
//   (in every component of the algebra, with a margin for the rounding of the plane's points);
//   for the mandelbrot kind by iterating the box of c enclosing the cell, from z_0 = 0. A cell
//   not proven whole is cut into four, and each part again, down to a sixteenth of a pixel; it
//   is missed where every part is.
// - certainly hit (255): the cell's centre (the image's sample with render.samples = 1) is in K_N,
// proven by
//   iterating a box about it, as wide as the rounding of the plane's point, with every iterate
//   the membership test reads wholly inside the ball (JuliaSet::includesBox); for mandelbrot,
//   c's orbit z_1 .. z_N in disc arithmetic, within max(2, |c|).
// - undecided (128): neither was proven: cells that the boundary passes through or comes close
//   to, and cells whose centre's box grows past the ball (a box turned with the orbit is
//   wrapped in a wider box each time, so near an attracting cycle whose multiplier is not far
//   below 1 the boxes grow, where discs would not).
// Basins have no certificate (their colours are not K_N): refused, naming plane.kind.
#pragma once

#include <cstdint>
#include <vector>

#include "quaternia/render/pixel_certificate.h"
#include "quaternia/render/render.h"
#include "quaternia/scene/scene.h"

namespace quaternia {

// The classes are render/pixel_certificate.h's PixelClass, counted as there.
struct PlaneCertificate {
    int width = 0, height = 0;
    std::vector<uint8_t> classes;  // PixelClass per pixel, row-major as the plane image's pixels
    CertificateCounts counts;
    int threads = 0;
    double seconds = 0;
    bool completed = true;  // false if cancelled (the classes are then incomplete)

    PixelClass at(int x, int y) const {
        return PixelClass(classes[size_t(y) * size_t(width) + size_t(x)]);
    }
};

// validatePlaneScene, then what a certificate needs: a kind that draws K_N (not basins, refused
// naming plane.kind) and a formula with an interval extension (JuliaSet::unprovablePart,
// refused naming fractal.formula). Throws UserError naming the key.
void validatePlaneCertificate(const Scene& scene);

// Validates (above), then classifies every pixel of the plane image of the scene, tiles spread
// over options.threads by the one parallel-for.
PlaneCertificate certifyPlane(const Scene& scene, const WorkOptions& options = {});

}  // namespace quaternia
