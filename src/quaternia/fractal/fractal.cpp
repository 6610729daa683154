#include "quaternia/fractal/fractal.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "quaternia/algebra/formula.h"
#include "quaternia/fractal/algebra_rules.h"
#include "quaternia/fractal/octonion_fold.h"

namespace quaternia {

namespace {

// An octonion real form (octonion_fold.h) on a slice whose points have their parts orthogonal to
// 1 and u = Im C / |Im C| in a plane W (the default slice does): the fold is then linear, an
// isometry of the slice into H, q -> (Re q, <Im q, u>, <q, w_1>, <q, w_2>), and the quaternion
// set of the folded formula through that slice has the same membership and estimates, so the
// quaternion paths (the SIMD lanes, the mesher) draw it. Nothing when the formula or the slice
// does not have that form.
std::optional<Fractal> octonionAsQuaternion(const FractalSettings& fractal,
                                            const HypercomplexJuliaSet& octonion,
                                            const Slice& slice) {
    std::optional<OctonionFold> fold = foldOctonion(fractal.formula, octonion, slice);
    // The lanes' bounding sphere is the bailout's: only slices whose origin is orthogonal to
    // the axes (as the default slice's 0 is).
    if (!fold || fold->rows.size() > 4 || !fold->originOrthogonal) return std::nullopt;
    auto column = [&](size_t c) {
        std::array<double, 4> q{};
        for (size_t r = 0; r < fold->rows.size(); ++r)
            q[r] = fold->rows[r][c];
        return Quaternion(q[0], q[1], q[2], q[3]);
    };
    return Fractal(
        QuaternionJuliaSet(std::move(fold->polynomial), fractal.maxIterations, fractal.bailout),
        Slice::isometry(column(0), {column(1), column(2), column(3)}));
}

// The quaternion set of fractal.formula with c's quaternion part and this bailout: the
// expanded polynomial, and the lanes' program from the formula as written (parsed again: it
// parsed in compileFormula).
QuaternionJuliaSet quaternionSetOf(const FractalSettings& fractal, double bailout) {
    Polynomial polynomial = compileFormula(fractal.formula, fractal.c);
    auto program = std::make_shared<const FormulaProgram>(
        FormulaProgram::compile(Formula::parse(fractal.formula), fractal.c));
    return QuaternionJuliaSet(std::move(polynomial), fractal.maxIterations, bailout,
                              std::move(program));
}

// An 8-component algebra whose c and slice lie in the quaternion half (components 0 .. 3, the
// rest 0): those elements are a subalgebra isomorphic to H (the biquaternion product (a + bh)
// (c + dh) = (ac - bd) + (ad + bc) h and the octonion product (a, b)(c, d) = (ac - conj(d) b,
// da + b conj(c)) are ac where b = d = 0), and the formula's own constants are written with 1,
// i, j and k, so every orbit stays there and is the quaternion orbit: the quaternion set of the
// formula with the same bailout, through the slice's isometry into H, draws it (the SIMD lanes,
// the distance estimate). Only slices whose origin is orthogonal to the axes, as for the fold.
std::optional<Fractal> quaternionHalf(const FractalSettings& fractal,
                                      const HypercomplexJuliaSet& set, const Slice& slice) {
    for (double upper : fractal.cUpper)
        if (upper != 0) return std::nullopt;
    const Hypercomplex origin = slice.fromWorld(Point3d(0, 0, 0));
    const std::array<Hypercomplex, 3>& axes = slice.tangents();
    for (size_t k = 4; k < 8; ++k) {
        if (origin[k] != 0) return std::nullopt;
        for (const Hypercomplex& axis : axes)
            if (axis[k] != 0) return std::nullopt;
    }
    for (const Hypercomplex& axis : axes)
        if (std::fabs(dotProduct(origin, axis)) > 1e-12) return std::nullopt;
    auto quaternion = [](const Hypercomplex& a) { return Quaternion(a[0], a[1], a[2], a[3]); };
    return Fractal(quaternionSetOf(fractal, set.bailout()),
                   Slice::isometry(quaternion(origin), {quaternion(axes[0]), quaternion(axes[1]),
                                                        quaternion(axes[2])}));
}

}  // namespace

Fractal Fractal::fromSettings(const FractalSettings& fractal, const SliceSettings& slice,
                              QuaternionPaths paths) {
    const AlgebraRules& rules = algebraRules(fractal.algebra);
    if (!rules.quaternionSet) {
        auto set = hypercomplexJuliaSetOf(fractal);  // checks the formula and bailout first
        Slice through(slice, fractal.algebra);
        if (rules.quaternionHalf && paths == QuaternionPaths::kWherePossible)
            if (auto same = quaternionHalf(fractal, *set, through)) return std::move(*same);
        if (rules.foldsOntoQuaternions && paths == QuaternionPaths::kWherePossible)
            if (auto same = octonionAsQuaternion(fractal, *set, through)) return std::move(*same);
        return Fractal(std::move(set), std::move(through));
    }
    return Fractal(quaternionSetOf(fractal, fractal.bailout), Slice(slice));
}

DistanceEstimate Fractal::estimate(const Point3d& p) const {
    DistanceEstimate e = set_->estimate(slice_.fromWorld(p));
    e.distance *= slice_.stepScale();
    return e;
}

bool Fractal::excludesTube(const Ray& ray, double t0, double t1, double radius) const {
    const double extend = radius > 0 ? radius : 0;
    const Hypercomplex a = slice_.fromWorld(ray.at(t0 - extend)),
                       b = slice_.fromWorld(ray.at(t1 + extend));
    double largest = 0;
    for (size_t i = 0; i < a.size(); ++i)
        largest = std::max({largest, std::fabs(a[i]), std::fabs(b[i])});
    const double rounding = 1e-12 * (1 + largest);
    if (!(radius > 0)) return set_->excludesSegment(a, b, rounding);
    // Two unit directions across the ray: the square of half-width `radius` they span holds
    // the tube's disc, and the segment lengthened by `radius` at each end its caps.
    const Vector3d& d = ray.direction;
    const Vector3d axis = std::fabs(d[0]) < 0.5 ? Vector3d(1, 0, 0) : Vector3d(0, 1, 0);
    const Vector3d u = normalize(cross(d, axis)), v = cross(d, u);
    const auto& tangents = slice_.tangents();
    Hypercomplex across1{}, across2{};
    for (size_t i = 0; i < across1.size(); ++i) {
        across1[i] =
            radius * (u[0] * tangents[0][i] + u[1] * tangents[1][i] + u[2] * tangents[2][i]);
        across2[i] =
            radius * (v[0] * tangents[0][i] + v[1] * tangents[1][i] + v[2] * tangents[2][i]);
    }
    // The across directions' rounding (a few ulps of radius times the tangents) lies far below
    // the allowance for the slice's.
    return set_->excludesTube(
        tubeAbout(a, b, across1, across2, rounding, int(kMaxAlgebraDimension)));
}

bool Fractal::includesPoint(const Point3d& p) const {
    const Hypercomplex q = slice_.fromWorld(p);
    double largest = 0;
    for (double x : q)
        largest = std::max(largest, std::fabs(x));
    return set_->includesBox(q, 1e-12 * (1 + largest));
}

Vector3d Fractal::normal(const Point3d& p) const {
    auto g = set_->potentialGradient(slice_.fromWorld(p), slice_.tangents());
    return normalOrOutward(Vector3d(g[0], g[1], g[2]), p);
}

Vector3d normalOrOutward(const Vector3d& g, const Point3d& p) {
    double len = length(g);
    if (!(len > 0) || !std::isfinite(len)) {
        double lp = length(p);
        return lp > 0 ? p / lp : Vector3d(0, 1, 0);
    }
    return g / len;
}

Vector3d Fractal::normalByDifferences(const Point3d& p, double h) const {
    // The potential's level sets are what the analytic normal differentiates: ln|z_M| with M
    // fixed at the point itself (the estimate's own gradient differs by that of ln|z'_M|).
    const int iterations = set_->gradientIterations(slice_.fromWorld(p));
    Vector3d g;
    for (int axis = 0; axis < 3; ++axis) {
        Point3d plus = p, minus = p;
        plus[axis] += h;
        minus[axis] -= h;
        g[axis] = set_->logRadiusAfter(slice_.fromWorld(plus), iterations) -
                  set_->logRadiusAfter(slice_.fromWorld(minus), iterations);
    }
    return normalize(g);
}

}  // namespace quaternia
