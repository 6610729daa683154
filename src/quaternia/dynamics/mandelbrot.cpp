#include "quaternia/dynamics/mandelbrot.h"

#include <algorithm>
#include <cmath>

#include "quaternia/fractal/distance.h"

namespace quaternia {
namespace {

using Complex = std::complex<double>;

// |z| at which an escaped orbit stops, as the 3D estimate's continuation (distance.h): large
// enough for the smooth count and the estimate to be accurate, small enough that z^d cannot
// overflow.
constexpr double kEstimateRadiusSquared = 1e8;

Complex power(Complex z, int degree) {
    Complex result = z;
    for (int k = 1; k < degree; ++k)
        result *= z;
    return result;
}

}  // namespace

MandelbrotEstimate estimateMandelbrot(Complex c, int maxIterations, int degree) {
    MandelbrotEstimate result;
    const double escapeRadius = std::max(2.0, std::abs(c));
    const double escapeSquared = escapeRadius * escapeRadius;
    Complex z = 0, dz = 0;  // z_n and dz_n / dc
    int n = 0;
    double r2 = 0;
    while (r2 <= escapeSquared) {
        if (n >= maxIterations) {
            result.inside = true;
            result.escapeIteration = maxIterations;
            result.smoothIteration = maxIterations;
            return result;
        }
        dz = double(degree) * power(z, degree - 1) * dz + 1.0;  // before z moves on
        z = power(z, degree) + c;
        r2 = std::norm(z);
        ++n;
    }
    result.escapeIteration = n;
    int extra = 0;
    for (; r2 < kEstimateRadiusSquared && extra < kMaxContinuation; ++extra) {
        dz = double(degree) * power(z, degree - 1) * dz + 1.0;
        z = power(z, degree) + c;
        r2 = std::norm(z);
    }
    result.smoothIteration = smoothEscapeCount(n + extra, r2, degree);
    // 0.5 |z| ln|z| / |z'| = 0.25 sqrt(|z|^2 / |z'|^2) ln |z|^2.
    double dz2 = std::norm(dz);
    result.distance = dz2 > 0 ? std::max(0.0, 0.25 * std::sqrt(r2 / dz2) * std::log(r2)) : 0;
    return result;
}

bool inMandelbrotSet(Complex c, int maxIterations, int degree) {
    return estimateMandelbrot(c, maxIterations, degree).inside;
}

bool inQuaternionMandelbrotSet(const Quaternion& c, int maxIterations) {
    const double escapeSquared = std::max(4.0, normSquared(c));
    Quaternion z;
    for (int n = 0; n < maxIterations; ++n) {
        z = square(z) + c;
        if (normSquared(z) > escapeSquared) return false;
    }
    return true;
}

}  // namespace quaternia
