// The SIMD path of the renderer: the distance estimate, the marchers, the analytic normal and the
// estimates of shading, run on many rays or points at once in SIMD lanes (Highway, with runtime
// dispatch to SSE4, AVX2 or AVX-512, whichever the CPU has). Each lane follows its own ray; a
// lane whose ray has finished takes the next ray of the batch at once, so lanes stay busy until
// the batch runs dry. The arithmetic is the scalar reference's (distance.cpp, march.cpp, one
// formula in julia_steps-inl.h), in float or double lanes.
//
// Every eq. 2.10 polynomial takes this path: s z^d + c (d <= kMaxLaneDegree) by its own loops
// (z^2 + c specialised), any other as its compiled program (algebra/formula_program.h) with the
// scalar reference's running bound of the derivative (docs/methods.md, Distance estimate).
#pragma once

#include <array>
#include <complex>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "quaternia/algebra/vecmath.h"
#include "quaternia/fractal/fractal.h"
#include "quaternia/scene/scene.h"

namespace quaternia {

// Where the points the lanes take live: in the slice's 3D space (the renderer's rays), or in the
// algebra itself (points of H, or of a 4-component algebra, as x, y, z and w).
enum class LaneCoordinates { World, Algebra };

// A Fractal flattened for the lanes: the slice as an affine map p -> origin + x axes[0] +
// y axes[1] + z axes[2] (+ w axes[3] for points with a fourth coordinate, PointBatch::w) of R^3
// (R^4) into H, and the polynomial: the power form s z^d + c, or else
// its program.
struct LaneFractal {
    std::array<double, 4> origin{};
    // axes[3] is zero on a slice; LaneCoordinates::Algebra makes the map the identity of R^4.
    std::array<std::array<double, 4>, 4> axes{};
    std::array<double, 4> c{};
    double scale = 1;
    int degree = 2;  // of the polynomial, either form
    // The general form (null for s z^d + c): p's program, and the coefficients of P'(r), lowest
    // degree first, whose value at |z| bounds the derivative's gain (Polynomial::
    // derivativeNormBound).
    std::shared_ptr<const FormulaProgram> program;
    std::vector<double> derivativeBound;
    // Where every coefficient but c is real (Polynomial::realForm; power forms too): the a_k of
    // sum a_k z^k + c, c in `c`. Empty otherwise.
    std::vector<double> realCoefficients;
    // A real form's program with c made complex, for withComplexConstant() (null otherwise).
    std::shared_ptr<const FormulaProgram> complexConstantProgram;
    // A single quadratic term p0 z p1 z p2 + c: the lanes iterate its conjugate by w = p1 z,
    // w <- A(w^2) + c (c is then p1 c; `program` is A(w^2) + c's, and the slice map is followed
    // by w = p1 z). A is the 4x4 matrix of s -> (p1 p0 p1^-1) s p2, row by row. Empty otherwise.
    std::optional<std::array<double, 16>> squareMap;
    // |z|^2 = normSquaredScale |w|^2 where the lanes iterate a conjugate w (1 / |p1|^2), else 1.
    double normSquaredScale = 1;
    int maxIterations = 1;
    double bailoutSquared = 4, escapeRadiusSquared = 4, stepScale = 1;
    Precision precision = Precision::Single;
    // A bicomplex polynomial (HypercomplexJuliaSet's duplex form, hypercomplex_julia.h): the
    // slice then maps into duplex coordinates, origin and axes holding (Re a, Im a, Re b, Im b)
    // of (a, b) = duplexForm(q), and the set iterates two complex polynomials; the escape test
    // is |q|^2 = (|a|^2 + |b|^2) / 2 > bailoutSquared. Empty for quaternions.
    struct Bicomplex {
        std::array<std::vector<std::complex<double>>, 2> coefficients;  // lowest degree first
        std::array<double, 2> escapeRadiusSquared{};
        // A component whose K is disconnected (duplex_component.h): its G*, ln|a_d| / (d - 1),
        // and the scalar reference, which the lanes ask for the points whose potential is below
        // 2 G* (the pull-back). Both components connected: no reference is asked.
        std::array<double, 2> criticalPotential{}, leadLog{};
        // Binomial components (a_d w^d + a_0) pull back in the lanes: 1 / |a_d| and the deepest
        // pull-back (DuplexComponent::pullBackLimit); the others ask the reference.
        std::array<bool, 2> binomial{};
        std::array<double, 2> inverseLead{}, pullBackLimit{};
        std::shared_ptr<const JuliaSet> reference;
    };
    std::optional<Bicomplex> bicomplex;
    // An octonion real form folded onto the quaternions (octonion_fold.h) through a slice on
    // which the fold is not linear: origin and axes hold the first four rows of
    // OctonionFold::rows (zero where absent) and foldRows the others, and the lanes iterate
    // (row 0, row 1, sqrt(row 2^2 + ... + row 5^2), 0), whose orbit has the octonion orbit's
    // radii. Each row as (value at 0, d/dx, d/dy, d/dz).
    bool folded = false;
    std::array<std::array<double, 4>, 2> foldRows{};
    // The set lies in the ball of this radius about the 3D origin.
    double boundingRadius = 2;

