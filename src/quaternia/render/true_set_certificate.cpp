#include "quaternia/render/true_set_certificate.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <mutex>

#include "quaternia/render/march.h"
#include "quaternia/render/render.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

// The cone's first cut, before the halving of undecided pieces.
constexpr int kFirstPieces = 16;

float roundedDownFloat(double x) {
    const float f = float(x);
    return double(f) <= x ? f : std::nextafter(f, -INFINITY);
}
float roundedUpFloat(double x) {
    const float f = float(x);
    return double(f) >= x ? f : std::nextafter(f, INFINITY);
}

class TrueSetCertifier {
  public:
    TrueSetCertifier(const Fractal& fractal, const CertifiedSet& set, const Camera& camera,
                     double epsilon)
        : set_(set),
          camera_(camera),
          dimension_(algebraDimension(set.algebra)),
          footprint_(std::max(1.0, 4 * epsilon)),
          origin_(fractal.slice().fromWorld(Point3d{0, 0, 0})),
          tangents_(fractal.slice().tangents()),
          ball_(fractal.slice().boundingRadius(set.escapeRadius) * (1 + 1e-9) + 1e-12) {
        double finest = INFINITY;
        for (const CellGrid& grid : set.grids)
            for (int a = 0; a < grid.dimension(); ++a)
                finest = std::min(finest, grid.cellSize(grid.finestLevel(), a));
        // Half a finest cell in the algebra (a third for the product: the duplex map stretches
        // by up to sqrt(2)), in world units.
        minimumPiece_ = (set.space == CertifiedSpace::kProduct ? 0.33 : 0.5) * finest *
                        fractal.slice().stepScale();
    }

    void certifyPixel(int px, int py, PixelCertificate& out) const {
        const double x0 = px + 0.5 - 0.5 * footprint_, y0 = py + 0.5 - 0.5 * footprint_;
        const Ray centre = camera_.generateRay(px + 0.5, py + 0.5);
        const double slope = camera_.coneSlope(centre, x0, y0, footprint_);
        const double farthest = length(centre.origin) + ball_;
        const auto interval = intersectSphere(centre, ball_ + slope * farthest);
        const size_t at = size_t(py) * size_t(out.width) + size_t(px);
        if (!interval) {
            out.classes[at] = uint8_t(PixelClass::kMissed);
            return;
        }
        Walk walk{centre, slope};
        const double t0 = std::max(0.0, interval->tNear), t1 = interval->tFar;
        const double piece = (t1 - t0) / kFirstPieces;
        for (int n = 0; n < kFirstPieces && !walk.hit; ++n)
            visit(walk, t0 + n * piece, n + 1 == kFirstPieces ? t1 : t0 + (n + 1) * piece);
        if (walk.hit) {
            out.classes[at] = uint8_t(PixelClass::kHit);
            out.nearestHit[at] = roundedDownFloat(walk.nearest);
            out.farthestHit[at] = roundedUpFloat(walk.farthest);
        } else {
            out.classes[at] =
                uint8_t(walk.blocked || slope <= 0 ? PixelClass::kUndecided : PixelClass::kMissed);
        }
    }

  private:
    struct Walk {
        Ray ray;
        double slope;
        bool hit = false, blocked = false;  // blocked: some piece was not proven outside
        double nearest = 0, farthest = 0;
    };

    // The algebra box holding every point of `box` (3D) through the affine slice, rounding
    // included (1e-12 (1 + |q|), as Fractal's segments).
    void algebraBox(const std::array<Interval, 3>& box, Interval* out) const {
        for (int k = 0; k < dimension_; ++k) {
            Interval q = Interval::point(origin_[k]);
            for (int i = 0; i < 3; ++i)
                if (tangents_[size_t(i)][k] != 0) q = q + tangents_[size_t(i)][k] * box[size_t(i)];
            const double margin = 1e-12 * (1 + std::max(std::fabs(q.lo), std::fabs(q.hi)));
            out[k] = {roundedDown(q.lo - margin), roundedUp(q.hi + margin)};
        }
    }

    uint8_t classesOfPiece(const Walk& walk, double t0, double t1) const {
        std::array<Interval, 3> box;
        const double radius = walk.slope * t1 * (1 + 1e-9) + 1e-12;
        for (int i = 0; i < 3; ++i) {
            const double a = walk.ray.origin[i] + t0 * walk.ray.direction[i];
            const double b = walk.ray.origin[i] + t1 * walk.ray.direction[i];
            const double slack = 1e-12 * (1 + std::max(std::fabs(a), std::fabs(b)));
            box[size_t(i)] = {roundedDown(std::min(a, b) - radius - slack),
                              roundedUp(std::max(a, b) + radius + slack)};
        }
        Interval algebra[kMaxAlgebraDimension];
        algebraBox(box, algebra);
        return set_.classesOfBox(algebra, dimension_);
    }

