// Quaternion polynomials (seed paper eq. 2.10): evaluation, derivative, the escape radius and the
// canonical text form. The certified minimum of the top-degree part, on which the escape radius
// rests, is top_degree_minimum.cpp.
#include "quaternia/algebra/polynomial.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "quaternia/algebra/polynomial_terms.h"
#include "quaternia/algebra/top_degree_minimum.h"
#include "quaternia/util/error.h"
#include "quaternia/util/number_format.h"

namespace quaternia {
namespace {

using terms::evaluateTerm;
using terms::isOne;
using terms::normProduct;
using terms::timesCoefficient;

bool isZero(const Quaternion& q) {
    return q == Quaternion{};
}
bool isReal(const Quaternion& q) {
    return q.x == 0 && q.y == 0 && q.z == 0;
}

// Forward-mode differentiation of a0 z a1 ... z ad: with v the product so far and dv its
// derivative in direction h, appending "z a" gives v z a and (dv z + v h) a. Unrolled, this is
// the sum over each z of (product left of it) h (product right of it) (docs/facts.md,
// Distance estimate).
Quaternion differentiateTerm(const Term& term, const Quaternion& z, const Quaternion& h) {
    const std::vector<Quaternion>& a = term.coefficients;
    Quaternion value = a[0];
    Quaternion derivative;
    for (size_t i = 1; i < a.size(); ++i) {
        derivative = timesCoefficient(derivative * z + value * h, a[i]);
        value = timesCoefficient(value * z, a[i]);
    }
    return derivative;
}

// ---- Text ------------------------------------------------------------------------------------

// "(w+xi+yj+zk)" without its zero components; a real q >= 0 is written bare.
std::string formatCoefficient(const Quaternion& q) {
    if (isReal(q) && q.w > 0) return shortestNumber(q.w);
    std::string text(1, '(');
    for (int k = 0; k < 4; ++k) {
        const double v = q[k];
        if (v == 0) continue;
        if (v < 0 || text.size() > 1) text.push_back(v < 0 ? '-' : '+');
        if (k == 0 || std::abs(v) != 1) text.append(shortestNumber(std::abs(v)));
        if (k > 0) text.push_back("ijk"[k - 1]);
    }
    if (text.size() == 1) text.push_back('0');
    text.push_back(')');
    return text;
}

// The factors of a term joined by '*', with runs of z between unit coefficients as z^n.
std::string formatFactors(const Term& term, const Quaternion& lead) {
    std::vector<std::string> factors;
    if (!isOne(lead)) factors.push_back(formatCoefficient(lead));
    const std::vector<Quaternion>& a = term.coefficients;
    int run = 0;
    for (size_t i = 1; i < a.size(); ++i) {
        ++run;
        if (!isOne(a[i]) || i + 1 == a.size()) {
            factors.push_back(run == 1 ? "z" : "z^" + std::to_string(run));
            run = 0;
            if (!isOne(a[i])) factors.push_back(formatCoefficient(a[i]));
        }
    }
    if (factors.empty()) return "1";
    std::string text = factors[0];
    for (size_t i = 1; i < factors.size(); ++i)
        text += "*" + factors[i];
    return text;
}

}  // namespace

Polynomial::Polynomial(std::vector<Term> terms) {
    Quaternion constant;
    for (Term& term : terms) {
        const std::vector<Quaternion>& a = term.coefficients;
        // A term with a zero coefficient is zero, whatever its other coefficients.
        if (a.empty() || std::any_of(a.begin(), a.end(), isZero)) continue;
        if (term.degree() == 0) {
            constant += a[0];
        } else {
            terms_.push_back(std::move(term));
        }
    }
    if (!isZero(constant)) terms_.push_back(Term{{constant}});  // the constant is kept last
}

int Polynomial::degree() const {
    int d = 0;
    for (const Term& term : terms_)
        d = std::max(d, term.degree());
    return d;
}

Quaternion Polynomial::evaluate(const Quaternion& z) const {
    Quaternion sum;
    for (const Term& term : terms_)
        sum += evaluateTerm(term, z);
    return sum;
}

Quaternion Polynomial::derivative(const Quaternion& z, const Quaternion& h) const {
    Quaternion sum;
    for (const Term& term : terms_)
        sum += differentiateTerm(term, z, h);
    return sum;
}

// Each term's derivative is a sum of d products whose norm is A_T |z|^(d-1) |h| (docs/facts.md,
// Distance estimate).
double Polynomial::derivativeNormBound(double r) const {
    double bound = 0;
    for (const Term& term : terms_) {
        const int d = term.degree();
        double power = 1;  // r^(d-1) by multiplication: cheaper than pow for small d
        for (int k = 1; k < d; ++k)
            power *= r;
        if (d > 0) bound += d * normProduct(term) * power;
    }
    return bound;
}

std::vector<double> Polynomial::derivativeNormBoundCoefficients() const {
    std::vector<double> coefficients(std::size_t(std::max(1, degree())), 0.0);
    for (const Term& term : terms_) {
        const int d = term.degree();
        if (d > 0) coefficients[std::size_t(d - 1)] += d * normProduct(term);
    }
    return coefficients;
}

std::optional<PowerForm> Polynomial::powerForm() const {
    std::optional<PowerForm> form;
    for (const Term& term : terms_) {
        if (term.degree() == 0) continue;  // the constant, summed into one term
        if (form) return std::nullopt;     // a second non-constant term
        PowerForm f;
        f.degree = term.degree();
        for (const Quaternion& a : term.coefficients) {
            if (!isReal(a)) return std::nullopt;
            f.scale *= a.w;
        }
        form = f;
    }
    if (form && !terms_.empty() && terms_.back().degree() == 0) {
        form->constant = terms_.back().coefficients[0];
    }
    return form;
}

std::optional<RealForm> Polynomial::realForm() const {
    RealForm form;
    form.coefficients.assign(std::size_t(std::max(0, degree())) + 1, 0.0);
    for (const Term& term : terms_) {
        if (term.degree() == 0) {
            form.constant = form.constant + term.coefficients[0];
            continue;
        }
        double product = 1;
        for (const Quaternion& a : term.coefficients) {
            if (!isReal(a)) return std::nullopt;
            product *= a.w;
        }
        form.coefficients[std::size_t(term.degree())] += product;
    }
    return form;
}

std::optional<QuadraticTerm> Polynomial::quadraticTerm() const {
    std::optional<QuadraticTerm> form;
    for (const Term& term : terms_) {
        if (term.degree() == 0) continue;  // the constant, summed into one term (as powerForm)
        if (term.degree() != 2 || form) return std::nullopt;
        form = QuadraticTerm{term.coefficients[0], term.coefficients[1], term.coefficients[2], {}};
    }
    if (form && terms_.back().degree() == 0) form->constant = terms_.back().coefficients[0];
    return form;
}

// top_degree_minimum.cpp: exact for one top term, a branch and bound over S^3 for several.
double Polynomial::topDegreeMinimum() const {
    return certifiedTopDegreeMinimum(terms_, degree());
}

// Why R is an escape radius: P_d is homogeneous (real r commutes with every coefficient), so
// for |z| = r, |p(z)| >= |P_d(z)| - sum_{k<d} |P_k(z)| >= m r^d - sum_{k<d} b_k r^k =: g(r),
// and f(r) = g(r) - r. By Descartes' rule f (one sign change) has exactly one positive root
// R, and f > 0 beyond it. So |z| > R gives |p(z)| > |z|: the norms |z_n| increase strictly. If
// they stayed bounded they would converge to some L > R with L >= g(L) > L, a contradiction;
// hence |z_n| tends to infinity. For z^2 + c, f(r) = r^2 - r - |c| and R = (1 + sqrt(1 + 4|c|))/2.
double Polynomial::escapeRadius() const {
    const int d = degree();
    if (d < 2) {
        throw UserError("fractal.formula", "fractal.formula: " + toString() + " has degree " +
                                               std::to_string(d) +
                                               ", below 2; its orbits need not escape");
    }
    const double m = topDegreeMinimum();
    if (!(m > 0)) {
        throw UserError("fractal.formula",
                        "fractal.formula: " + toString() +
                            ": the top-degree part vanishes on the unit sphere (or comes too "
                            "close to 0 to be bounded away from it), so the set may be "
                            "unbounded; give the highest degree a single term, or terms that "
                            "cannot cancel");
    }
    std::vector<double> b(d + 1, 0.0);  // b[k] for k < d; b[1] also holds the "- r"
    for (const Term& term : terms_) {
        if (term.degree() < d) b[term.degree()] += normProduct(term);
    }
    b[1] += 1;
    auto f = [&](double r) {  // Horner: m r^d - sum b_k r^k
        double value = m;
        for (int k = d - 1; k >= 0; --k)
            value = value * r - b[k];
        return value;
    };
    double lo = 0, hi = 1;  // f < 0 on (0, R), f >= 0 from R on: bisect keeping f(hi) >= 0
    while (f(hi) < 0) {
        lo = hi;
        hi *= 2;
        if (!std::isfinite(hi)) {
            throw UserError("fractal.formula",
                            "fractal.formula: " + toString() + ": no finite escape radius");
        }
    }
    for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
        const double mid = (lo + hi) / 2;
        (f(mid) < 0 ? lo : hi) = mid;
    }
    return hi;  // R itself when f(R) is exactly 0, as for z^2 (R = 1)
}

// Terms joined by " + ", or " - " when the leading coefficient is a negative real.
std::string Polynomial::toString() const {
    if (terms_.empty()) return "0";
    std::string text;
    for (const Term& term : terms_) {
        Quaternion lead = term.coefficients[0];
        const bool negative = isReal(lead) && lead.w < 0;
        if (negative) lead = -lead;
        if (!text.empty()) {
            text.append(negative ? " - " : " + ");
        } else if (negative) {
            text.push_back('-');
        }
        text.append(formatFactors(term, lead));
    }
    return text;
}

}  // namespace quaternia