#include "quaternia/fractal/octonion_fold.h"

#include <cmath>

#include "quaternia/algebra/formula.h"

namespace quaternia {

std::optional<OctonionFold> foldOctonion(const std::string& formulaText,
                                         const HypercomplexJuliaSet& set, const Slice& slice) {
    const HypercomplexFormula& formula = set.formula();
    if (!algebraRules(formula.algebra()).foldsOntoQuaternions || formula.transcendental())
        return std::nullopt;
    // The a_k, and that c is only in the constant term: the same terms for two values of c.
    std::optional<Polynomial> without, with;
    try {
        const Formula parsed = Formula::parse(formulaText);
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
    // The slice map's value at 0 and its three tangents (affine), their parts orthogonal to 1
    // and u, and an orthonormal basis of the span of those parts.
    const std::array<Hypercomplex, 4> vectors = {slice.fromWorld(Point3d(0, 0, 0)),
                                                 slice.tangents()[0], slice.tangents()[1],
                                                 slice.tangents()[2]};
    auto orthogonalPart = [&](Hypercomplex x) {
        x[0] = 0;
        return x - dotProduct(x, u) * u;
    };
    std::vector<Hypercomplex> basis;
    for (const Hypercomplex& v : vectors) {
        Hypercomplex rest = orthogonalPart(v);
        for (const Hypercomplex& b : basis)
            rest = rest - dotProduct(rest, b) * b;
        const double size = euclideanNorm(rest);
        if (size > 1e-12 * std::max(1.0, euclideanNorm(v))) basis.push_back((1 / size) * rest);
    }
    OctonionFold fold;
    auto row = [&](auto coordinate) {
        return std::array<double, 4>{coordinate(vectors[0]), coordinate(vectors[1]),
                                     coordinate(vectors[2]), coordinate(vectors[3])};
    };
    fold.rows.push_back(row([](const Hypercomplex& x) { return x[0]; }));
    fold.rows.push_back(row([&](const Hypercomplex& x) {
        Hypercomplex im = x;
        im[0] = 0;
        return dotProduct(im, u);
    }));
    for (const Hypercomplex& b : basis)
        fold.rows.push_back(row([&](const Hypercomplex& x) { return dotProduct(x, b); }));
    fold.originOrthogonal = true;
    for (size_t a = 1; a < 4; ++a)
        fold.originOrthogonal =
            fold.originOrthogonal && std::abs(dotProduct(vectors[0], vectors[a])) <= 1e-12;
    std::vector<Term> terms;
    for (const Term& term : without->terms())
        if (term.degree() > 0) terms.push_back(term);
    terms.push_back(Term{{Quaternion(constant[0], length, 0, 0)}});
    fold.polynomial = Polynomial(std::move(terms));
    return fold;
}

}  // namespace quaternia