    CellClass classOfRayPoint(const Walk& walk, double t) const {
        std::array<Interval, 3> box;
        for (int i = 0; i < 3; ++i) {
            const double p = walk.ray.origin[i] + t * walk.ray.direction[i];
            const double slack = 1e-12 * (1 + std::fabs(p));
            box[size_t(i)] = {roundedDown(p - slack), roundedUp(p + slack)};
        }
        Interval algebra[kMaxAlgebraDimension];
        algebraBox(box, algebra);
        return set_.classOfBox(algebra, dimension_);
    }

    // Front to back through [t0, t1]: stops at the first proven point of K. A piece that
    // touches no inside cell holds no provable point: it is not cut further.
    void visit(Walk& walk, double t0, double t1) const {
        const uint8_t classes = classesOfPiece(walk, t0, t1);
        if (classes == CellGrid::kHasOutside) return;
        if (!walk.blocked) walk.nearest = t0, walk.blocked = true;
        if (classes == CellGrid::kHasInside) {
            walk.hit = true, walk.farthest = t0;
            return;
        }
        if (!(classes & CellGrid::kHasInside)) return;
        if (t1 - t0 > minimumPiece_) {
            const double middle = 0.5 * (t0 + t1);
            visit(walk, t0, middle);
            if (!walk.hit) visit(walk, middle, t1);
            return;
        }
        const double middle = 0.5 * (t0 + t1);
        if (classOfRayPoint(walk, middle) == CellClass::kInside)
            walk.hit = true, walk.farthest = middle;
    }

    const CertifiedSet& set_;
    const Camera& camera_;
    int dimension_;
    double footprint_;
    Hypercomplex origin_;
    std::array<Hypercomplex, 3> tangents_;
    double ball_;
    double minimumPiece_ = 0;
};

}  // namespace

std::shared_ptr<const CertifiedSet> certifiedSetOfScene(const Scene& scene) {
    const std::string& path = scene.render.certified;
    static std::mutex mutex;
    static std::string cachedPath;
    static std::uintmax_t cachedSize = 0;
    static std::filesystem::file_time_type cachedTime;
    static std::shared_ptr<const CertifiedSet> cached;
    std::error_code error;
    const auto size = std::filesystem::file_size(path, error);
    const auto time = std::filesystem::last_write_time(path, error);
    std::shared_ptr<const CertifiedSet> loaded;
    {
        std::lock_guard<std::mutex> lock(mutex);
        if (!error && cached && cachedPath == path && cachedSize == size && cachedTime == time)
            loaded = cached;
    }
    if (!loaded) {
        loaded = std::make_shared<const CertifiedSet>(CertifiedSet::read(path, "render.certified"));
        if (!error) {
            std::lock_guard<std::mutex> lock(mutex);
            cachedPath = path, cachedSize = size, cachedTime = time, cached = loaded;
        }
    }
    const CertifiedSet& set = *loaded;
    const Hypercomplex c = cOfScene(scene);
    bool sameC = true;
    for (int k = 0; k < kMaxAlgebraDimension; ++k)
        sameC = sameC && c[k] == set.c[k];
    if (set.algebra != scene.fractal.algebra || set.formula != scene.fractal.formula || !sameC)
        throw UserError("render.certified",
                        "render.certified: " + path + " certifies " + set.formula + " in the " +
                            std::string(algebraName(set.algebra)) +
                            " algebra with another c than the scene's fractal; certify this "
                            "scene with `quaternia certify`");
    return loaded;
}

PixelCertificate certifyPixelsAgainstSet(const Fractal& fractal, const CertifiedSet& set,
                                         const Camera& camera, double epsilon,
                                         const WorkOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    PixelCertificate out = undecidedCertificate(camera.width(), camera.height());
    const TrueSetCertifier certifier(fractal, set, camera, epsilon);
    const ParallelOptions parallel = imageParallelOptions(options, out.width, out.height);
    out.completed = parallelForTiles(out.width, out.height, parallel, [&](const Tile& tile, int) {
        for (int y = tile.y0; y < tile.y1; ++y)
            for (int x = tile.x0; x < tile.x1; ++x)
                certifier.certifyPixel(x, y, out);
    });
    tallyClasses(out);
    out.threads = resolveThreadCount(parallel.threads);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

}  // namespace quaternia
