#include "quaternia/render/march.h"

#include <algorithm>
#include <cmath>

namespace quaternia {

MarchResult sphereTrace(const Fractal& fractal, const Ray& ray, const MarchSettings& settings) {
    auto interval = intersectSphere(ray, fractal.boundingRadius());
    return interval ? sphereTrace(fractal, ray, settings, *interval) : MarchResult();
}

MarchResult fixedStepMarch(const Fractal& fractal, const Ray& ray, const MarchSettings& settings) {
    auto interval = intersectSphere(ray, fractal.boundingRadius());
    return interval ? fixedStepMarch(fractal, ray, settings, *interval) : MarchResult();
}

MarchResult march(const Fractal& fractal, const Ray& ray, const MarchSettings& settings) {
    return settings.method == MarchMethod::FixedStep ? fixedStepMarch(fractal, ray, settings)
                                                     : sphereTrace(fractal, ray, settings);
}

MarchResult march(const Fractal& fractal, const Ray& ray, const MarchSettings& settings,
                  const RayInterval& interval) {
    return settings.method == MarchMethod::FixedStep
               ? fixedStepMarch(fractal, ray, settings, interval)
               : sphereTrace(fractal, ray, settings, interval);
}

MarchResult sphereTrace(const Fractal& fractal, const Ray& ray, const MarchSettings& settings,
                        const RayInterval& interval) {
    // Steps are over-relaxed (settings.relaxation, relaxedMarchStep in march.h) and checked
    // against the plain step.
    // Once the estimate is below epsilon the ray is within about two epsilons of K_N (the
    // estimate is at least half the true distance near the set). Rather than stop on that offset
    // surface, which fattens dust and thin filaments, confirm: keep stepping by the estimate but
    // at least kMarchConfirmStep footprints, testing membership, until a point is inside (the hit),
    // the estimate grows past epsilon again (a near miss: march on), or kMarchConfirmBudget steps
    // pass (a grazing ray: take the offset surface after all).
    MarchResult result;
    double t = interval.tNear;
    double tOutside = t;
    double radius = 0;       // the estimate at tOutside
    double plainStep = 0;    // the plain step from tOutside
    double relaxedStep = 0;  // the step taken from tOutside where it was longer, else 0
    int confirming = 0;
    while (t <= interval.tFar && result.steps < settings.maxSteps) {
        Point3d p = ray.at(t);
        DistanceEstimate e = fractal.estimate(p);
        ++result.steps;
        result.iterations += e.iterations;
        result.closest = std::min(result.closest, e.distance);
        if (relaxedStep > plainStep + e.distance) {
            // This ball does not reach back to the plain step's end: take the plain step.
            t = tOutside + plainStep;
            relaxedStep = 0;
            continue;
        }
        if (e.inside) {
            Point3d outside = ray.at(tOutside);
            result.hit = Hit{t, p, outside, fractal.estimate(outside), tOutside};
            return result;
        }
        double footprint = settings.pixelAngle * t;
        if (e.distance >= settings.epsilon * footprint) {
            confirming = 0;
        } else if (++confirming > kMarchConfirmBudget) {
            result.hit = Hit{t, p, p, e, t};
            return result;
        }
        const double plain =
            confirming ? std::max(e.distance, kMarchConfirmStep * footprint) : e.distance;
        const double relaxed =
            relaxedMarchStep(settings.relaxation, t, tOutside, radius, e.distance);
        relaxedStep = relaxed > plain && relaxed + t <= interval.tFar ? relaxed : 0;
        tOutside = t;
        radius = e.distance;
        plainStep = plain;
        t += relaxedStep > 0 ? relaxedStep : plain;
    }
    return result;
}

MarchResult fixedStepMarch(const Fractal& fractal, const Ray& ray, const MarchSettings& settings,
                           const RayInterval& interval) {
    MarchResult result;
    double tOutside = interval.tNear;
    // Where the fractal's distance is a proven lower bound (DistanceKind::kLipschitz), a sample
    // outside skips ahead by that distance when it exceeds the step: nothing lies within it.
    const bool skip = fractal.distanceKind() == DistanceKind::kLipschitz;
    for (double t = interval.tNear, advance = settings.step;
         t <= interval.tFar && result.steps < settings.maxSteps; t += advance) {
        ++result.steps;
        bool inside;
        if (skip) {
            const DistanceEstimate e = fractal.estimate(ray.at(t));
            result.iterations += e.iterations;
            inside = e.inside;
            result.closest = std::min(result.closest, e.distance);
            advance = std::max(settings.step, e.distance);
        } else {
            inside = fractal.contains(ray.at(t));
        }
        if (!inside) {
            tOutside = t;
            continue;
        }
        // Bisect between the last outside and the first inside sample to a thousandth of the
        // step, so that depth and normals do not show the sampling grid.
        double tInside = t;
        for (int k = 0; k < 10 && tInside > tOutside; ++k) {
            double middle = 0.5 * (tOutside + tInside);
            ++result.steps;
            (fractal.contains(ray.at(middle)) ? tInside : tOutside) = middle;
        }
        Point3d outside = ray.at(tOutside);
        result.hit = Hit{tInside, ray.at(tInside), outside, fractal.estimate(outside), tOutside};
        return result;
    }
    return result;
}

}  // namespace quaternia
