#include "quaternia/render/march.h"

#include <algorithm>
#include <cmath>
#include <limits>

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

SampleCrossing firstSampleInside(const Fractal& fractal, const Ray& ray, double tStart, double tEnd,
                                 double step, int maxSteps, double provenUntil, int64_t firstSpan) {
    SampleCrossing crossing;
    crossing.tOutside = tStart;
    if (fractal.provesEmptySegments()) {
        // Samples by index, so that a run crossed at once lands on the same grid.
        const double samples = std::floor((tEnd - tStart) / step);
        if (!(samples >= 0)) return crossing;
        const int64_t last = int64_t(std::min(samples, 1e15));
        auto at = [&](int64_t k) { return tStart + double(k) * step; };
        int64_t first = 0;  // the first sample not known outside
        if (provenUntil >= at(0)) {
            first = int64_t(std::min(std::floor((provenUntil - tStart) / step), double(last)));
            while (first > 0 && !(at(first) <= provenUntil))
                --first;
            crossing.tOutside = at(first);
            ++first;
        }
        ProofRuns runs{std::clamp<int64_t>(firstSpan, 1, kLongestSpan)};
        const bool clearance = fractal.hasClearance();
        const double along = length(ray.direction) * step;
        for (int64_t k = first; k <= last && crossing.steps < maxSteps;) {
            ++crossing.steps;
            if (clearance) {
                // A proven clearance d at a sample rules out every sample less than d ahead
                // (k + m with m along < d); membership only where d is 0.
                const Point3d p = ray.at(at(k));
                if (const double d = fractal.clearance(p); d > 0) {
                    const double ahead = std::ceil(d / along * (1 - 1e-12)) - 1;
                    k = std::min(k + int64_t(std::clamp(ahead, 0.0, 1e15)), last);
                } else if (fractal.contains(p)) {
                    crossing.tInside = at(k);
                    return crossing;
                }
                crossing.tOutside = at(k);
                ++k;
                continue;
            }
            const int64_t end = std::min(k + runs.span - 1, last);
            if (runs.span > kTestedSpan) {
                if (fractal.excludesSegment(ray, at(k), at(end))) {
                    crossing.tOutside = at(end);
                    k = end + 1;
                    runs.proved();
                } else {
                    runs.failed();
                }
                continue;
            }
            // A short run's samples, tested together (Fractal::firstInsideSample), cost less
            // than a proof that may fail; past them the runs lengthen as after a proof.
            const int64_t inside = fractal.firstInsideSample(ray, tStart, step, k, end);
            if (inside <= end) {
                crossing.tInside = at(inside);
                if (inside > k) crossing.tOutside = at(inside - 1);
                return crossing;
            }
            crossing.tOutside = at(end);
            k = end + 1;
            runs.proved();
        }
        return crossing;
    }
    const bool skip = fractal.distanceKind() == DistanceKind::kLipschitz;
    for (double t = tStart, advance = step; t <= tEnd && crossing.steps < maxSteps; t += advance) {
        ++crossing.steps;
        bool inside;
        if (skip) {
            const DistanceEstimate e = fractal.estimate(ray.at(t));
            crossing.iterations += e.iterations;
            inside = e.inside;
            crossing.closest = std::min(crossing.closest, e.distance);
            advance = std::max(step, e.distance);
        } else {
            inside = fractal.contains(ray.at(t));
        }
        if (inside) {
            crossing.tInside = t;
            return crossing;
        }
        crossing.tOutside = t;
    }
    return crossing;
}

MarchResult fixedStepMarch(const Fractal& fractal, const Ray& ray, const MarchSettings& settings,
                           double provenUntil) {
    if (!(provenUntil > 0)) return fixedStepMarch(fractal, ray, settings);
    if (provenUntil == std::numeric_limits<double>::infinity()) return MarchResult();
    auto interval = intersectSphere(ray, fractal.boundingRadius());
    return interval ? fixedStepMarch(fractal, ray, settings, *interval, provenUntil)
                    : MarchResult();
}

MarchResult fixedStepMarch(const Fractal& fractal, const Ray& ray, const MarchSettings& settings,
                           const RayInterval& interval, double provenUntil) {
    MarchResult result;
    // Past a cone's proof (proven_cones.h) the set is near: short runs first.
    const SampleCrossing crossing = firstSampleInside(
        fractal, ray, interval.tNear, interval.tFar, settings.step, settings.maxSteps, provenUntil,
        provenUntil > 0 ? kSpanAfterCone : kFirstSpan);
    result.steps = crossing.steps;
    result.iterations = crossing.iterations;
    result.closest = crossing.closest;
    if (!crossing.tInside) return result;
    // Bisect between the last outside and the first inside sample to a thousandth of the
    // step, so that depth and normals do not show the sampling grid.
    double tOutside = crossing.tOutside, tInside = *crossing.tInside;
    for (int k = 0; k < 10 && tInside > tOutside; ++k) {
        double middle = 0.5 * (tOutside + tInside);
        ++result.steps;
        (fractal.contains(ray.at(middle)) ? tInside : tOutside) = middle;
    }
    Point3d outside = ray.at(tOutside);
    result.hit = Hit{tInside, ray.at(tInside), outside, fractal.estimate(outside), tOutside};
    return result;
}

}  // namespace quaternia
