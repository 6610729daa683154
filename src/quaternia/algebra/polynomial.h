// Quaternion polynomials, eq. 2.10 of the seed paper: p(z) = sum of terms a0 z a1 z ... z ak with
// quaternion coefficients on either side of every z. Multiplication in H does not commute, so a
// term keeps all k+1 coefficients in order; z^2 is the term 1 z 1 z 1.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "quaternia/algebra/quaternion.h"

namespace quaternia {

// One term a0 z a1 z ... z ak: coefficients.size() == degree + 1 (a constant has one).
struct Term {
    std::vector<Quaternion> coefficients;
    int degree() const { return int(coefficients.size()) - 1; }
};

// p(z) = s z^d + c with a real scale s: the hot case, iterated with square()/powers and a scalar
// derivative |z'| <- s d |z|^(d-1) |z'| (docs/facts.md, Distance estimate).
struct PowerForm {
    int degree = 0;
    double scale = 1;
    Quaternion constant;
};

// p(z) = sum_k a_k z^k + c with real a_k (index k; a_0 = 0): the polynomials that every rotation
// of the imaginary 3-space commutes with but for c (docs/facts.md, Symmetries). Each iterate
// then stays in span{1, Im z, Im c}, which the float lanes use (estimate_lanes-inl.h).
struct RealForm {
    std::vector<double> coefficients;
    Quaternion constant;
};

// p(z) = left z middle z right + constant: a single term of degree 2 (eq. 2.10's p0 z p1 z p2).
// The SIMD lanes conjugate it by w = middle z (render/lanes/march_lanes.h, LaneFractal).
struct QuadraticTerm {
    Quaternion left, middle, right, constant;
};

class Polynomial {
  public:
    Polynomial() = default;
    // Drops terms with a zero coefficient and sums the constant terms into one.
    explicit Polynomial(std::vector<Term> terms);

    const std::vector<Term>& terms() const { return terms_; }
    int degree() const;  // highest term degree; 0 for a constant

    Quaternion evaluate(const Quaternion& z) const;
    // The derivative of p at z in direction h: for each term, the sum over each of its z's of
    // (the product left of that z) h (the product right of it) (docs/facts.md, Distance estimate).
    Quaternion derivative(const Quaternion& z, const Quaternion& h) const;
    // P'(r) where P(r) = sum over terms of (product of coefficient norms) r^degree: an upper
    // bound on the operator norm of the derivative at any z with |z| = r.
    double derivativeNormBound(double r) const;
    // P'(r)'s coefficients, lowest degree first: entry k multiplies r^k (the SIMD lanes evaluate
    // the bound by Horner's rule from them).
    std::vector<double> derivativeNormBoundCoefficients() const;

    // The polynomial as s z^d + c when it has that form (all coefficients of its one non-constant
    // term real), else nullopt.
    std::optional<PowerForm> powerForm() const;
    // The polynomial as sum_k a_k z^k + c when every coefficient of its non-constant terms is
    // real, else nullopt.
    std::optional<RealForm> realForm() const;
    // The polynomial as left z middle z right + c when its one non-constant term has degree 2,
    // else nullopt.
    std::optional<QuadraticTerm> quadraticTerm() const;

    // m = min over unit u of |P_d(u)|, P_d the top-degree part: a certified lower bound (exact
    // for a single top term: the product of its coefficient norms). 0 when P_d may vanish on
    // the unit sphere.
    double topDegreeMinimum() const;

    // A radius R such that |z| > R implies the orbit of z tends to infinity, so K_p lies in the
    // closed ball of radius R: the positive root of m r^d - sum_{k<d} b_k r^k - r, with b_k the
    // sums of coefficient-norm products of the degree-k terms. For z^2 + c it is exactly
    // R_c = (1 + sqrt(1 + 4|c|)) / 2. Throws UserError("fractal.formula", ...) when the degree
    // is below 2 or m is not certified positive (K may be unbounded).
    double escapeRadius() const;

    // Canonical text that Formula::parse reads back to the same polynomial (17 significant
    // digits), e.g. "z^2 + (0.1+0.2j)*z + (-0.2+0.6i+0.2j+0.2k)", where it is within the
    // parser's 10000 characters: a formula that multiplies out to many terms writes more.
    std::string toString() const;

  private:
    std::vector<Term> terms_;
};

}  // namespace quaternia