    // The power form where the polynomial has it (d <= kMaxLaneDegree), else the program.
    // With LaneCoordinates::Algebra the points are the algebra's own (x, y, z, w) = components
    // 0 to 3, the slice left out (stepScale 1).
    static LaneFractal from(const Fractal& fractal, Precision precision,
                            LaneCoordinates coordinates = LaneCoordinates::World);
    // The lanes of a bicomplex polynomial (not functions) whose bailout makes every escape of
    // |q| an escape of one duplex component (bailout^2 >= (R_1^2 + R_2^2) / 2, the default
    // bailout 4 for z^2 + c while both duplex components of c have modulus at most 12): the scalar
    // reference's estimate then never needs its Lipschitz fallback. Nothing for any other fractal.
    static std::optional<LaneFractal> fromBicomplex(
        const Fractal& fractal, Precision precision,
        LaneCoordinates coordinates = LaneCoordinates::World);
    // The lanes of an octonion real form (octonion_fold.h; formula as written in the scene),
    // on any slice. Nothing for any other fractal.
    static std::optional<LaneFractal> fromOctonion(const Scene& scene, const Fractal& fractal,
                                                   Precision precision);
    // The renderer's choice for `scene`: the lanes above where the SIMD engine sphere traces
    // (the quaternions, bicomplex polynomials, octonion real forms; in the scene's precision),
    // nothing where the scalar reference draws. With LaneCoordinates::Algebra, for points of
    // the algebra (4 components: no octonion fold).
    static std::optional<LaneFractal> forScene(
        const Scene& scene, const Fractal& fractal,
        LaneCoordinates coordinates = LaneCoordinates::World);

