#include "quaternia/dynamics/orbit.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace quaternia {
namespace {

// The maps the orbit analysis runs on: a point type with operator[] on its N coordinates,
// evaluation and the N x N Jacobian, and the complex plane C_u where the map restricts to a
// complex polynomial (the multiplier of a cycle there).
struct QuaternionMap {
    using Point = Quaternion;
    using Cycle = CycleAnalysis;
    static constexpr std::size_t N = 4;
    const Polynomial& p;
    Point operator()(const Point& z) const { return p.evaluate(z); }
    Matrix4 jacobianAt(const Point& z) const { return jacobian(p, z); }
    static double size(const Point& z) { return norm(z); }
    static bool finite(const Point& z) { return isFinite(z); }
    void addMultiplier(Cycle& cycle) const;
    static bool inPlane(const Point& z, const Quaternion& axis) {
        return quaternia::inPlane(z, axis);
    }
};

// In another algebra the complex plane is the copy span{1, u} of C that the formula maps into
// itself (HypercomplexFormula::complexAxis), where p is complex-analytic: its derivative along
// 1 is p'(z), read in the coordinates x + y u.
template <std::size_t Dimension>
struct HypercomplexMap {
    using Point = Hypercomplex;
    using Cycle = HypercomplexCycleAnalysis<Dimension>;
    static constexpr std::size_t N = Dimension;
    const HypercomplexFormula& formula;
    std::optional<Quaternion> axis = formula.complexAxis();
    Point operator()(const Point& z) const { return formula.evaluate(z); }
    Matrix<N> jacobianAt(const Point& z) const { return hypercomplexJacobian<N>(formula, z); }
    static double size(const Point& z) { return euclideanNorm(z); }
    static bool finite(const Point& z) { return std::isfinite(normSquared(z)); }
    static Quaternion quaternionPart(const Point& z) { return Quaternion(z[0], z[1], z[2], z[3]); }
    static bool inPlane(const Point& z, const Quaternion& u) {
        return std::all_of(z.begin() + 4, z.end(), [](double v) { return v == 0; }) &&
               quaternia::inPlane(quaternionPart(z), u);
    }
    void addMultiplier(Cycle& cycle) const {
        if (!axis || !std::all_of(cycle.points.begin(), cycle.points.end(),
                                  [&](const Point& w) { return inPlane(w, *axis); }))
            return;
        Complex lambda = 1;
        for (const Point& w : cycle.points) {
            const Quaternion slope =
                quaternionPart(formula.evaluateWithDerivative(w, realElement(1)).second);
            lambda *= Complex(slope.w, dot(slope, *axis));
        }
        cycle.multiplier = lambda;
        cycle.axis = *axis;
        cycle.complexClass = classifyMultiplier(lambda);
    }
};

template <typename Map>
typename Map::Point iterate(const Map& f, typename Map::Point z, int n) {
    for (int k = 0; k < n; ++k)
        z = f(z);
    return z;
}

// The Jacobian of f^n at cycle[0]: J(cycle[n-1]) ... J(cycle[1]) J(cycle[0]) (chain rule).
template <typename Map>
Matrix<Map::N> jacobianOfCycle(const Map& f, const std::vector<typename Map::Point>& cycle) {
    Matrix<Map::N> m = identityMatrix<Map::N>();
    for (const auto& z : cycle)
        m = f.jacobianAt(z) * m;
    return m;
}

// Newton's method on F(w) = f^n(w) - w: (J - I) delta = -F(w), J the Jacobian of f^n.
// Returns nullopt when J - I is singular (a multiplier ~1) or the iteration does not settle.
template <typename Map>
std::optional<typename Map::Point> refineCycle(const Map& f, typename Map::Point w, int n,
                                               double tolerance) {
    using Point = typename Map::Point;
    constexpr std::size_t N = Map::N;
    for (int step = 0; step < 60; ++step) {
        std::vector<Point> cycle{w};
        for (int k = 1; k < n; ++k)
            cycle.push_back(f(cycle.back()));
        Point residual = f(cycle.back()) - w;
        Matrix<N> m = jacobianOfCycle(f, cycle);
        std::array<double, N> b;
        for (std::size_t i = 0; i < N; ++i) {
            m[i][i] -= 1;
            b[i] = -residual[i];
        }
        std::array<double, N> delta;
        if (!solve(m, b, delta)) return std::nullopt;
        Point correction{};
        for (std::size_t i = 0; i < N; ++i)
            correction[i] = delta[i];
        if (!Map::finite(correction)) return std::nullopt;
        w = w + correction;
        if (Map::size(correction) <= 1e-15 * std::max(1.0, Map::size(w))) break;
    }
    if (!(Map::size(iterate(f, w, n) - w) <= tolerance)) return std::nullopt;
    return w;
}

// The least divisor d of n with |f^d(w) - w| <= tolerance.
template <typename Map>
int exactPeriod(const Map& f, const typename Map::Point& w, int n, double tolerance) {
    for (int d = 1; d < n; ++d) {
        if (n % d == 0 && Map::size(iterate(f, w, d) - w) <= tolerance) return d;
    }
    return n;
}

template <typename Map>
double distanceToCycle(const typename Map::Point& z,
                       const std::vector<typename Map::Point>& cycle) {
    double best = INFINITY;
    for (const auto& w : cycle)
        best = std::min(best, Map::size(z - w));
    return best;
}

// The first iterate index k with |z_k - z_{k-n}| <= tol (tol growing with the scale), and n.
struct Recurrence {
    int index = -1, period = 0;
};

// The iterates of z0 up to the first that escapes or recurs, or to maxIterations.
template <typename Point>
struct OrbitWalk {
    std::vector<Point> orbit;
    double scale = 1;  // the largest |z_k| (at least 1), which the tolerance is relative to
    Recurrence recurrence;
    int escapeIteration = -1;
};

template <typename Map>
OrbitWalk<typename Map::Point> walkOrbit(const Map& f, const typename Map::Point& z0,
                                         double escapeRadius, const OrbitOptions& options) {
    OrbitWalk<typename Map::Point> walk;
    auto& orbit = walk.orbit;
    orbit.push_back(z0);
    walk.scale = std::max(1.0, Map::size(z0));
    for (int k = 0;; ++k) {
        const auto& z = orbit[k];
        walk.scale = std::max(walk.scale, Map::size(z));
        if (Map::size(z) > escapeRadius) {
            walk.escapeIteration = k;
            return walk;
        }
        const double tolerance = options.tolerance * walk.scale;
        for (int j = k - 1; j >= std::max(0, k - options.maxPeriod); --j) {
            if (Map::size(z - orbit[j]) <= tolerance) {
                walk.recurrence = {k, k - j};
                break;
            }
        }
        if (walk.recurrence.index >= 0 || k == options.maxIterations) return walk;
        orbit.push_back(f(z));
    }
}

// Continues the orbit, if no iterate so far is within tol of the cycle, until one is. The
// recurrence |z_k - z_{k-n}| <= tol that found the cycle puts z_k within about tol / |1 - lambda|
// of it (lambda the multiplier of f^n), not within tol: an orbit that spirals into an attracting
// cycle (lambda near a root of unity) or creeps into it (lambda near 1) recurs before it arrives,
// and Newton's cycle then lies beyond tol of every iterate so far. False when the orbit leaves the
// escape radius or passes maxIterations first: then the cycle is not shown to be this orbit's.
template <typename Map>
bool reachCycle(const Map& f, std::vector<typename Map::Point>& orbit, double tol,
                double escapeRadius, int maxIterations, const typename Map::Cycle& cycle) {
    for (const auto& z : orbit)
        if (distanceToCycle<Map>(z, cycle.points) <= tol) return true;
    while (distanceToCycle<Map>(orbit.back(), cycle.points) > tol) {
        if (int(orbit.size()) - 1 >= maxIterations) return false;
        orbit.push_back(f(orbit.back()));
        if (!(Map::size(orbit.back()) <= escapeRadius)) return false;
    }
    return true;
}

// The first iterate on the cycle (within tol): the orbit's preperiod. The cycle is rotated so
// that its points[0] is the point the orbit meets there. Some iterate is on the cycle
// (reachCycle).
template <typename Map>
int meetCycle(const Map& f, const std::vector<typename Map::Point>& orbit, double tol,
              typename Map::Cycle& cycle) {
    int hit = 0;
    while (distanceToCycle<Map>(orbit[size_t(hit)], cycle.points) > tol)
        ++hit;
    for (size_t k = 0; k < cycle.points.size(); ++k) {
        if (Map::size(orbit[hit] - cycle.points[k]) <= tol) {
            std::rotate(cycle.points.begin(), cycle.points.begin() + std::ptrdiff_t(k),
                        cycle.points.end());
            cycle.jacobian = jacobianOfCycle(f, cycle.points);
            break;
        }
    }
    return hit;
}

// The fate of an orbit that meets its cycle at iterate `hit`: periodic where it starts on the
// cycle; preperiodic where the governing class repels (or is a saddle) or where the orbit jumps
// onto the cycle; attracted otherwise.
template <typename Map, typename Result>
void decideFate(const std::vector<typename Map::Point>& orbit, int hit, double scale,
                Result& result) {
    const auto& cycle = *result.cycle;
    const double tol = result.tolerance;
    Stability stability = result.governingClass.stability;
    if (hit == 0) {
        result.fate = OrbitFate::Periodic;
    } else if (stability == Stability::Repelling || stability == Stability::Saddle) {
        result.fate = OrbitFate::Preperiodic;
    } else {
        bool jumped = distanceToCycle<Map>(orbit[hit], cycle.points) <= 1e-3 * tol &&
                      distanceToCycle<Map>(orbit[hit - 1], cycle.points) > 1e-4 * scale;
        result.fate = jumped ? OrbitFate::Preperiodic : OrbitFate::Attracted;
        if (stability == Stability::Neutral) {
            result.unsure = true;
            result.note =
                "neutral cycle: landing on it and slow convergence to it cannot be "
                "told apart numerically";
        }
    }
}

template <typename Map>
typename Map::Cycle cycleOf(const Map& f, const typename Map::Point& start, int period) {
    typename Map::Cycle cycle;
    cycle.points.push_back(start);
    for (int k = 1; k < period; ++k)
        cycle.points.push_back(f(cycle.points.back()));
    for (int k = 0; k < period; ++k) {
        const auto& w = cycle.points[k];
        cycle.residual = std::max(cycle.residual, Map::size(iterate(f, w, period) - w));
    }
    cycle.jacobian = jacobianOfCycle(f, cycle.points);
    cycle.eigenvalues = eigenvalues(cycle.jacobian);
    cycle.classInH = classifyEigenvalues({cycle.eigenvalues.begin(), cycle.eigenvalues.end()});
    f.addMultiplier(cycle);
    return cycle;
}

void QuaternionMap::addMultiplier(Cycle& cycle) const {
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
}

template <typename Map>
BasicOrbitResult<typename Map::Cycle> orbitOf(const Map& f, double escapeRadius,
                                              const typename Map::Point& z0,
                                              const OrbitOptions& options) {
    BasicOrbitResult<typename Map::Cycle> result;
    result.escapeRadius = escapeRadius;
    auto walk = walkOrbit(f, z0, result.escapeRadius, options);
    auto& orbit = walk.orbit;
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
    const auto start = orbit[recurrence.index];
    const auto refined = refineCycle(f, start, recurrence.period, tol);
    int period = exactPeriod(f, refined.value_or(start), recurrence.period, tol);
    result.cycle = cycleOf(f, refined.value_or(start), period);
    auto& cycle = *result.cycle;
    cycle.refined = refined.has_value();
    if (!cycle.refined) {
        result.unsure = true;
        result.note =
            "Newton refinement of the cycle failed (f^n - id is near singular), so "
            "the cycle points are the orbit's own";
    }
    bool orbitInPlane = cycle.multiplier && Map::inPlane(z0, cycle.axis);
    result.governingClass = orbitInPlane ? cycle.complexClass : cycle.classInH;
    result.unsure = result.unsure || result.governingClass.unsure;
    if (!reachCycle(f, orbit, tol, escapeRadius, options.maxIterations, cycle)) {
        result = BasicOrbitResult<typename Map::Cycle>{};
        result.escapeRadius = escapeRadius;
        result.tolerance = tol;
        result.iterations = int(orbit.size()) - 1;
        result.unsure = true;
        result.note = "the orbit recurred with period " + std::to_string(recurrence.period) +
                      " at iteration " + std::to_string(recurrence.index) +
                      " but came no nearer than the tolerance to the cycle found there within " +
                      std::to_string(result.iterations) + " iterations";
        return result;
    }
    result.iterations = int(orbit.size()) - 1;
    result.preperiod = meetCycle(f, orbit, tol, cycle);
    decideFate<Map>(orbit, result.preperiod, walk.scale, result);
    return result;
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
    return cycleOf(QuaternionMap{p}, start, period);
}

OrbitResult analyzeOrbit(const Polynomial& p, const Quaternion& z0, const OrbitOptions& options) {
    return orbitOf(QuaternionMap{p}, p.escapeRadius(), z0, options);
}

template <std::size_t N>
Matrix<N> hypercomplexJacobian(const HypercomplexFormula& formula, const Hypercomplex& z) {
    Matrix<N> m{};
    for (std::size_t a = 0; a < N; ++a) {
        const Hypercomplex column = formula.evaluateWithDerivative(z, basisElement(int(a))).second;
        for (std::size_t i = 0; i < N; ++i)
            m[i][a] = column[i];
    }
    return m;
}

template <std::size_t N>
HypercomplexOrbitResult<N> analyzeHypercomplexOrbit(const HypercomplexFormula& formula,
                                                    double escapeRadius, const Hypercomplex& z0,
                                                    const OrbitOptions& options) {
    if (std::size_t(formula.dimension()) != N)
        throw std::invalid_argument("analyzeHypercomplexOrbit: N is not the algebra's dimension");
    return orbitOf(HypercomplexMap<N>{formula}, escapeRadius, z0, options);
}

AnyOrbitResult analyzeOrbit(const JuliaSet& set, const Hypercomplex& z0,
                            const OrbitOptions& options) {
    if (const auto* quaternion = dynamic_cast<const QuaternionJuliaSet*>(&set))
        return analyzeOrbit(quaternion->polynomial(), Quaternion(z0[0], z0[1], z0[2], z0[3]),
                            options);
    const auto& other = dynamic_cast<const HypercomplexJuliaSet&>(set);
    if (other.formula().dimension() == 4)
        return analyzeHypercomplexOrbit<4>(other.formula(), other.escapeRadius(), z0, options);
    return analyzeHypercomplexOrbit<8>(other.formula(), other.escapeRadius(), z0, options);
}

template Matrix<4> hypercomplexJacobian<4>(const HypercomplexFormula&, const Hypercomplex&);
template Matrix<8> hypercomplexJacobian<8>(const HypercomplexFormula&, const Hypercomplex&);
template HypercomplexOrbitResult<4> analyzeHypercomplexOrbit<4>(const HypercomplexFormula&, double,
                                                                const Hypercomplex&,
                                                                const OrbitOptions&);
template HypercomplexOrbitResult<8> analyzeHypercomplexOrbit<8>(const HypercomplexFormula&, double,
                                                                const Hypercomplex&,
                                                                const OrbitOptions&);

}  // namespace quaternia
