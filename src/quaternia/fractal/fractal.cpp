#include "quaternia/fractal/fractal.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "quaternia/algebra/formula.h"
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
                                            const HypercomplexFractal& octonion) {
    std::optional<OctonionFold> fold = foldOctonion(fractal.formula, octonion);
    // The lanes' bounding sphere is the bailout's: only slices whose origin is orthogonal to
    // the axes (as the default slice's 0 is).
    if (!fold || fold->rows.size() > 4 || !fold->originOrthogonal) return std::nullopt;
    auto column = [&](size_t c) {
        std::array<double, 4> q{};
        for (size_t r = 0; r < fold->rows.size(); ++r)
            q[r] = fold->rows[r][c];
        return Quaternion(q[0], q[1], q[2], q[3]);
    };
    return Fractal(JuliaSet(std::move(fold->polynomial), fractal.maxIterations, fractal.bailout),
                   Slice::isometry(column(0), {column(1), column(2), column(3)}));
}

}  // namespace

Fractal Fractal::fromSettings(const FractalSettings& fractal, const SliceSettings& slice,
                              OctonionFolding folding) {
    if (fractal.algebra != Algebra::kQuaternion) {
        auto other = hypercomplexFractalOf(fractal, slice);  // checks everything first
        if (fractal.algebra == Algebra::kOctonion && folding == OctonionFolding::kWherePossible)
            if (auto same = octonionAsQuaternion(fractal, *other)) return std::move(*same);
        return Fractal(std::move(other));
    }
    Polynomial polynomial = compileFormula(fractal.formula, fractal.c);
    // The lanes' program from the formula as written (parsed again: it parsed above).
    auto program = std::make_shared<const FormulaProgram>(
        FormulaProgram::compile(Formula::parse(fractal.formula), fractal.c));
    return Fractal(
        JuliaSet(std::move(polynomial), fractal.maxIterations, fractal.bailout, std::move(program)),
        Slice(slice));
}

DistanceEstimate Fractal::estimate(const Point3d& p) const {
    if (hypercomplex_) {
        DistanceEstimate e = hypercomplex_->set.estimate(hypercomplex_->slice.fromWorld(p));
        e.distance *= hypercomplex_->slice.stepScale();
        return e;
    }
    DistanceEstimate e = set_->estimate(slice_->quaternionFromWorld(p));
    e.distance *= slice_->stepScale();
    return e;
}

bool Fractal::contains(const Point3d& p) const {
    if (hypercomplex_) return hypercomplex_->set.contains(hypercomplex_->slice.fromWorld(p));
    return set_->contains(slice_->quaternionFromWorld(p));
}

double Fractal::boundingRadius() const {
    if (hypercomplex_)
        return hypercomplex_->slice.boundingRadius(hypercomplex_->set.boundingRadius());
    return set_->boundingRadius();
}

DistanceKind Fractal::distanceKind() const {
    return hypercomplex_ ? hypercomplex_->set.distanceKind() : DistanceKind::kEstimate;
}

double Fractal::escapeRadius() const {
    return hypercomplex_ ? hypercomplex_->set.escapeRadius() : set_->escapeRadius();
}

Vector3d Fractal::normal(const Point3d& p) const {
    if (hypercomplex_) {
        const Slice& slice = hypercomplex_->slice;
        auto g = hypercomplex_->set.potentialGradient(slice.fromWorld(p), slice.tangents());
        return normalOrOutward(Vector3d(g[0], g[1], g[2]), p);
    }
    auto g = set_->potentialGradient(slice_->quaternionFromWorld(p), slice_->quaternionTangents());
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
    auto differences = [&](const auto& set, const auto& toAlgebra) {
        const int iterations = set.gradientIterations(toAlgebra(p));
        Vector3d g;
        for (int axis = 0; axis < 3; ++axis) {
            Point3d plus = p, minus = p;
            plus[axis] += h;
            minus[axis] -= h;
            g[axis] = set.logRadiusAfter(toAlgebra(plus), iterations) -
                      set.logRadiusAfter(toAlgebra(minus), iterations);
        }
        return normalize(g);
    };
    if (hypercomplex_) {
        return differences(hypercomplex_->set,
                           [&](const Point3d& q) { return hypercomplex_->slice.fromWorld(q); });
    }
    return differences(*set_, [&](const Point3d& q) { return slice_->quaternionFromWorld(q); });
}

}  // namespace quaternia
