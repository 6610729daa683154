// Certified pictures (`quaternia render --certify`): for each pixel, a proof of what its ray
// meets, in interval arithmetic (interval/), independent of the distance estimate and of the
// marchers' floating point:
// - missed: no point of K_N lies in the pixel's footprint cone, from the camera to where the
//   cone leaves the set's ball. The cone is that of every ray through the pixel's footprint
//   square, of side max(1, 4 render.epsilon) pixels about its centre, whose inscribed disc holds
//   the points within 2 epsilon footprints of the central ray (the sphere tracer takes a point
//   within epsilon footprints of an estimate below epsilon, which is at least half the
//   distance, as a grazing hit: march.cpp). Proven by tubes (Fractal::excludesTube, proveCone),
//   as the renderer's cones of proof (proven_cones.h) prove blocks of pixels, here down to the
//   pixel and, where its cone stops short, its quarters.
// - hit: a point of the central ray is proven in K_N (Fractal::includesPoint: the ball, then
//   the box, of its rounding, iterated, stays in the bailout's ball), and the first point of
//   K_N on the central ray lies within [nearestHit, farthestHit]: the ray is proven outside K_N
//   before nearestHit (by the blocks' tubes, then by segments of the central ray alone), and
//   the point at farthestHit is in it.
// - undecided: neither, where the footprint straddles the surface (silhouettes, grazing rays,
//   parts thinner than a pixel) or the orbit of the central ray's points lies too near the
//   bailout for the box to decide.
// So a renderer that draws a pixel as missed that is certainly hit has overshot the surface,
// and one that draws a certainly missed pixel as hit has drawn a false surface
// (Certificate.RendererAgreesWithProof). Knoll et al., "Fast ray tracing of arbitrary implicit
// surfaces with interval and affine arithmetic" (Computer Graphics Forum 28(1), 2009) cast
// rays through intervals this way; the classes are those of Figueiredo, Nehab, Stolfi and
// Oliveira's certified Julia set images ("Images of Julia sets that you can trust", 2012).
#pragma once

#include <cstdint>
#include <vector>

#include "quaternia/fractal/fractal.h"
#include "quaternia/image/image.h"
#include "quaternia/render/camera.h"
#include "quaternia/scene/scene.h"
#include "quaternia/util/parallel.h"

namespace quaternia {

// The classes as the certificate's grey PNG stores them.
enum class PixelClass : uint8_t { kMissed = 0, kUndecided = 128, kHit = 255 };

struct CertificateCounts {
    int64_t missed = 0, hit = 0, undecided = 0;
    double undecidedFraction() const {
        const int64_t all = missed + hit + undecided;
        return all > 0 ? double(undecided) / double(all) : 0.0;
    }
};

struct PixelCertificate {
    // Where no certain hit holds a depth (as RenderPasses::kNoHitDistance).
    static constexpr float kNoDepth = 1e10f;
    int width = 0, height = 0;
    std::vector<uint8_t> classes;  // PixelClass per pixel, row-major
    // Per pixel, for certain hits: the first point of K_N on the central ray lies between these
    // distances from the camera (rounded outward to float); kNoDepth elsewhere.
    std::vector<float> nearestHit, farthestHit;
    CertificateCounts counts;
    int64_t proofs = 0;  // tube, segment and box proofs tried
    int threads = 0;
    double seconds = 0;
    bool completed = true;  // false if cancelled

    PixelClass at(int x, int y) const {
        return PixelClass(classes[size_t(y) * size_t(width) + size_t(x)]);
    }
};

// What no certificate can take, as a one-line UserError naming the key: a formula part with no
// interval extension yet (fractal.formula: "the function log") and a thin lens
// (camera.aperture: its rays do not share the pinhole the cones need). validateScene first.
void validateCertificate(const Scene& scene);

// The certificate of the scene's picture at render.width x render.height (validates first;
// threads, cancellation and progress as a render's).
PixelCertificate certifyPixels(const Scene& scene, const WorkOptions& options = {});
// The same for a fractal seen by a pinhole camera, with footprint squares of side
// max(1, 4 epsilon) pixels (header comment).
PixelCertificate certifyPixels(const Fractal& fractal, const Camera& camera, double epsilon,
                               const WorkOptions& options = {});

// A certificate of the size with every pixel undecided and no depths (where certifiers start).
PixelCertificate undecidedCertificate(int width, int height);
// Sets certificate.counts from its classes.
void tallyClasses(PixelCertificate& certificate);

// The undecided pixels of `image` (display values, the certificate's size) mixed halfway
// with magenta, opaque: where the picture is not proven.
void tintUndecided(Image& image, const PixelCertificate& certificate);
// The classes as an 8-bit grey PNG.
std::vector<uint8_t> encodeCertificatePng(const PixelCertificate& certificate);

}  // namespace quaternia
