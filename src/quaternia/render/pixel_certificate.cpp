#include "quaternia/render/pixel_certificate.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "quaternia/image/png_writer.h"
#include "quaternia/render/march.h"
#include "quaternia/render/render.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

// Blocks of pixels share their cone's proofs far from the set (as proven_cones.h's), splitting
// where a run of this many units fails, down to the pixel.
constexpr int kBlock = 16;
constexpr int64_t kShortestBlockRun = 16;
// The unit of a run, in pixel footprints at the distance of the origin: runs of 1 unit are the
// shortest a pixel's tube or central ray tries.
constexpr double kUnitFootprints = 0.25;
// Samples of the central ray tried for a point in K_N past the proven part, kUnitFootprints
// apart: the surface lies within a few footprints of where the tube stops being provable.
constexpr int kHitSamples = 256;

float roundedDownFloat(double x) {
    const float f = float(x);
    return double(f) <= x ? f : std::nextafter(f, -std::numeric_limits<float>::infinity());
}
float roundedUpFloat(double x) {
    const float f = float(x);
    return double(f) >= x ? f : std::nextafter(f, std::numeric_limits<float>::infinity());
}

class Certifier {
  public:
    Certifier(const Fractal& fractal, const Camera& camera, double epsilon)
        : fractal_(fractal),
          camera_(camera),
          // The footprint cone's radius per unit distance, past the directions' rounding.
          footprintSlope_(std::max(1.0, 2 * epsilon) * camera.pixelFootprint(1) * (1 + 1e-9)),
          unit_(kUnitFootprints * camera.pixelFootprint(std::max(length(camera.position()), 1e-3))),
          // The set's ball, past the rounding of where rays meet it.
          ball_(fractal.boundingRadius() * (1 + 1e-9) + 1e-12) {}

    void certifyTile(const Tile& tile, PixelCertificate& out, int64_t& proofs) const {
        for (int y = tile.y0 / kBlock * kBlock; y < tile.y1; y += kBlock)
            for (int x = tile.x0 / kBlock * kBlock; x < tile.x1; x += kBlock)
                certifyBlock(x, y, kBlock, 0, tile, out, proofs);
    }

  private:
    // The largest chord between the central direction of the square [x0, x0 + size)^2 and a
    // corner's: the cone of rays through the square (proven_cones.h).
    double coneSlope(const Ray& centre, int x0, int y0, int size) const {
        double rho = 0;
        for (int corner = 0; corner < 4; ++corner) {
            const Ray edge =
                camera_.generateRay(x0 + (corner & 1) * size, y0 + (corner >> 1) * size);
            rho = std::max(rho, length(edge.direction - centre.direction));
        }
        return rho * (1 + 1e-9) + 1e-15;
    }

    // Proves the tube of radius slope t about `ray` outside K_N by runs from `t`, until `tFar`
    // or a run shorter than `shortest` units fails; returns how far it got.
    double clearTube(const Ray& ray, double t, double tFar, double slope, int64_t shortest,
                     int64_t& span, int64_t& proofs) const {
        ProofRuns runs{span};
        while (t < tFar) {
            const double end = std::min(t + double(runs.span) * unit_, tFar);
            ++proofs;
            if (fractal_.excludesTube(ray, t, end, slope * end)) {
                t = end;
                runs.proved();
            } else {
                runs.failed();
                if (runs.span < shortest) break;
            }
        }
        span = std::max<int64_t>(runs.span, 1);
        return t;
    }

    void certifyBlock(int x0, int y0, int size, double from, const Tile& tile,
                      PixelCertificate& out, int64_t& proofs) const {
        const Ray centre = camera_.generateRay(x0 + 0.5 * size, y0 + 0.5 * size);
        const double rho = coneSlope(centre, x0, y0, size);
        // Every pixel's footprint cone lies within this one (its central ray within rho t,
        // its points within footprintSlope t of that).
        const double slope = size == 1 ? std::max(rho, footprintSlope_) : rho + footprintSlope_;
        // The largest angle at a corner needs the cone in front of the image plane
        // (proven_cones.h); near a field of view of 180 degrees it is not, and the block
        // splits without a cone (a pixel proves no miss).
        const bool coneHolds = dot(centre.direction, camera_.forward()) > slope;
        const double farthest = length(centre.origin) + ball_;
        const auto interval = intersectSphere(centre, ball_ + slope * farthest);
        double t = interval ? std::max(from, interval->tNear) : 0;
        const double tFar = interval ? interval->tFar : 0;
        int64_t span = size == 1 ? kSpanAfterCone : kFirstSpan;
        if (coneHolds)
            t = clearTube(centre, t, tFar, slope, size == 1 ? 1 : kShortestBlockRun, span, proofs);
        const bool missed = coneHolds && !(t < tFar);
        if (size == 1) {
            settlePixel(x0, y0, centre, missed, coneHolds ? t : from, tFar, span, out, proofs);
            return;
        }
        if (missed) {
            for (int py = std::max(y0, tile.y0); py < std::min(y0 + size, tile.y1); ++py)
                for (int px = std::max(x0, tile.x0); px < std::min(x0 + size, tile.x1); ++px)
                    record(px, py, PixelClass::kMissed, 0, 0, out);
            return;
        }
        const int half = size / 2;
        for (int y = y0; y < y0 + size; y += half)
            for (int x = x0; x < x0 + size; x += half)
                if (x < tile.x1 && x + half > tile.x0 && y < tile.y1 && y + half > tile.y0)
                    certifyBlock(x, y, half, coneHolds ? t : from, tile, out, proofs);
    }

