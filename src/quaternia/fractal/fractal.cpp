#include "quaternia/fractal/fractal.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "quaternia/algebra/formula.h"

namespace quaternia {

namespace {

// An octonion formula sum a_k z^k + C with real a_k, C = p(0) (docs/methods.md, Other algebras):
// z_n stays in span{1, Im z_0, Im C}, and its orbit depends only on Re z, the component of Im z
// along u = Im C / |Im C| and the length of the rest, exactly as for quaternions. Where the
// slice's points have their parts orthogonal to 1 and u in a plane W (the default slice does),
// q -> (Re q, <Im q, u>, <q, w_1>, <q, w_2>) is an isometry of the slice into H that carries the
// octonion orbit to the quaternion orbit of the same formula with c' = Re C + |Im C| i: the same
// membership and estimates, so the quaternion paths (the SIMD lanes) draw it. Nothing when the
// formula or the slice does not have that form.
std::optional<Fractal> octonionAsQuaternion(const Scene& scene,
                                            const HypercomplexFractal& octonion) {
    const HypercomplexFormula& formula = octonion.set.formula();
    if (formula.transcendental()) return std::nullopt;
    // The a_k, and that c is only in the constant term: the same terms for two values of c.
    // (A formula too large to multiply out stays with the octonion arithmetic.)
    std::optional<Polynomial> without, with;
    try {
        const Formula parsed = Formula::parse(scene.fractal.formula);
        without = parsed.expand(Quaternion());
        with = parsed.expand(Quaternion(0.37, 0.21, -0.13, 0.29));
    } catch (const FormulaError&) {
        return std::nullopt;
    }
    const std::optional<RealForm> real = without->realForm(), realWith = with->realForm();
    if (!real || !realWith || real->coefficients != realWith->coefficients) return std::nullopt;
    const Hypercomplex constant = formula.evaluate(Hypercomplex{});
    Hypercomplex u{};
    for (size_t n = 1; n < 8; ++n)
        u[n] = constant[n];
    const double length = euclideanNorm(u);
    if (length > 0)
        u = (1 / length) * u;
    else
        u[1] = 1;
    // The parts of the slice's origin and axes orthogonal to 1 and u, and a basis of their span.
    const HypercomplexSlice& slice = octonion.slice;
    const std::array<Hypercomplex, 4> vectors = {slice.fromWorld(Point3d(0, 0, 0)),
                                                 slice.tangents()[0], slice.tangents()[1],
                                                 slice.tangents()[2]};
    auto dot = [](const Hypercomplex& a, const Hypercomplex& b) {
        double sum = 0;
        for (size_t n = 0; n < 8; ++n)
            sum += a[n] * b[n];
        return sum;
    };
    auto orthogonalPart = [&](Hypercomplex x) {
        x[0] = 0;
        return x - dot(x, u) * u;
    };
    std::vector<Hypercomplex> basis;
    for (const Hypercomplex& v : vectors) {
        Hypercomplex rest = orthogonalPart(v);
        for (const Hypercomplex& b : basis)
            rest = rest - dot(rest, b) * b;
        const double size = euclideanNorm(rest);
        if (size <= 1e-12 * std::max(1.0, euclideanNorm(v))) continue;
        if (basis.size() == 2) return std::nullopt;  // W has more than two dimensions
        basis.push_back((1 / size) * rest);
    }
    while (basis.size() < 2)
        basis.push_back(Hypercomplex{});
    auto toQuaternion = [&](const Hypercomplex& x) {
        Hypercomplex im = x;
        im[0] = 0;
        return Quaternion(x[0], dot(im, u), dot(x, basis[0]), dot(x, basis[1]));
    };
    // The lanes' bounding sphere is the bailout's: only slices whose origin is orthogonal to
    // the axes (as the default slice's 0 is).
    for (size_t a = 0; a < 3; ++a)
        if (std::abs(dot(vectors[0], vectors[a + 1])) > 1e-12) return std::nullopt;
    std::vector<Term> terms;
    for (const Term& term : without->terms())
        if (term.degree() > 0) terms.push_back(term);
    terms.push_back(Term{{Quaternion(constant[0], length, 0, 0)}});
    return Fractal(
        JuliaSet(Polynomial(std::move(terms)), scene.fractal.maxIterations, scene.fractal.bailout),
        Slice::isometry(
            toQuaternion(vectors[0]),
            {toQuaternion(vectors[1]), toQuaternion(vectors[2]), toQuaternion(vectors[3])}));
}

}  // namespace

Fractal Fractal::fromScene(const Scene& scene) {
    if (scene.fractal.algebra != Algebra::kQuaternion) {
        auto other = hypercomplexFractalFromScene(scene);  // checks everything first
        if (scene.fractal.algebra == Algebra::kOctonion &&
            scene.render.engine == RenderEngine::Simd)
            if (auto same = octonionAsQuaternion(scene, *other)) return std::move(*same);
        return Fractal(std::move(other));
    }
    Polynomial polynomial = compileFormula(scene.fractal.formula, scene.fractal.c);
    // The lanes' program from the formula as written (parsed again: it parsed above).
    auto program = std::make_shared<const FormulaProgram>(
        FormulaProgram::compile(Formula::parse(scene.fractal.formula), scene.fractal.c));
    return Fractal(JuliaSet(std::move(polynomial), scene.fractal.maxIterations,
                            scene.fractal.bailout, std::move(program)),
                   Slice(scene.slice));
}

DistanceEstimate Fractal::estimate(const Point3d& p) const {
    if (hypercomplex_) {
        DistanceEstimate e = hypercomplex_->set.estimate(hypercomplex_->slice.fromWorld(p));
        e.distance /= hypercomplex_->slice.stretch();
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
        const HypercomplexSlice& slice = hypercomplex_->slice;
        auto g = hypercomplex_->set.potentialGradient(slice.fromWorld(p), slice.tangents());
        return normalOrOutward(Vector3d(g[0], g[1], g[2]), p);
    }
    auto g = set_->potentialGradient(slice_->quaternionFromWorld(p), slice_->tangents());
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
