#include "quaternia/render/pixel_certificate.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

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
// Segments of the central ray tried for the near end of a hit's depth interval.
constexpr int kNearTries = 4;
// Halvings of a pixel's footprint square where its cone is not proven whole: 4 and 16 cones.
constexpr int kFootprintSplits = 2;

float roundedDownFloat(double x) {
    const float f = float(x);
    return double(f) <= x ? f : std::nextafter(f, -std::numeric_limits<float>::infinity());
}
float roundedUpFloat(double x) {
    const float f = float(x);
    return double(f) >= x ? f : std::nextafter(f, std::numeric_limits<float>::infinity());
}

// A square of the image, [x0, x0 + size)^2 in pixel units, and the cone of the rays through it.
struct Square {
    double x0, y0, size;
};

class Certifier {
  public:
    Certifier(const Fractal& fractal, const Camera& camera, double epsilon)
        : fractal_(fractal),
          camera_(camera),
          // The footprint square's side (header comment): its inscribed disc holds the points
          // within 2 epsilon footprints of the central ray.
          footprint_(std::max(1.0, 4 * epsilon)),
          unit_(kUnitFootprints * camera.pixelFootprint(std::max(length(camera.position()), 1e-3))),
          // The set's ball, past the rounding of where rays meet it.
          ball_(fractal.boundingRadius() * (1 + 1e-9) + 1e-12) {}

    void certifyTile(const Tile& tile, PixelCertificate& out, int64_t& proofs) const {
        for (int y = tile.y0 / kBlock * kBlock; y < tile.y1; y += kBlock)
            for (int x = tile.x0 / kBlock * kBlock; x < tile.x1; x += kBlock)
                certifyBlock(x, y, kBlock, 0, tile, out, proofs);
    }

  private:
    // The square of the footprints of the pixels [x0, x0 + size)^2.
    Square footprints(int x0, int y0, int size) const {
        const double margin = 0.5 * (footprint_ - 1);
        return {x0 - margin, y0 - margin, size + 2 * margin};
    }

    // The cone of a square's rays about its central ray (proven_cones.h): the largest chord
    // between the central direction and a corner's, per unit distance, past the directions'
    // rounding. Zero where the cone is not in front of the image plane: the largest angle lies
    // at a corner only while the centre's angle to the view axis plus the cone's is below 90
    // degrees, which fails only near a field of view of 180 degrees; such a cone proves nothing.
    double coneSlope(const Ray& centre, const Square& square) const {
        double rho = 0;
        for (int corner = 0; corner < 4; ++corner) {
            const Ray edge = camera_.generateRay(square.x0 + (corner & 1) * square.size,
                                                 square.y0 + (corner >> 1) * square.size);
            rho = std::max(rho, length(edge.direction - centre.direction));
        }
        rho = rho * (1 + 1e-9) + 1e-15;
        return dot(centre.direction, camera_.forward()) > rho ? rho : 0;
    }

    // Proves the cone of `slope` about `ray` outside K_N by tubes, runs from `t` on, until
    // `tFar` or a run shorter than `shortest` units fails; returns how far it got.
    double clearTube(const Ray& ray, double t, double tFar, double slope, int64_t shortest,
                     int64_t span, int64_t& proofs) const {
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
        return t;
    }

    // Where the cone of a square's rays about `centre` meets the set's ball (nothing where it
    // does not).
    std::optional<RayInterval> ballInterval(const Ray& centre, double slope) const {
        const double farthest = length(centre.origin) + ball_;
        return intersectSphere(centre, ball_ + slope * farthest);
    }

    void certifyBlock(int x0, int y0, int size, double from, const Tile& tile,
                      PixelCertificate& out, int64_t& proofs) const {
        if (size == 1) {
            settlePixel(x0, y0, from, out, proofs);
            return;
        }
        const Square square = footprints(x0, y0, size);
        const Ray centre = camera_.generateRay(square.x0 + 0.5 * square.size,
                                               square.y0 + 0.5 * square.size);
        const double slope = coneSlope(centre, square);
        const auto interval = ballInterval(centre, slope);
        double t = interval ? std::max(from, interval->tNear) : from;
        const double tFar = interval ? interval->tFar : 0;
        if (slope > 0) t = clearTube(centre, t, tFar, slope, kShortestBlockRun, kFirstSpan, proofs);
        if (slope > 0 && !(t < tFar)) {
            for (int py = std::max(y0, tile.y0); py < std::min(y0 + size, tile.y1); ++py)
                for (int px = std::max(x0, tile.x0); px < std::min(x0 + size, tile.x1); ++px)
                    record(px, py, PixelClass::kMissed, 0, 0, out);
            return;
        }
        const int half = size / 2;
        for (int y = y0; y < y0 + size; y += half)
            for (int x = x0; x < x0 + size; x += half)
                if (x < tile.x1 && x + half > tile.x0 && y < tile.y1 && y + half > tile.y0)
                    certifyBlock(x, y, half, slope > 0 ? t : from, tile, out, proofs);
    }

