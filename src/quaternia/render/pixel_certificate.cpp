#include "quaternia/render/pixel_certificate.h"
#include "quaternia/render/true_set_certificate.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include "quaternia/image/png_writer.h"
#include "quaternia/render/march.h"
#include "quaternia/render/proven_cones.h"
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
// apart: first from where the pixel's block stopped (most hits lie within a few footprints of
// it; a miss costs these samples before its tube), then from where the central ray alone stops
// being provable.
constexpr int kFirstHitSamples = 1024, kHitSamples = 256;
// Samples tried from just before where the renderer's march stops.
constexpr int kHitsPastMarch = 16;
// Segments of the central ray tried for the near end of a hit's depth interval.
constexpr int kNearTries = 8;
// Halvings of a pixel's footprint square where its cone is not proven whole: its quarters'
// cones (measured at 640x360: the default scene's undecided pixels 1.67% -> 1.03% for 1.2x the
// time; a second halving 0.67% for 1.5x, the bicomplex preset's 4.3% -> 2.5% for 1.8x).
constexpr int kFootprintSplits = 1;
// The quarters prove a window of this many units past where their square's cone stopped, and
// the square's cone goes on from there (far past the set it is proven as cheaply as theirs),
// at most this many times.
constexpr double kQuarterWindow = 64;
constexpr int kQuarterWindows = 8;

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
          ball_(fractal.boundingRadius() * (1 + 1e-9) + 1e-12) {
        march_.epsilon = epsilon;
        march_.pixelAngle = camera.pixelFootprint(1);
    }

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

    // The cone of a square's rays about its central ray (Camera::coneSlope; 0: none).
    double coneSlope(const Ray& centre, const Square& square) const {
        return camera_.coneSlope(centre, square.x0, square.y0, square.size);
    }

    // The runs of proven_cones.h's proveCone, in units of unit_.
    double clearTube(const Ray& ray, double t, double tFar, double slope, int64_t shortest,
                     int64_t span, int64_t& proofs) const {
        ProofRuns runs{span};
        return proveCone(fractal_, ray, t, tFar, unit_, slope, shortest, runs, proofs);
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
        const Ray centre =
            camera_.generateRay(square.x0 + 0.5 * square.size, square.y0 + 0.5 * square.size);
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

    // Whether every ray of the square is proven outside K_N from `from` to `to` (or to where
    // its cone leaves the ball): by the square's own cone, and where that stops short, by its
    // quarters' (down to `splits` halvings: a tube half as wide is proven much nearer the set)
    // across a window of kQuarterWindow units, after which the square's own cone goes on.
    bool clearSquare(const Square& square, double from, double to, int splits,
                     int64_t& proofs) const {
        const Ray centre =
            camera_.generateRay(square.x0 + 0.5 * square.size, square.y0 + 0.5 * square.size);
        const double slope = coneSlope(centre, square);
        if (!(slope > 0)) return false;
        const auto interval = ballInterval(centre, slope);
        if (!interval) return true;
        const double end = std::min(to, interval->tFar);
        double t = std::max(from, interval->tNear);
        for (int window = 0; window <= kQuarterWindows; ++window) {
            t = clearTube(centre, t, end, slope, 1, kSpanAfterCone, proofs);
            if (!(t < end)) return true;
            if (splits == 0 || window == kQuarterWindows) return false;
            const double half = 0.5 * square.size;
            const double next = std::min(t + kQuarterWindow * unit_, end);
            for (int quarter = 0; quarter < 4; ++quarter)
                if (!clearSquare(
                        {square.x0 + (quarter & 1) * half, square.y0 + (quarter >> 1) * half, half},
                        t, next, splits - 1, proofs))
                    return false;
            t = next;
        }
        return false;
    }

    // A pixel whose rays are proven outside K_N up to `from`. A hit is looked for first along
    // the central ray (it needs no tube near the surface, where tubes are dearest); then the
    // miss is proven by the footprint's cone; where that stops short (at a part of the set
    // that the central ray may pass by) the ray alone is proven on and looked along again.
    void settlePixel(int px, int py, double from, PixelCertificate& out, int64_t& proofs) const {
        const Ray ray = camera_.generateRay(px + 0.5, py + 0.5);
        const auto interval = intersectSphere(ray, ball_);
        const double start = interval ? std::max(from, interval->tNear) : from;
        if (interval && findFirstHit(px, py, ray, start, interval->tFar, out, proofs)) return;
        if (clearSquare(footprints(px, py, 1), from, HUGE_VAL, kFootprintSplits, proofs)) {
            record(px, py, PixelClass::kMissed, 0, 0, out);
            return;
        }
        if (interval) {
            const double alone =
                clearTube(ray, start, interval->tFar, 0, 1, kSpanAfterCone, proofs);
            if (alone > start &&
                findHit(px, py, ray, alone, alone, interval->tFar, kHitSamples, out, proofs))
                return;
        }
        record(px, py, PixelClass::kUndecided, 0, 0, out);
    }

    // A hit where the renderer's own march finds one (sets with a distance estimate: a few
    // dozen estimates, where samples would take hundreds), else at the first sample in K_N.
    // The march only proposes: its point, or one a little deeper, is proven in K_N.
    bool findFirstHit(int px, int py, const Ray& ray, double from, double tFar,
                      PixelCertificate& out, int64_t& proofs) const {
        if (fractal_.distanceKind() != DistanceKind::kEstimate)
            return findHit(px, py, ray, from, from, tFar, kFirstHitSamples, out, proofs);
        const MarchResult march = sphereTrace(fractal_, ray, march_, RayInterval{from, tFar});
        if (!march.hit) return false;
        return findHit(px, py, ray, from, std::max(from, march.hit->t - unit_), tFar,
                       kHitsPastMarch, out, proofs);
    }

    // The first sample of the central ray in K_N (floating point) from `from` on, whose box of
    // rounding is then proven in K_N: recorded as a hit, with the depth interval's near end
    // (the ray being proven outside K_N up to `proven`).
    bool findHit(int px, int py, const Ray& ray, double proven, double from, double tFar,
                 int samples, PixelCertificate& out, int64_t& proofs) const {
        for (int k = 0; k < samples; ++k) {
            const double t = from + k * unit_;
            if (t > tFar) break;
            const Point3d p = ray.at(t);
            if (!fractal_.contains(p)) continue;
            ++proofs;
            if (!fractal_.includesPoint(p)) continue;
            record(px, py, PixelClass::kHit, nearEnd(ray, proven, t, proofs), t, out);
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
    MarchSettings march_;  // the renderer's sphere tracing, proposing hits
    double unit_;
    double ball_;
};

}  // namespace

namespace {

// validateCertificate for the scene's fractal, made once by the caller.
void requirePinhole(const Scene& scene) {
    if (scene.camera.aperture > 0) {
        throw UserError("camera.aperture",
                        "camera.aperture must be 0 for a certificate: a thin lens's rays share "
                        "no pinhole for the footprint cones");
    }
}

void validateCertificateOf(const Scene& scene, const Fractal& fractal) {
    if (auto part = fractal.unprovablePart()) {
        throw UserError("fractal.formula",
                        "fractal.formula: " + *part +
                            " has no interval extension yet, so no pixel can be certified");
    }
    requirePinhole(scene);
}

}  // namespace

void validateCertificate(const Scene& scene) {
    if (!scene.render.certified.empty()) {
        requirePinhole(scene);
        certifiedSetOfScene(scene);
        return;
    }
    validateCertificateOf(scene, fractalFromScene(scene));
}

PixelCertificate certifyPixels(const Scene& scene, const WorkOptions& options) {
    validateScene(scene);
    if (!scene.render.certified.empty()) {
        // Against K itself (true_set_certificate.h), through the slice of the algebra's own set.
        requirePinhole(scene);
        const auto set = certifiedSetOfScene(scene);
        const Fractal fractal = hypercomplexFractalFromScene(scene);
        const Camera camera(scene.camera, scene.render.width, scene.render.height);
        return certifyPixelsAgainstSet(fractal, *set, camera, scene.render.epsilon, options);
    }
    const Fractal fractal = fractalFromScene(scene);
    validateCertificateOf(scene, fractal);
    const Camera camera(scene.camera, scene.render.width, scene.render.height);
    return certifyPixels(fractal, camera, scene.render.epsilon, options);
}

PixelCertificate certifyPixels(const Fractal& fractal, const Camera& camera, double epsilon,
                               const WorkOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    PixelCertificate out = undecidedCertificate(camera.width(), camera.height());
    const Certifier certifier(fractal, camera, epsilon);
    const ParallelOptions parallel = imageParallelOptions(options, out.width, out.height);
    std::vector<int64_t> proofs(size_t(resolveThreadCount(parallel.threads)), 0);
    out.completed =
        parallelForTiles(out.width, out.height, parallel, [&](const Tile& tile, int thread) {
            certifier.certifyTile(tile, out, proofs[size_t(thread)]);
        });
    for (int64_t p : proofs)
        out.proofs += p;
    tallyClasses(out);
    out.threads = resolveThreadCount(parallel.threads);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

PixelCertificate undecidedCertificate(int width, int height) {
    PixelCertificate out;
    out.width = width;
    out.height = height;
    const size_t pixels = size_t(width) * size_t(height);
    out.classes.assign(pixels, uint8_t(PixelClass::kUndecided));
    out.nearestHit.assign(pixels, PixelCertificate::kNoDepth);
    out.farthestHit.assign(pixels, PixelCertificate::kNoDepth);
    return out;
}

void tallyClasses(PixelCertificate& certificate) {
    certificate.counts = {};
    for (uint8_t c : certificate.classes) {
        if (c == uint8_t(PixelClass::kMissed))
            ++certificate.counts.missed;
        else if (c == uint8_t(PixelClass::kHit))
            ++certificate.counts.hit;
        else
            ++certificate.counts.undecided;
    }
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