    // The same object seen through the rotation phi of the imaginary 3-space that takes Im c
    // onto the i axis: c becomes the complex Re c + |Im c| i and the slice map is followed by
    // phi. phi(q) = u q conj(u) is an algebra automorphism that keeps |q| and inner products
    // (docs/facts.md, Symmetries), so phi(s z^d + c) = s phi(z)^d + phi(c): every orbit is the
    // rotated orbit, with the same radii, escape counts, estimates and gradient products. With
    // a complex c the j and k components of z^2 + c only scale (the quadratic float loop of
    // estimate_lanes-inl.h iterates three numbers instead of four). Real forms only: a program
    // with quaternion coefficients is returned as it is.
    LaneFractal withComplexConstant() const;
};

// Work done by the lanes, to explain speed: polynomial evaluations that did useful work, and the
// lane slots that were available for them (utilisation = laneIterations / laneSlots).
struct LaneCounters {
    int64_t estimates = 0;       // distance estimates (or membership tests) completed
    int64_t laneIterations = 0;  // polynomial evaluations in live lanes
    int64_t laneSlots = 0;       // vector iterations times lanes
    LaneCounters& operator+=(const LaneCounters& o) {
        estimates += o.estimates;
        laneIterations += o.laneIterations;
        laneSlots += o.laneSlots;
        return *this;
    }
};

// Rays as structure of arrays; t runs over [tNear, tFar] (the bounding sphere).
struct RayBatch {
    std::vector<double> ox, oy, oz, dx, dy, dz, tNear, tFar;
    // Cones only (CameraMarch::cone), and optional: each cone's radius at t = 0, to which
    // pixelAngle * t adds (a cylinder where pixelAngle is 0). Empty means 0 for every ray.
    std::vector<double> spread;
    void clear();
    // Keeps the rays whose flag in `drop` is 0, in their order (`drop` has one per ray).
    void removeFlagged(const std::vector<uint8_t>& drop);
    void push(const Ray& ray, double near, double far) {
        ox.push_back(ray.origin.x), oy.push_back(ray.origin.y), oz.push_back(ray.origin.z);
        dx.push_back(ray.direction.x), dy.push_back(ray.direction.y), dz.push_back(ray.direction.z);
        tNear.push_back(near), tFar.push_back(far);
    }
    size_t size() const { return ox.size(); }
};

// Points as structure of arrays; w, the fourth coordinate of points of the algebra
// (LaneCoordinates::Algebra), is empty for 3D points.
struct PointBatch {
    std::vector<double> x, y, z, w;
    void clear();
    void push(const Point3d& p) { x.push_back(p.x), y.push_back(p.y), z.push_back(p.z); }
    size_t size() const { return x.size(); }
};

// The primary marcher (march.h, sphereTrace) with its settings.
struct CameraMarch {
    double epsilon = 0.25;     // in pixel footprints
    double pixelAngle = 1e-3;  // footprint per unit of t
    int maxSteps = 5000;
    double relaxation = 1;  // sphereTrace's over-relaxation (march.h); ignored by cones
    // Cone marching: each ray stands for a cone of radius pixelAngle * t (plus the ray's
    // spread, RayBatch::spread) about it, steps by the
    // estimate less that radius (so the ball of the estimate covers the cone's next stretch),
    // and ends (Grazing) as soon as the estimate is below epsilon radii (epsilon > 1, so that
    // steps stay at least (epsilon - 1) radii long): no confirmation. A miss before maxSteps
    // means no ray inside the cone meets the set before tFar.
    bool cone = false;
    // Whether each ray's result records the least estimate met on the way (TraceResult::
    // closest), for the glow.
    bool closest = false;
};
enum class TraceEnd : uint8_t { Miss, Inside, Grazing };
struct TraceResult {
    TraceEnd end = TraceEnd::Miss;
    double t = 0;         // where it ended
    double tOutside = 0;  // the last point known outside (t itself for a Grazing ray; the
                          // point before for a Grazing cone)
    int steps = 0;
    // With CameraMarch::closest: the least distance estimate along the ray, at most 1.
    float closest = 1;
};
void traceCameraRays(const LaneFractal& fractal, const CameraMarch& march, const RayBatch& rays,
                     std::vector<TraceResult>& results, LaneCounters& counters);

// The key light's shadow rays (shade.h, Shader::shadow): visibility in [0, 1] before the
// smoothstep, 0 where the set is hit.
struct ShadowMarch {
    double minimumStep = 1e-4;
    double softness = 12;
    bool soft = true;
    int maxSteps = 256;
    // Over-relaxation (Shader::shadowRelaxation): the factor where the estimate neither grows
    // nor falls, and its cap.
    double relaxation = 1;
    double maxRelaxation = 1;
};
void traceShadowRays(const LaneFractal& fractal, const ShadowMarch& march, const RayBatch& rays,
                     std::vector<double>& visibility, LaneCounters& counters);

// The distance estimate at each point (distance scaled for 3D steps, as Fractal::estimate).
struct PointEstimate {
    double distance = 0;
    bool inside = false;
    int iterations = 0;        // as DistanceEstimate::iterations
    double trap = 0;           // min |z_n| before escape
    double radiusSquared = 0;  // |z|^2 where the estimate was taken
};
void estimatePoints(const LaneFractal& fractal, const PointBatch& points,
                    std::vector<PointEstimate>& results, LaneCounters& counters);
// Only the distances (0 inside), without the orbit: cheaper where the bailout certifies escape
// (ambient occlusion needs no more).
void estimateDistances(const LaneFractal& fractal, const PointBatch& points,
                       std::vector<double>& distances, LaneCounters& counters);

// The M of a point's analytic normal (QuaternionJuliaSet::gradientIterations): the iterations of
// its estimate, maxIterations - 1 for points inside.
inline int gradientIterationsOf(const PointEstimate& estimate, int maxIterations) {
    return estimate.inside ? maxIterations - 1 : estimate.iterations;
}
// Unit outward normals from the analytic gradient of |z_M|^2 (Fractal::normal), M given per
// point (gradientIterationsOf its estimate).
void potentialNormals(const LaneFractal& fractal, const PointBatch& points,
                      const std::vector<int>& iterations, std::vector<Vector3d>& normals,
                      LaneCounters& counters);
// The same normals for shading that needs nothing else of the estimates (no orbit colouring):
// where the lanes iterate z^2 + c in three numbers (float, certified bailout), the gradient's
// own iterates stop where the estimate would, and no estimate is taken.
void potentialNormalsAlone(const LaneFractal& fractal, const PointBatch& points,
                           std::vector<Vector3d>& normals, LaneCounters& counters);

// The SIMD target the dispatcher chose on this CPU, e.g. "AVX2".
const char* laneTargetName();

}  // namespace quaternia
