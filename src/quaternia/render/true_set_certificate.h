// The certificate of a picture against the filled Julia set K itself (render.certified: a cells
// file of `quaternia certify`, cellmap/certified_set.h), in the classes of pixel_certificate.h:
// - missed: every point of the pixel's footprint cone (the square of side max(1, 4 epsilon)
//   pixels, as there) between the camera and the slice of the escape ball lies in outside
//   cells: no point of K is seen through the pixel.
// - hit: a point of the central ray lies in inside cells (its box, rounding included, does):
//   the ray meets K. The first point of K on the central ray lies within [nearestHit,
//   farthestHit]: the cone is outside K before nearestHit and the point at farthestHit is in K.
// - undecided: the rest (the cone passes through undecided cells, and no central-ray point was
//   proven inside).
// The cone is cut into pieces front to back; each piece's box, taken through the slice into
// the algebra (the slice is affine), is classified by the cells. An undecided piece is halved
// down to about half a finest cell, and the central-ray point in the middle of the last ones
// is tried alone. For a set that is dust (a Cantor set: no inside cell) no pixel is a hit.
#pragma once

#include <memory>

#include "quaternia/cellmap/certified_set.h"
#include "quaternia/fractal/fractal.h"
#include "quaternia/render/camera.h"
#include "quaternia/render/pixel_certificate.h"

namespace quaternia {

// Reads scene.render.certified and checks it certifies the scene's formula, c and algebra
// (UserError naming render.certified otherwise, or for an unreadable file). The last file read
// is kept while its size and modification time stay the same (the explorer asks per frame).
std::shared_ptr<const CertifiedSet> certifiedSetOfScene(const Scene& scene);

// The certificate of the picture of `fractal`'s slice (its algebra's, never folded:
// hypercomplexFractalFromScene) seen by `camera`, against `set`.
PixelCertificate certifyPixelsAgainstSet(const Fractal& fractal, const CertifiedSet& set,
                                         const Camera& camera, double epsilon,
                                         const WorkOptions& options = {});

}  // namespace quaternia
