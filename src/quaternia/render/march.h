// Finding where a ray first meets the object, two ways:
// - fixedStepMarch: the seed paper's Algorithm 2, the reference. Samples at a fixed step delta
//   inside the bounding sphere, each tested for membership by iteration; the first inside
//   sample is refined by bisection against the last outside one.
// - sphereTrace: the fast path. Steps by the distance estimate, which cannot cross the set, from
//   the bounding sphere (the estimate overshoots far away, distance.h) until it falls below
//   epsilon times the pixel footprint at t, then confirms membership with steps of a fifth of
//   a footprint: the drawn surface is K_N's own (its epsilon-offset only for grazing rays),
//   and no feature wider than a pixel is skipped.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>

#include "quaternia/algebra/vecmath.h"
#include "quaternia/fractal/fractal.h"
#include "quaternia/render/lanes/march_rules.h"
#include "quaternia/scene/scene.h"

namespace quaternia {

struct RayInterval {
    double tNear, tFar;
};
// Where the ray is inside the ball of the given radius about the origin, for t >= 0.
inline std::optional<RayInterval> intersectSphere(const Ray& ray, double radius) {
    // |o + t d|^2 = r^2 with |d| = 1: t^2 + 2 b t + c = 0.
    double b = dot(ray.origin, ray.direction);
    double c = dot(ray.origin, ray.origin) - radius * radius;
    double discriminant = b * b - c;
    if (discriminant < 0) return std::nullopt;
    double root = std::sqrt(discriminant);
    double tFar = -b + root;
    if (tFar < 0) return std::nullopt;
    return RayInterval{std::max(0.0, -b - root), tFar};
}

// kMarchConfirmStep and kMarchConfirmBudget: render/lanes/march_rules.h.

// Over-relaxed steps before confirmation (after Keinert et al. 2014, "Enhanced sphere tracing",
// with the factor of Balint and Valasek 2018): along a ray the estimate falls almost linearly
// towards the surface, at a slope (radius - distance) / step seen between consecutive points;
// if the surface were a plane at that slope, a step of 2 / (1 + slope) estimates would just
// keep the two balls touching. kMarchRelaxation (< 2) leaves a margin. Where the far point's
// ball does not reach back to the end of the plain step (the estimate, or in confirmation at
// least kMarchConfirmStep footprints), the set may lie between them: the march drops the far
// point and takes the plain step instead, so it crosses nothing that plain steps would not.
// The length of the step from a point at t whose
// estimate is `distance`, the point before being at tPrevious with estimate `radius`:
inline constexpr double kMarchRelaxation = 1.8;  // the default of render.relaxation
inline double relaxedMarchStep(double relaxation, double t, double tPrevious, double radius,
                               double distance) {
    if (!(t > tPrevious && radius > 0)) return distance;
    const double slope = std::max(0.0, (radius - distance) / (t - tPrevious));
    return std::max(1.0, relaxation / (1.0 + slope)) * distance;
}

struct MarchSettings {
    MarchMethod method = MarchMethod::SphereTracing;
    double step = 0.002;       // fixed-step delta
    double epsilon = 0.25;     // in pixel footprints
    double pixelAngle = 1e-3;  // footprint per unit of t: Camera::pixelFootprint(1)
    int maxSteps = 5000;
    double relaxation = kMarchRelaxation;  // 1: plain sphere tracing
};

struct Hit {
    double t = 0;
    Point3d position;
    // The last point known to be outside K_N (the hit itself for sphere tracing): where the
    // potential is defined and normals are taken.
    Point3d outside;
    DistanceEstimate estimate;
    double tOutside = 0;  // where `outside` lies along the ray
};

struct MarchResult {
    std::optional<Hit> hit;
    int steps = 0;           // distance estimates or membership tests
    int64_t iterations = 0;  // polynomial evaluations
    // The least distance estimate met on the way, at most 1 (the glow's; Lipschitz bounds where
    // the fixed steps take them, else 1).
    double closest = 1;
};

// Algorithm 2's samples t_k = tStart + k step (k = 0, 1, ... while t_k <= tEnd) along a ray
// through a set whose membership is all that is known (DistanceKind::kLipschitz), each tested
// for membership, the first inside one found. Where the set proves empty boxes
// (Fractal::provesEmptySegments: every formula but the bicomplex functions without a form,
// interval/function_forms.h, and real powers) runs of samples are
// crossed at once where Fractal::excludesSegment proves the segment that holds them outside K_N,
// the runs doubled after two proofs in a row (from kFirstSpan up to kLongestSpan samples) and
// halved after each failure; a run of kTestedSpan samples or fewer is not proven but its
// samples tested together (Fractal::firstInsideSample: the orbits in lanes, algebra/
// orbit_batch.h), which costs less than a proof there and never fails. The samples tested are
// the same, only those proven outside are skipped, so the first inside sample is the one plain
// fixed steps would find (Marching.ProvenRunsFindThePlainStepsSample).
// Elsewhere a sample skips ahead by the set's proven distance (its Lipschitz bound) where it is
// longer than the step.
struct SampleCrossing {
    std::optional<double> tInside;  // the first sample in K_N
    double tOutside = 0;            // the sample before it (tStart where it is the first)
    int steps = 0;                  // membership tests and segments tested
    int64_t iterations = 0;         // polynomial evaluations where counted (the distance bounds)
    double closest = 1;             // the least distance bound met (where they are taken)
};
inline constexpr int64_t kFirstSpan = 64, kLongestSpan = 1024;
// Runs this short are tested sample by sample rather than proven: a proof of a run costs about
// as much as 16 orbits in the lanes (coquaternion z^2 + c), and fails near the surface.
// Measured on the default coquaternion scene at 480x270: 8 to 32 samples within 3% of each
// other, 64 9% slower (docs/benchmarks.md, "Samples tested in lanes, squares by symmetry").
inline constexpr int64_t kTestedSpan = 16;
// The length of the next run to prove, in samples: doubled after two proofs in a row, up to
// kLongestSpan, and halved after a failure (a ray's runs here, a block's cone's in
// proven_cones.h).
struct ProofRuns {
    int64_t span = kFirstSpan;
    int proofs = 0;  // in a row at this span
    void proved() {
        if (++proofs == 2) {
            span = std::min(2 * span, kLongestSpan);
            proofs = 0;
        }
    }
    void failed() {
        proofs = 0;
        span /= 2;
    }
};
// The first runs of a ray past its cone's proof, where the set is near.
inline constexpr int64_t kSpanAfterCone = 8;
// Samples at or before `provenUntil` are known outside K_N (ProvenCones, proven_cones.h): the
// crossing starts after them, its runs at `firstSpan` samples.
SampleCrossing firstSampleInside(const Fractal& fractal, const Ray& ray, double tStart, double tEnd,
                                 double step, int maxSteps, double provenUntil = 0,
                                 int64_t firstSpan = kFirstSpan);

// The ray from where it enters the set's bounding sphere to where it leaves it.
MarchResult sphereTrace(const Fractal& fractal, const Ray& ray, const MarchSettings& settings);
MarchResult fixedStepMarch(const Fractal& fractal, const Ray& ray, const MarchSettings& settings);
// The method named in the settings.
MarchResult march(const Fractal& fractal, const Ray& ray, const MarchSettings& settings);
// The same over the part `interval` of the ray (the paths' rays: cut short by the ground, or
// started where a path has come to, path_waves.h).
MarchResult sphereTrace(const Fractal& fractal, const Ray& ray, const MarchSettings& settings,
                        const RayInterval& interval);
MarchResult fixedStepMarch(const Fractal& fractal, const Ray& ray, const MarchSettings& settings,
                           const RayInterval& interval, double provenUntil = 0);
// Fixed steps of a ray whose samples up to `provenUntil` are known outside K_N (firstSampleInside).
MarchResult fixedStepMarch(const Fractal& fractal, const Ray& ray, const MarchSettings& settings,
                           double provenUntil);
MarchResult march(const Fractal& fractal, const Ray& ray, const MarchSettings& settings,
                  const RayInterval& interval);

}  // namespace quaternia
