#include "quaternia/dynamics/orbit.h"

#include <algorithm>
#include <cmath>

namespace quaternia {
namespace {

Quaternion iterate(const Polynomial& p, Quaternion z, int n) {
    for (int k = 0; k < n; ++k)
        z = p.evaluate(z);
    return z;
}

// Newton's method on F(w) = f^n(w) - w in H: (J - I) delta = -F(w), J the Jacobian of f^n.
// Returns nullopt when J - I is singular (a multiplier ~1) or the iteration does not settle.
std::optional<Quaternion> refineCycle(const Polynomial& p, Quaternion w, int n, double tolerance) {
    for (int step = 0; step < 60; ++step) {
        std::vector<Quaternion> cycle{w};
        for (int k = 1; k < n; ++k)
            cycle.push_back(p.evaluate(cycle.back()));
        Quaternion residual = p.evaluate(cycle.back()) - w;
        Matrix4 m = cycleJacobian(p, cycle);
        for (int i = 0; i < 4; ++i)
            m[i][i] -= 1;
        std::array<double, 4> delta;
        if (!solve(m, {-residual.w, -residual.x, -residual.y, -residual.z}, delta)) {
            return std::nullopt;
        }
        Quaternion correction(delta[0], delta[1], delta[2], delta[3]);
        if (!isFinite(correction)) return std::nullopt;
        w += correction;
        if (norm(correction) <= 1e-15 * std::max(1.0, norm(w))) break;
    }
    if (!(norm(iterate(p, w, n) - w) <= tolerance)) return std::nullopt;
    return w;
}

// The least divisor d of n with |f^d(w) - w| <= tolerance.
int exactPeriod(const Polynomial& p, const Quaternion& w, int n, double tolerance) {
    for (int d = 1; d < n; ++d) {
        if (n % d == 0 && norm(iterate(p, w, d) - w) <= tolerance) return d;
    }
    return n;
}

double distanceToCycle(const Quaternion& z, const std::vector<Quaternion>& cycle) {
    double best = INFINITY;
    for (const Quaternion& w : cycle)
        best = std::min(best, norm(z - w));
    return best;
}

// The first iterate index k with |z_k - z_{k-n}| <= tol (tol growing with the scale), and n.
struct Recurrence {
    int index = -1, period = 0;
};

// The iterates of z0 up to the first that escapes or recurs, or to maxIterations.
struct OrbitWalk {
    std::vector<Quaternion> orbit;
    double scale = 1;  // the largest |z_k| (at least 1), which the tolerance is relative to
    Recurrence recurrence;
    int escapeIteration = -1;
};

OrbitWalk walkOrbit(const Polynomial& p, const Quaternion& z0, double escapeRadius,
                    const OrbitOptions& options) {
    OrbitWalk walk;
    std::vector<Quaternion>& orbit = walk.orbit;
    orbit.push_back(z0);
    walk.scale = std::max(1.0, norm(z0));
    for (int k = 0;; ++k) {
        const Quaternion& z = orbit[k];
        walk.scale = std::max(walk.scale, norm(z));
        if (norm(z) > escapeRadius) {
            walk.escapeIteration = k;
            return walk;
        }
        const double tolerance = options.tolerance * walk.scale;
        for (int j = k - 1; j >= std::max(0, k - options.maxPeriod); --j) {
            if (norm(z - orbit[j]) <= tolerance) {
                walk.recurrence = {k, k - j};
                break;
            }
        }
        if (walk.recurrence.index >= 0 || k == options.maxIterations) return walk;
        orbit.push_back(p.evaluate(z));
    }
}

// The first iterate on the cycle (within tol): the orbit's preperiod. The cycle is rotated so
// that its points[0] is the point the orbit meets there.
int meetCycle(const Polynomial& p, const std::vector<Quaternion>& orbit, double tol,
              CycleAnalysis& cycle) {
    int hit = 0;
    while (distanceToCycle(orbit[hit], cycle.points) > tol)
        ++hit;  // ends at the recurrence's index at the latest
    for (size_t k = 0; k < cycle.points.size(); ++k) {
        if (norm(orbit[hit] - cycle.points[k]) <= tol) {
            std::rotate(cycle.points.begin(), cycle.points.begin() + std::ptrdiff_t(k),
                        cycle.points.end());
            cycle.jacobian = cycleJacobian(p, cycle.points);
            break;
        }
    }
    return hit;
}

// The fate of an orbit that meets its cycle at iterate `hit`: periodic where it starts on the
// cycle; preperiodic where the governing class repels (or is a saddle) or where the orbit jumps
// onto the cycle; attracted otherwise.
void decideFate(const std::vector<Quaternion>& orbit, int hit, double scale, OrbitResult& result) {
    const CycleAnalysis& cycle = *result.cycle;
    const double tol = result.tolerance;
    Stability stability = result.governingClass.stability;
    if (hit == 0) {
        result.fate = OrbitFate::Periodic;
    } else if (stability == Stability::Repelling || stability == Stability::Saddle) {
        result.fate = OrbitFate::Preperiodic;
    } else {
        bool jumped = distanceToCycle(orbit[hit], cycle.points) <= 1e-3 * tol &&
                      distanceToCycle(orbit[hit - 1], cycle.points) > 1e-4 * scale;
        result.fate = jumped ? OrbitFate::Preperiodic : OrbitFate::Attracted;
        if (stability == Stability::Neutral) {
            result.unsure = true;
            result.note =
                "neutral cycle: landing on it and slow convergence to it cannot be "
                "told apart numerically";
        }
    }
}

}  // namespace

std::string toString(OrbitFate fate) {
    switch (fate) {
        case OrbitFate::Escapes:
            return "escapes";
        case OrbitFate::Periodic:
            return "periodic";
        case OrbitFate::Preperiodic:
            return "preperiodic";
        case OrbitFate::Attracted:
            return "attracted";
        case OrbitFate::Undecided:
            return "undecided";
    }
    return "unknown";
}

Polynomial quaternionPolynomial(const ComplexPolynomial& p) {
    std::vector<Term> terms;
    for (int k = 0; k <= p.degree(); ++k) {
        Complex a = p.coefficients()[k];
        Term term{std::vector<Quaternion>(k + 1, Quaternion(1))};
        term.coefficients[0] = Quaternion(a.real(), a.imag(), 0, 0);
        terms.push_back(std::move(term));
    }
    return Polynomial(std::move(terms));
}

CycleAnalysis analyzeCycle(const Polynomial& p, const Quaternion& start, int period) {
    CycleAnalysis cycle;
    cycle.points.push_back(start);
    for (int k = 1; k < period; ++k)
        cycle.points.push_back(p.evaluate(cycle.points.back()));
    for (int k = 0; k < period; ++k) {
        const Quaternion& w = cycle.points[k];
        cycle.residual = std::max(cycle.residual, norm(iterate(p, w, period) - w));
    }
    cycle.jacobian = cycleJacobian(p, cycle.points);
    cycle.eigenvalues = eigenvalues(cycle.jacobian);
    cycle.classInH = classifyEigenvalues({cycle.eigenvalues.begin(), cycle.eigenvalues.end()});
    if (auto restriction = restrictToComplexPlane(p)) {
        bool inside = std::all_of(cycle.points.begin(), cycle.points.end(),
                                  [&](const auto& w) { return inPlane(w, restriction->axis); });
        if (inside) {
            Complex lambda = 1;
            for (const Quaternion& w : cycle.points)
                lambda *= restriction->polynomial.derivative(restriction->toComplex(w));
            cycle.multiplier = lambda;
            cycle.axis = restriction->axis;
            cycle.complexClass = classifyMultiplier(lambda);
        }
    }
    return cycle;
}

OrbitResult analyzeOrbit(const Polynomial& p, const Quaternion& z0, const OrbitOptions& options) {
    OrbitResult result;
    result.escapeRadius = p.escapeRadius();
    const OrbitWalk walk = walkOrbit(p, z0, result.escapeRadius, options);
    const std::vector<Quaternion>& orbit = walk.orbit;
    const Recurrence& recurrence = walk.recurrence;
    result.tolerance = options.tolerance * walk.scale;
    result.iterations = int(orbit.size()) - 1;
    if (walk.escapeIteration >= 0) {
        result.fate = OrbitFate::Escapes;
        result.escapeIteration = walk.escapeIteration;
        return result;
    }
    if (recurrence.index < 0) {
        result.note = "no escape and no cycle within " + std::to_string(options.maxIterations) +
                      " iterations";
        return result;
    }

    const double tol = result.tolerance;
    Quaternion start = orbit[recurrence.index];
    std::optional<Quaternion> refined = refineCycle(p, start, recurrence.period, tol);
    int period = exactPeriod(p, refined.value_or(start), recurrence.period, tol);
    result.cycle = analyzeCycle(p, refined.value_or(start), period);
    CycleAnalysis& cycle = *result.cycle;
    cycle.refined = refined.has_value();
    if (!cycle.refined) {
        result.unsure = true;
        result.note =
            "Newton refinement of the cycle failed (f^n - id is near singular), so "
            "the cycle points are the orbit's own";
    }
    bool orbitInPlane = cycle.multiplier && inPlane(z0, cycle.axis);
    result.governingClass = orbitInPlane ? cycle.complexClass : cycle.classInH;
    result.unsure = result.unsure || result.governingClass.unsure;
    result.preperiod = meetCycle(p, orbit, tol, cycle);
    decideFate(orbit, result.preperiod, walk.scale, result);
    return result;
}

}  // namespace quaternia
