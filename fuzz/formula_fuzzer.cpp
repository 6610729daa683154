// The formula parser (formula.h) and what it hands on: the quaternion polynomial (H) and its
// complex restriction (C_u). A FormulaError is a clean rejection (and a UserError from
// escapeRadius, which refuses some polynomials); everything else is a bug, as is an accepted
// formula that breaks the invariants checked here.
#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include "fuzz/fuzz_check.h"
#include "quaternia/algebra/complex_polynomial.h"
#include "quaternia/algebra/formula.h"
#include "quaternia/algebra/formula_tree.h"
#include "quaternia/algebra/polynomial.h"
#include "quaternia/util/error.h"

namespace {

using namespace quaternia;

// |a| without the squares' underflow: norm() is 0 for coefficients below 1e-154, which made the
// tolerances below 0 for polynomials of such coefficients.
double safeNorm(const Quaternion& a) {
    const double largest = std::max({std::abs(a.w), std::abs(a.x), std::abs(a.y), std::abs(a.z)});
    return largest == 0 || !std::isfinite(largest) ? largest : largest * norm(a / largest);
}

// Sum over terms of the product of coefficient norms times |z|^degree: bounds every
// evaluation's rounding error, relative to the double precision.
double magnitude(const Polynomial& p, double r) {
    double sum = 0;
    for (const Term& term : p.terms()) {
        double product = std::pow(r, term.degree());
        for (const Quaternion& a : term.coefficients)
            product *= safeNorm(a);
        sum += product;
    }
    return sum;
}

// restrictToComplexPlane takes a coefficient to be in the plane when its part off the plane is
// at most 1e-12 max(1, |a|) (inPlane, complex_polynomial.cpp), absolutely for small coefficients,
// and drops that part: the sum over terms of what dropping it from one coefficient of the term
// can change, times |z|^degree.
double planeSlack(const Polynomial& p, double r) {
    double sum = 0;
    std::vector<double> norms;
    for (const Term& term : p.terms()) {
        norms.clear();
        for (const Quaternion& a : term.coefficients)
            norms.push_back(safeNorm(a));
        for (size_t j = 0; j < norms.size(); ++j) {
            double product = std::pow(r, term.degree()) * 1e-12;
            for (size_t i = 0; i < norms.size(); ++i)
                product *= i == j ? std::max(1.0, norms[i]) : norms[i];
            sum += product;
        }
    }
    return sum;
}

// The largest component of a - b: norm() would overflow from 1e154 on.
double difference(const Quaternion& a, const Quaternion& b) {
    double largest = 0;
    for (int k = 0; k < 4; ++k)
        largest = std::max(largest, std::abs(a[k] - b[k]));
    return largest;
}

void checkShape(const Polynomial& p) {
    FUZZ_CHECK(p.degree() >= 0 && p.degree() <= 64);
    FUZZ_CHECK(p.terms().size() <= 4096 + 1);
    for (const Term& term : p.terms()) {
        FUZZ_CHECK(!term.coefficients.empty());
        for (const Quaternion& a : term.coefficients)
            FUZZ_CHECK(isFinite(a) && !(a == Quaternion{}));
    }
}

// toString is documented to read back to the same polynomial, within the parser's length limit.
void checkText(const Polynomial& p) {
    const std::string text = p.toString();
    if (text.size() > 10000) return;
    Polynomial back;
    try {
        back = Formula::parse(text).expand(Quaternion(0));
    } catch (const FormulaError& e) {
        std::fprintf(stderr, "toString gave '%s', which does not parse: %s\n", text.c_str(),
                     e.what());
        FUZZ_CHECK(false);
    }
    FUZZ_CHECK(back.terms().size() == p.terms().size());
    for (size_t t = 0; t < p.terms().size(); ++t)
        FUZZ_CHECK(back.terms()[t].coefficients == p.terms()[t].coefficients);
}

// On the plane C_u the restriction must agree with the quaternion polynomial.
void checkRestriction(const Polynomial& p) {
    const auto restriction = restrictToComplexPlane(p);
    if (!restriction) return;
    FUZZ_CHECK(restriction->polynomial.degree() <= p.degree());
    for (const Complex z : {Complex(0.3, -0.4), Complex(-1.1, 0.7)}) {
        const Quaternion h = p.evaluate(restriction->toQuaternion(z));
        const Quaternion c = restriction->toQuaternion(restriction->polynomial.evaluate(z));
        const double scale = magnitude(p, std::abs(z)), slack = planeSlack(p, std::abs(z));
        if (!std::isfinite(scale + slack) || !isFinite(h) || !isFinite(c)) continue;
        FUZZ_CHECK(difference(h, c) <= 1e-9 * scale + slack + 1e-300);
    }
}

void checkPowerForm(const Polynomial& p) {
    const auto form = p.powerForm();
    if (!form) return;
    const Quaternion z(0.3, -0.2, 0.1, 0.5);
    Quaternion power(1);
    for (int k = 0; k < form->degree; ++k)
        power = power * z;
    const Quaternion expected = power * form->scale + form->constant;
    const Quaternion value = p.evaluate(z);
    const double scale = magnitude(p, norm(z));
    if (std::isfinite(scale) && isFinite(expected) && isFinite(value))
        FUZZ_CHECK(difference(expected, value) <= 1e-9 * scale + 1e-300);
}

// The escape radius, where its certified minimum is exact (one top-degree term): a branch and
// bound with several would cost tens of milliseconds an input.
void checkEscapeRadius(const Polynomial& p) {
    int topTerms = 0;
    const int degree = p.degree();  // a loop over the terms
    for (const Term& term : p.terms())
        topTerms += term.degree() == degree;
    if (topTerms != 1) return;
    try {
        const double radius = p.escapeRadius();
        FUZZ_CHECK(radius > 0);
    } catch (const UserError&) {
    }
}

void checkPolynomial(const Polynomial& p) {
    checkShape(p);
    for (const Quaternion& z : {Quaternion(0), Quaternion(0.3, -0.2, 0.1, 0.5)}) {
        (void)p.evaluate(z);
        (void)p.derivative(z, Quaternion(0, 1, 0, 0));
    }
    (void)p.derivativeNormBound(2);
    checkText(p);
    checkRestriction(p);
    checkPowerForm(p);
    checkEscapeRadius(p);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view text = fuzzText(data, size);
    Formula formula;
    try {
        formula = Formula::parse(text);
    } catch (const FormulaError& e) {
        FUZZ_CHECK(e.column() >= 0 && size_t(e.column()) <= size + 1);
        return 0;
    }
    FUZZ_CHECK(formula.text() == text);
    // Functions and real powers (the bicomplex numbers' only) parse but never expand: refused at
    // their column.
    const FormulaNode* transcendental = firstTranscendental(formula.root());
    try {
        checkPolynomial(formula.expand(Quaternion(-0.2, 0.6, 0.2, 0.2)));
        if (formula.usesC()) checkPolynomial(formula.expand(Quaternion(0)));
        FUZZ_CHECK(transcendental == nullptr);
    } catch (const FormulaError& e) {
        // Expansion limits (column 0), or a function or real power at its column.
        FUZZ_CHECK(e.column() == 0 ||
                   (transcendental != nullptr && e.column() >= 1 && size_t(e.column()) <= size));
    }
    return 0;
}
