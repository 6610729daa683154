// Complex polynomials, and the complex map that a quaternion polynomial restricts to.
//
// If every coefficient of an eq. 2.10 polynomial lies in one plane C_u = span{1, u} (u a unit
// imaginary quaternion), C_u is invariant and the polynomial acts on it as a complex polynomial
// in x + y i <-> x + y u (docs/facts.md, Complex restriction): the terms commute there, so
// a0 z a1 ... z ak becomes (a0 a1 ... ak) z^k. Complex dynamics (cycles, multipliers, basins,
// the Mandelbrot set) works on that restriction.
#pragma once

#include <complex>
#include <functional>
#include <optional>
#include <vector>

#include "quaternia/algebra/polynomial.h"
#include "quaternia/algebra/quaternion.h"

namespace quaternia {

using Complex = std::complex<double>;

class ComplexPolynomial {
  public:
    ComplexPolynomial() = default;
    // a_0 + a_1 z + ... + a_d z^d; trailing zero coefficients are dropped.
    explicit ComplexPolynomial(std::vector<Complex> coefficients);

    const std::vector<Complex>& coefficients() const { return coefficients_; }
    int degree() const { return int(coefficients_.size()) - 1; }
    Complex evaluate(Complex z) const;    // Horner
    Complex derivative(Complex z) const;  // p'(z), Horner
    ComplexPolynomial derivativePolynomial() const;

  private:
    std::vector<Complex> coefficients_;
};

struct ComplexRestriction {
    ComplexPolynomial polynomial;
    Quaternion axis;  // the unit imaginary u of the plane C_u (i when every coefficient is real)

    Quaternion toQuaternion(Complex z) const { return Quaternion(z.real()) + axis * z.imag(); }
    Complex toComplex(const Quaternion& q) const { return {q.w, dot(q, axis)}; }
};

// The restriction of p to the plane C_u that holds all its coefficients, or nullopt if they do
// not share one plane (then p has no complex restriction and is genuinely quaternionic).
std::optional<ComplexRestriction> restrictToComplexPlane(const Polynomial& p);

// The plane C_u holding q and the axis u (i when q is real); whether a second quaternion lies in
// it is checked with inPlane().
Quaternion planeAxis(const Quaternion& q);
bool inPlane(const Quaternion& q, const Quaternion& axis);

// Aberth-Ehrlich simultaneous iteration for `count` roots of a function given by its Newton
// ratio f/f'. Works for polynomials and for quotients such as f^n(z) - z with lower periods
// divided out, whose ratio is computed without coefficients. Starts on a circle of the given
// radius; stops when every correction is below tolerance times max(1, |z|), or after
// maxIterations (then the result holds the last iterates).
std::vector<Complex> aberthRoots(int count, const std::function<Complex(Complex)>& newtonRatio,
                                 double initialRadius, double tolerance = 1e-14,
                                 int maxIterations = 1000);

// All roots of p, with multiplicity (Aberth-Ehrlich from the Cauchy bound).
std::vector<Complex> polynomialRoots(const ComplexPolynomial& p);

}  // namespace quaternia
