// The plain-C++ side of march_lanes.h: flattening a Fractal for the lanes, and the batches.
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <optional>

#include "quaternia/fractal/octonion_fold.h"
#include "quaternia/render/lanes/march_lanes.h"

#include "quaternia/fractal/algebra_rules.h"

namespace quaternia {

namespace {

std::array<double, 4> components(const Quaternion& q) {
    return {q.w, q.x, q.y, q.z};
}

Quaternion quaternionOf(const std::array<double, 4>& a) {
    return Quaternion(a[0], a[1], a[2], a[3]);
}

// p(z) = p0 z p1 z p2 + c iterated as w = p1 z: w <- p1 p0 z p1 z p2 + p1 c = A(w^2) + p1 c, with
// A(s) = (p1 p0 p1^-1) s p2, one square and one 4x4 map per iterate instead of three products.
// z -> p1 z is |p1| times a rotation of R^4, so the orbits correspond with every radius times
// |p1|: the bailout, the escape radius and the estimate's radius scale by |p1|, and the estimate
// takes |z|^2 = |w|^2 / |p1|^2 (normSquaredScale); escapes, iteration counts, the boundary and
// the estimate are the scalar reference's (docs/methods.md, Single quadratic terms). The
// derivative bound is the conjugate's, P'(r) = 2 |p0| |p2| r, which at |w| = |p1| |z| equals the
// gain of z's, so the bound of |w'| is that of |z'| all along (Dw_n[p1 h] = p1 Dz_n[h]).
void iterateConjugate(LaneFractal& lanes, const QuadraticTerm& term) {
    const Quaternion& p1 = term.middle;
    const double n2 = normSquared(p1);
    const Quaternion left = p1 * term.left * inverse(p1);
    std::array<double, 16> map{};
    const Quaternion basis[4] = {Quaternion(1), kUnitI, kUnitJ, kUnitK};
    for (int column = 0; column < 4; ++column) {
        const std::array<double, 4> image = components(left * basis[column] * term.right);
        for (int row = 0; row < 4; ++row)
            map[size_t(4 * row + column)] = image[size_t(row)];
    }
    const Polynomial conjugate(
        {Term{{left, Quaternion(1), term.right}}, Term{{p1 * term.constant}}});
    lanes.squareMap = map;
    lanes.program =
        std::make_shared<const FormulaProgram>(FormulaProgram::fromPolynomial(conjugate));
    lanes.derivativeBound = conjugate.derivativeNormBoundCoefficients();
    lanes.c = components(p1 * term.constant);
    lanes.origin = components(p1 * quaternionOf(lanes.origin));
    for (auto& axis : lanes.axes)
        axis = components(p1 * quaternionOf(axis));
    lanes.bailoutSquared *= n2;
    lanes.escapeRadiusSquared *= n2;
    lanes.normSquaredScale = 1 / n2;
}

}  // namespace

LaneFractal LaneFractal::from(const Fractal& fractal, Precision precision,
                              LaneCoordinates coordinates) {
    const QuaternionJuliaSet& set = *fractal.setAs<QuaternionJuliaSet>();
    LaneFractal lanes;
    const Polynomial& polynomial = set.polynomial();
    lanes.derivativeBound = polynomial.derivativeNormBoundCoefficients();
    std::optional<PowerForm> power = polynomial.powerForm();
    if (power && power->degree >= 1 && power->degree <= kMaxLaneDegree) {
        lanes.c = {power->constant.w, power->constant.x, power->constant.y, power->constant.z};
        lanes.scale = power->scale;
        lanes.degree = power->degree;
    } else {
        lanes.program = std::make_shared<const FormulaProgram>(set.program());
        lanes.degree = std::max(1, polynomial.degree());
    }
    if (std::optional<RealForm> real = polynomial.realForm(); real && lanes.degree >= 2) {
        lanes.realCoefficients = real->coefficients;
        lanes.c = {real->constant.w, real->constant.x, real->constant.y, real->constant.z};
        if (lanes.program) {
            // The program withComplexConstant() takes: phi fixes the real coefficients, so it is
            // that of sum a_k z^k + phi(c), phi(c) = Re c + |Im c| i. Made once here, not for
            // every batch of lanes.
            const Quaternion& c = real->constant;
            std::vector<Term> terms;
            for (std::size_t k = 1; k < real->coefficients.size(); ++k) {
                if (real->coefficients[k] == 0) continue;
                Term term;
                term.coefficients.assign(k + 1, Quaternion(1));
                term.coefficients[0] = Quaternion(real->coefficients[k]);
                terms.push_back(std::move(term));
            }
            terms.push_back(
                Term{{Quaternion(c.w, std::sqrt(c.x * c.x + c.y * c.y + c.z * c.z), 0, 0)}});
            lanes.complexConstantProgram = std::make_shared<const FormulaProgram>(
                FormulaProgram::fromPolynomial(Polynomial(terms)));
        }
    }
    const Slice& slice = fractal.slice();
    if (coordinates == LaneCoordinates::Algebra) {
        for (size_t axis = 0; axis < 4; ++axis)
            lanes.axes[axis][axis] = 1;
    } else {
        // The slice map is affine: its value at the origin plus the images of the unit vectors.
        lanes.origin = components(slice.quaternionFromWorld(Point3d(0, 0, 0)));
        for (int axis = 0; axis < 3; ++axis)
            lanes.axes[axis] = components(slice.quaternionTangents()[axis]);
    }
    lanes.maxIterations = set.maxIterations();
    lanes.bailoutSquared = set.bailout() * set.bailout();
    lanes.escapeRadiusSquared = set.escapeRadius() * set.escapeRadius();
    lanes.stepScale = coordinates == LaneCoordinates::Algebra ? 1 : slice.stepScale();
    lanes.precision = precision;
    lanes.boundingRadius = set.bailout();  // |p| <= |s(p)| (slice.h)
    if (std::optional<QuadraticTerm> term = polynomial.quadraticTerm(); term && lanes.program)
        iterateConjugate(lanes, *term);
    return lanes;
}

std::optional<LaneFractal> LaneFractal::fromBicomplex(const Fractal& fractal, Precision precision,
                                                      LaneCoordinates coordinates) {
    const HypercomplexJuliaSet* other = fractal.setAs<HypercomplexJuliaSet>();
    if (!other) return std::nullopt;
    const HypercomplexJuliaSet& set = *other;
    const HypercomplexFormula& formula = set.formula();
    if (!algebraRules(formula.algebra()).duplexForm || formula.transcendental())
        return std::nullopt;
    const double bailoutSquared = set.bailout() * set.bailout();
    Bicomplex bicomplex;
    for (size_t i = 0; i < 2; ++i) {
        bicomplex.coefficients[i] = set.componentCoefficients(i);
        bicomplex.escapeRadiusSquared[i] =
            set.componentEscapeRadius(i) * set.componentEscapeRadius(i);
        bicomplex.criticalPotential[i] = set.component(i).criticalPotential();
        bicomplex.leadLog[i] = set.component(i).leadLog();
        bicomplex.binomial[i] = set.component(i).binomial();
        bicomplex.inverseLead[i] = 1 / set.component(i).leadModulus();
        bicomplex.pullBackLimit[i] = set.component(i).pullBackLimit(set.maxIterations());
        if (!set.component(i).connected()) bicomplex.reference = fractal.sharedSet();
    }
    // Every escape of |q| then has a component beyond its escape radius: |a|^2 <= R_1^2 and
    // |b|^2 <= R_2^2 give |q|^2 <= (R_1^2 + R_2^2) / 2. The cap keeps float lanes' running
    // derivatives finite up to the bailout (larger bailouts take the scalar reference).
    if (2 * bailoutSquared < bicomplex.escapeRadiusSquared[0] + bicomplex.escapeRadiusSquared[1] ||
        set.bailout() > 100)
        return std::nullopt;
    // The slice map (affine, slice.h) followed by the duplex map, linear.
    auto duplex = [](const Hypercomplex& q) {
        const auto [a, b] = duplexForm(q);
        return std::array<double, 4>{a.real(), a.imag(), b.real(), b.imag()};
    };
    LaneFractal lanes;
    const Slice& slice = fractal.slice();
    if (coordinates == LaneCoordinates::Algebra) {
        for (size_t axis = 0; axis < 4; ++axis) {
            Hypercomplex unit{};
            unit[axis] = 1;
            lanes.axes[axis] = duplex(unit);
        }
    } else {
        lanes.origin = duplex(slice.fromWorld(Point3d(0, 0, 0)));
        for (size_t axis = 0; axis < 3; ++axis)
            lanes.axes[axis] = duplex(slice.tangents()[axis]);
    }
    lanes.degree = formula.degree();
    lanes.maxIterations = set.maxIterations();
    lanes.bailoutSquared = lanes.escapeRadiusSquared = bailoutSquared;
    lanes.stepScale = coordinates == LaneCoordinates::Algebra ? 1 : slice.stepScale();
    lanes.precision = precision;
    lanes.boundingRadius = slice.boundingRadius(set.bailout());
    lanes.bicomplex = std::move(bicomplex);
    return lanes;
}

std::optional<LaneFractal> LaneFractal::fromOctonion(const Scene& scene, const Fractal& fractal,
                                                     Precision precision) {
    const HypercomplexJuliaSet* other = fractal.setAs<HypercomplexJuliaSet>();
    if (!other || !algebraRules(other->algebra()).foldsOntoQuaternions) return std::nullopt;
    std::optional<OctonionFold> fold = foldOctonion(scene.fractal.formula, *other, fractal.slice());
    if (!fold) return std::nullopt;
    // The folded formula's lanes, then the fold's rows in place of the slice map.
    const Fractal folded(
        QuaternionJuliaSet(fold->polynomial, scene.fractal.maxIterations, scene.fractal.bailout),
        Slice(SliceSettings{}));
    LaneFractal lanes = from(folded, precision);
    if (lanes.squareMap) return std::nullopt;  // (a conjugate would multiply the rows)
    lanes.origin = {};
    lanes.axes = {};
    lanes.foldRows = {};
    for (size_t r = 0; r < fold->rows.size(); ++r) {
        const std::array<double, 4>& row = fold->rows[r];
        if (r < 4) {
            lanes.origin[r] = row[0];
            for (size_t a = 0; a < 3; ++a)
                lanes.axes[a][r] = row[a + 1];
        } else {
            lanes.foldRows[r - 4] = row;
        }
    }
    lanes.folded = true;
    lanes.stepScale = fractal.slice().stepScale();
    lanes.boundingRadius = fractal.slice().boundingRadius(std::sqrt(lanes.bailoutSquared));
    return lanes;
}

std::optional<LaneFractal> LaneFractal::forScene(const Scene& scene, const Fractal& fractal,
                                                 LaneCoordinates coordinates) {
    if (scene.render.engine != RenderEngine::Simd ||
        scene.render.method != MarchMethod::SphereTracing)
        return std::nullopt;
    const Precision precision = scene.render.precision;
    if (fractal.setAs<QuaternionJuliaSet>()) return from(fractal, precision, coordinates);
    if (std::optional<LaneFractal> lanes = fromBicomplex(fractal, precision, coordinates))
        return lanes;
    if (coordinates == LaneCoordinates::Algebra) return std::nullopt;
    return fromOctonion(scene, fractal, precision);
}

LaneFractal LaneFractal::withComplexConstant() const {
    // (A folded octonion's c is complex already.)
    if (bicomplex || folded || (program && realCoefficients.empty())) return *this;
    const Vector3d imaginary(c[1], c[2], c[3]);
    const double length = std::sqrt(dot(imaginary, imaginary));
    if (!(length > 0)) return *this;  // c is real already
    // An orthonormal, right-handed frame whose first axis is Im c: phi maps v to its
    // coordinates in it.
    const Vector3d first = imaginary / length;
    const Vector3d helper = std::abs(first.x) < 0.6 ? Vector3d(1, 0, 0) : Vector3d(0, 1, 0);
    const Vector3d second = normalize(cross(first, helper));
    const Vector3d third = cross(first, second);
    auto rotate = [&](const std::array<double, 4>& q) {
        const Vector3d v(q[1], q[2], q[3]);
        return std::array<double, 4>{q[0], dot(v, first), dot(v, second), dot(v, third)};
    };
    LaneFractal rotated = *this;
    rotated.origin = rotate(origin);
    for (auto& axis : rotated.axes)
        axis = rotate(axis);
    rotated.c = {c[0], length, 0, 0};
    if (program) rotated.program = complexConstantProgram;
    return rotated;
}

void RayBatch::clear() {
    for (auto* v : {&ox, &oy, &oz, &dx, &dy, &dz, &tNear, &tFar, &spread})
        v->clear();
}

void RayBatch::removeFlagged(const std::vector<uint8_t>& drop) {
    for (auto* v : {&ox, &oy, &oz, &dx, &dy, &dz, &tNear, &tFar, &spread}) {
        if (v->empty()) continue;  // spread is optional
        size_t kept = 0;
        for (size_t r = 0; r < v->size(); ++r) {
            if (!drop[r]) (*v)[kept++] = (*v)[r];
        }
        v->resize(kept);
    }
}

void PointBatch::clear() {
    x.clear(), y.clear(), z.clear(), w.clear();
}

}  // namespace quaternia
