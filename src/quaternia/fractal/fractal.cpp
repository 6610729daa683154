#include "quaternia/fractal/fractal.h"

#include "quaternia/algebra/formula.h"

namespace quaternia {

Fractal Fractal::fromScene(const Scene& scene) {
    Polynomial polynomial = compileFormula(scene.fractal.formula, scene.fractal.c);
    // The lanes' program from the formula as written (parsed again: it parsed above).
    auto program = std::make_shared<const FormulaProgram>(
        FormulaProgram::compile(Formula::parse(scene.fractal.formula), scene.fractal.c));
    return Fractal(JuliaSet(std::move(polynomial), scene.fractal.maxIterations,
                            scene.fractal.bailout, std::move(program)),
                   Slice(scene.slice));
}

DistanceEstimate Fractal::estimate(const Point3d& p) const {
    DistanceEstimate e = set_.estimate(slice_.quaternionFromWorld(p));
    e.distance *= slice_.stepScale();
    return e;
}

Vector3d Fractal::normal(const Point3d& p) const {
    auto g = set_.potentialGradient(slice_.quaternionFromWorld(p), slice_.tangents());
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
    const int iterations = set_.gradientIterations(slice_.quaternionFromWorld(p));
    Vector3d g;
    for (int axis = 0; axis < 3; ++axis) {
        Point3d plus = p, minus = p;
        plus[axis] += h;
        minus[axis] -= h;
        g[axis] = set_.logRadiusAfter(slice_.quaternionFromWorld(plus), iterations) -
                  set_.logRadiusAfter(slice_.quaternionFromWorld(minus), iterations);
    }
    return normalize(g);
}

}  // namespace quaternia