    // Whether every ray of the square is proven outside K_N from `from` to where its cone
    // leaves the ball: by the square's own cone, and where that stops short, by its quarters'
    // (down to `splits` halvings: a tube a quarter as wide is proven much nearer the set).
    bool clearSquare(const Square& square, double from, int splits, int64_t& proofs) const {
        const Ray centre = camera_.generateRay(square.x0 + 0.5 * square.size,
                                               square.y0 + 0.5 * square.size);
        const double slope = coneSlope(centre, square);
        if (!(slope > 0)) return false;
        const auto interval = ballInterval(centre, slope);
        if (!interval) return true;
        const double t = clearTube(centre, std::max(from, interval->tNear), interval->tFar,
                                   slope, 1, kSpanAfterCone, proofs);
        if (!(t < interval->tFar)) return true;
        if (splits == 0) return false;
        const double half = 0.5 * square.size;
        for (int quarter = 0; quarter < 4; ++quarter)
            if (!clearSquare({square.x0 + (quarter & 1) * half, square.y0 + (quarter >> 1) * half,
                              half},
                             t, splits - 1, proofs))
                return false;
        return true;
    }

    // A pixel whose rays are proven outside K_N up to `from`. A hit is looked for first along
    // the central ray (it needs no tube near the surface, where tubes are dearest); then the
    // miss is proven by the footprint's cone; where that stops short (at a part of the set
    // that the central ray may pass by) the ray alone is proven on and looked along again.
    void settlePixel(int px, int py, double from, PixelCertificate& out, int64_t& proofs) const {
        const Ray ray = camera_.generateRay(px + 0.5, py + 0.5);
        const auto interval = intersectSphere(ray, ball_);
        const double start = interval ? std::max(from, interval->tNear) : from;
        if (interval && findHit(px, py, ray, start, interval->tFar, out, proofs)) return;
        if (clearSquare(footprints(px, py, 1), from, kFootprintSplits, proofs)) {
            record(px, py, PixelClass::kMissed, 0, 0, out);
            return;
        }
        if (interval) {
            const double alone =
                clearTube(ray, start, interval->tFar, 0, 1, kSpanAfterCone, proofs);
            if (alone > start && findHit(px, py, ray, alone, interval->tFar, out, proofs)) return;
        }
        record(px, py, PixelClass::kUndecided, 0, 0, out);
    }

    // The first sample of the central ray in K_N (floating point) from `from` on, whose box of
    // rounding is then proven in K_N: recorded as a hit, with the depth interval's near end.
    bool findHit(int px, int py, const Ray& ray, double from, double tFar, PixelCertificate& out,
                 int64_t& proofs) const {
        for (int k = 0; k < kHitSamples; ++k) {
            const double t = from + k * unit_;
            if (t > tFar) break;
            const Point3d p = ray.at(t);
            if (!fractal_.contains(p)) continue;
            ++proofs;
            if (!fractal_.includesPoint(p)) continue;
            record(px, py, PixelClass::kHit, nearEnd(ray, from, t, proofs), t, out);
            return true;
        }
        return false;
    }

    // The near end of a hit's depth interval: the central ray is proven outside K_N up to
    // `from`, and alone it is provable nearer the surface than its tube: a few segments towards
    // the hit at t, the longest first.
    double nearEnd(const Ray& ray, double from, double t, int64_t& proofs) const {
        double nearest = from, end = t - unit_;
        for (int tries = 0; tries < kNearTries && end > nearest; ++tries) {
            ++proofs;
            if (fractal_.excludesSegment(ray, nearest, end)) {
                nearest = end;
                end = 0.5 * (nearest + t);
            } else {
                end = 0.5 * (nearest + end);
            }
        }
        return nearest;
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
    double footprint_;
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
