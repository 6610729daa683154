// The escape-time distance estimate shared by the quaternion Julia sets (distance.cpp) and the
// octonions (hypercomplex_julia.cpp): one loop for every element type and map.
#pragma once

#include <algorithm>
#include <cmath>

#include "quaternia/algebra/hypercomplex.h"
#include "quaternia/algebra/quaternion.h"
#include "quaternia/fractal/distance.h"

namespace quaternia {

// The limits of an escape-time estimate: N, the bailout and certified escape radius squared, the
// degree (for the smooth count) and where the continuation stops.
struct IterationLimits {
    int maxIterations;
    double bailoutSquared;
    double escapeRadiusSquared;
    int degree;
    double estimateRadiusSquared;
};

// The estimate 0.5 |z_n| ln|z_n| / |z'_n| of distance.h for any element type with normSquared
// (Quaternion, Hypercomplex) and any map with operator() and gainSquared(r2), the squared factor
// by which the running derivative bound grows at |z|^2 = r2; escape beyond the certified radius
// is final, so the orbit is followed on to where the estimate is accurate.
template <typename Map, typename Z>
DistanceEstimate estimateWith(const Map& map, const IterationLimits& limits, const Z& z0) {
    DistanceEstimate result;
    Z z = z0;
    double derivativeSquared = 1;
    double r2 = normSquared(z);
    double trap2 = r2;
    int n = 0;  // z = z_n; the iterates z_0 .. z_{N-1} are tested
    while (r2 <= limits.bailoutSquared) {
        if (n + 1 >= limits.maxIterations)
            return insideEstimate(std::sqrt(trap2), limits.maxIterations);
        derivativeSquared *= map.gainSquared(r2);
        z = map(z);
        r2 = normSquared(z);
        trap2 = std::min(trap2, r2);
        ++n;
    }
    result.trap = std::sqrt(trap2);
    result.escapeIteration = n;
    // Escape beyond the certified radius is final, so iterating on cannot change membership;
    // it takes the estimate where it is accurate.
    int extra = 0;
    if (r2 > limits.escapeRadiusSquared) {
        for (; r2 < limits.estimateRadiusSquared && extra < kMaxContinuation; ++extra) {
            derivativeSquared *= map.gainSquared(r2);
            z = map(z);
            r2 = normSquared(z);
        }
    }
    result.iterations = n + extra;
    if (r2 <= limits.escapeRadiusSquared) {
        result.distance = uncertainEscapeDistance(r2, limits.bailoutSquared, derivativeSquared);
    } else {
        // d = 0.5 |z| ln|z| / |z'| = 0.25 sqrt(|z|^2 / |z'|^2) ln |z|^2.
        result.distance = std::max(0.0, 0.25 * std::sqrt(r2 / derivativeSquared) * std::log(r2));
    }
    result.smoothIteration = smoothEscapeCount(n + extra, r2, limits.degree);
    return result;
}

}  // namespace quaternia
