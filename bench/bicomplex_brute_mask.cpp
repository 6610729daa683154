#include "bicomplex_brute_mask.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>

#include "quaternia/util/parallel.h"

namespace quaternia::bench {
namespace {

using Complex = std::complex<double>;

// POV-Ray's membership test of a 3D point (Iteration_HCompl: z_0 .. z_{N-1} tested).
class BicomplexSet {
  public:
    explicit BicomplexSet(const BicomplexBrute& o)
        : power_(o.power), iterations_(o.iterations), bailoutSquared_(o.bailout * o.bailout) {
        const double norm = std::sqrt(o.slice[0] * o.slice[0] + o.slice[1] * o.slice[1] +
                                      o.slice[2] * o.slice[2] + o.slice[3] * o.slice[3]);
        if (!(norm > 0) || o.slice[3] == 0)
            throw std::invalid_argument("slice: the normal's w must not be 0");
        for (int k = 0; k < 4; ++k)
            normal_[k] = o.slice[k] / norm;
        distance_ = o.slice[4];
        ca_ = Complex(o.c[0] - o.c[3], o.c[1] + o.c[2]);
        cb_ = Complex(o.c[0] + o.c[3], o.c[1] - o.c[2]);
    }

    bool contains(const Point3d& p) const {
        const double w =
            (distance_ - normal_[0] * p.x - normal_[1] * p.y - normal_[2] * p.z) / normal_[3];
        Complex a(p.x - w, p.y + p.z), b(p.x + w, p.y - p.z);
        for (int n = 0; n < iterations_; ++n) {
            if (0.5 * (std::norm(a) + std::norm(b)) > bailoutSquared_) return false;
            a = raise(a) + ca_;
            b = raise(b) + cb_;
        }
        return true;
    }

  private:
    Complex raise(const Complex& z) const {
        Complex result = z;
        for (int k = 1; k < power_; ++k)
            result *= z;
        return result;
    }

    int power_, iterations_;
    double bailoutSquared_;
    double normal_[4], distance_;
    Complex ca_, cb_;
};

// Samples t0, t0 + step, ... up to t1 where the ray is inside the sphere |p| <= radius.
bool rayHits(const Ray& ray, const BicomplexSet& set, double radius, double step) {
    const double b = dot(ray.origin, ray.direction);
    const double c = dot(ray.origin, ray.origin) - radius * radius;
    const double discriminant = b * b - c;
    if (discriminant < 0) return false;
    const double root = std::sqrt(discriminant);
    const double t0 = std::max(0.0, -b - root), t1 = -b + root;
    for (long k = 0;; ++k) {
        const double t = t0 + double(k) * step;
        if (t > t1) return false;
        if (set.contains(ray.at(t))) return true;
    }
}

}  // namespace

std::vector<uint8_t> bicomplexBruteMask(const BicomplexBrute& o, const Camera& camera, int width,
                                        int height, int threads) {
    const BicomplexSet set(o);
    std::vector<uint8_t> samples(size_t(width) * size_t(height), 0);
    ParallelOptions parallel;
    parallel.threads = threads;
    parallel.chunkSize = 1;
    parallelFor(height, parallel, [&](int64_t begin, int64_t end, int) {
        for (int64_t y = begin; y < end; ++y)
            for (int x = 0; x < width; ++x) {
                const Ray ray = camera.generateRay(x + 0.5, double(y) + 0.5);
                if (rayHits(ray, set, o.radius, o.step))
                    samples[size_t(y) * size_t(width) + size_t(x)] = 255;
            }
    });
    return samples;
}

}  // namespace quaternia::bench