    // A pixel whose tube is proven up to `until`: missed, or a point of its central ray proven
    // in K_N past the part of the ray proven outside, or undecided.
    void settlePixel(int px, int py, const Ray& ray, bool missed, double until, double tFar,
                     int64_t span, PixelCertificate& out, int64_t& proofs) const {
        if (missed) {
            record(px, py, PixelClass::kMissed, 0, 0, out);
            return;
        }
        // The central ray alone is provable nearer the surface than its tube.
        const double nearest = clearTube(ray, until, tFar, 0, 1, span, proofs);
        for (int k = 0; k < kHitSamples; ++k) {
            const double t = nearest + k * unit_;
            if (t > tFar) break;
            const Point3d p = ray.at(t);
            if (!fractal_.contains(p)) continue;
            ++proofs;
            if (fractal_.includesPoint(p)) {
                record(px, py, PixelClass::kHit, nearest, t, out);
                return;
            }
        }
        record(px, py, PixelClass::kUndecided, 0, 0, out);
    }

    static void record(int px, int py, PixelClass c, double nearest, double farthest,
                       PixelCertificate& out) {
        const size_t i = size_t(py) * size_t(out.width) + size_t(px);
        out.classes[i] = uint8_t(c);
        if (c == PixelClass::kHit) {
            out.nearestHit[i] = roundedDownFloat(nearest);
            out.farthestHit[i] = roundedUpFloat(farthest);
        }
    }

    const Fractal& fractal_;
    const Camera& camera_;
    double footprintSlope_;
    double unit_;
    double ball_;
};

}  // namespace

void validateCertificate(const Scene& scene) {
    const Fractal fractal = fractalFromScene(scene);
    if (auto part = fractal.unprovablePart()) {
        throw UserError("fractal.formula",
                        "fractal.formula: " + *part +
                            " has no interval extension yet, so no pixel can be certified");
    }
    if (scene.camera.aperture > 0) {
        throw UserError("camera.aperture",
                        "camera.aperture must be 0 for a certificate: a thin lens's rays share "
                        "no pinhole for the footprint cones");
    }
}

PixelCertificate certifyPixels(const Scene& scene, const WorkOptions& options) {
    validateScene(scene);
    validateCertificate(scene);
    const Fractal fractal = fractalFromScene(scene);
    const Camera camera(scene.camera, scene.render.width, scene.render.height);
    return certifyPixels(fractal, camera, scene.render.epsilon, options);
}

PixelCertificate certifyPixels(const Fractal& fractal, const Camera& camera, double epsilon,
                               const WorkOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    PixelCertificate out;
    out.width = camera.width();
    out.height = camera.height();
    const size_t pixels = size_t(out.width) * size_t(out.height);
    out.classes.assign(pixels, uint8_t(PixelClass::kUndecided));
    out.nearestHit.assign(pixels, PixelCertificate::kNoDepth);
    out.farthestHit.assign(pixels, PixelCertificate::kNoDepth);
    const Certifier certifier(fractal, camera, epsilon);
    const ParallelOptions parallel = imageParallelOptions(options, out.width, out.height);
    std::vector<int64_t> proofs(size_t(resolveThreadCount(parallel.threads)), 0);
    out.completed =
        parallelForTiles(out.width, out.height, parallel, [&](const Tile& tile, int thread) {
            certifier.certifyTile(tile, out, proofs[size_t(thread)]);
        });
    for (int64_t p : proofs)
        out.proofs += p;
    for (uint8_t c : out.classes) {
        if (c == uint8_t(PixelClass::kMissed))
            ++out.counts.missed;
        else if (c == uint8_t(PixelClass::kHit))
            ++out.counts.hit;
        else
            ++out.counts.undecided;
    }
    out.threads = resolveThreadCount(parallel.threads);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

void tintUndecided(Image& image, const PixelCertificate& certificate) {
    for (int y = 0; y < std::min(image.height(), certificate.height); ++y)
        for (int x = 0; x < std::min(image.width(), certificate.width); ++x) {
            if (certificate.at(x, y) != PixelClass::kUndecided) continue;
            Rgba& p = image.at(x, y);
            p = Rgba{0.5f * (p.r + 1.0f), 0.5f * p.g, 0.5f * (p.b + 1.0f), 1.0f};
        }
}

std::vector<uint8_t> encodeCertificatePng(const PixelCertificate& certificate) {
    PngFormat format{certificate.width, certificate.height, 8, PngColorType::Gray};
    return writePngBytes(format, certificate.classes);
}

}  // namespace quaternia
