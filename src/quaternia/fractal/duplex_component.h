// One duplex component of a bicomplex polynomial (hypercomplex_julia.h): a complex polynomial P
// of degree d, and a lower bound for the distance from a point w to the part of K_N it allows,
// that holds whether or not P's filled Julia set is connected (issue 43; docs/methods.md, Other
// algebras).
//
// The escape-time estimate 0.5 |w_M| ln|w_M| / |w'_M| is G / (2 |grad G|) for the Green's
// function G, and bounds the distance to K because the inverse of Boettcher's map phi is
// univalent on |zeta| > 1 (Koebe). That needs K connected. Where a critical point escapes, phi
// is univalent only on {G > G*}, G* the largest G at a critical point: the disc about
// zeta = phi(w) that the inverse takes univalently shrinks from radius |zeta| - 1 to
// |zeta| - e^(G*), and the estimate with it, by (e^G - e^(G*)) / (e^G - 1). Below G* (the dust's
// fat neighbourhood, where orbits pass near escaping critical points and |w'| nearly vanishes)
// no such bound exists; there the first iterate w_j with G(w_j) = d^j G(w) >= 2 G* gets the
// shrunken bound r_j, and a disc about w is pulled back to it exactly: a disc of radius e about
// w_k maps into the disc of radius Q(|w_k| + e) - Q(|w_k|) about w_{k+1}, Q the polynomial of
// the coefficients' moduli, so e_k, the largest e with Q(|w_k| + e) - Q(|w_k|) <= e_{k+1},
// keeps the disc about w off {G <= G* / d^j}. That set holds every point whose orbit stays within
// rho for N iterates as long as G* / d^j >= G_Q(rho) / d^(N-1) (G_Q(rho), the majorant's
// Green's function at rho, bounds G on the disc of radius rho); beyond that the bound is 0.
#pragma once

#include <complex>
#include <vector>

#include "quaternia/algebra/complex_polynomial.h"

namespace quaternia {

class DuplexComponent {
  public:
    using Complex = std::complex<double>;
    DuplexComponent() = default;
    // P's coefficients (lowest degree first, degree >= 2), its escape radius, and rho: the
    // largest modulus a point of K_N may give the component (sqrt(2) times the bailout).
    DuplexComponent(std::vector<Complex> coefficients, double escapeRadius, double rho);

    // G*: 0 where every critical orbit stays bounded (K connected), else the largest G there.
    double criticalPotential() const { return criticalPotential_; }
    bool connected() const { return criticalPotential_ == 0; }
    int degree() const { return degree_; }
    // ln|a_d| / (d - 1): G(w) = (ln|w_M| + this) / d^M for large |w_M|.
    double leadLog() const { return leadLog_; }
    // P is a_d w^d + a_0 (the duplex form of s z^d + c): Q's inverse growth has a closed form.
    bool binomial() const { return binomial_; }
    double leadModulus() const { return moduli_.back(); }
    // The deepest pull-back, j, that keeps K_N inside {G <= G* / d^j}: N - 1 - log_d(G_Q(rho) /
    // G*) (the header comment); -1 where K is connected.
    double pullBackLimit(int maxIterations) const;
    // The largest e >= 0 with Q(r + e) - Q(r) <= target, for the binomial Q(r) = A r^d + B:
    // e = x / sum_{m < d} s^m r^(d-1-m) with x = target / A and s = (r^d + x)^(1/d), a form
    // without the cancellation of s - r (the lanes take it in float).
    static double binomialGrowthInverse(double r, double x, int degree);
    // (e^G - e^(G*)) / (e^G - 1) for G > G*: the factor Koebe's bound loses to the escaping
    // critical points (1 where K is connected).
    double koebeFactor(double potential) const;
    // The lower bound for the distance from w0 to the component's part of K_N, for a
    // disconnected K: the escape-time estimate times koebeFactor where G(w0) >= 2 G*, the
    // pull-back of the header comment below that, and 0 where the orbit does not leave the
    // escape radius within maxIterations iterates (the component may be in K_N).
    double distance(Complex w0, int maxIterations) const;

  private:
    double majorant(double r) const;  // Q(r)
    // The largest e >= 0 with Q(r + e) - Q(r) <= target.
    double inverseGrowth(double r, double target) const;

    ComplexPolynomial polynomial_;
    std::vector<double> moduli_;  // |a_k|: Q's coefficients
    int degree_ = 2;
    double escapeRadius_ = 2, rho_ = 4;
    double leadLog_ = 0;
    double criticalPotential_ = 0;
    double boundPotential_ = 0;  // G_Q(rho)
    bool binomial_ = false;
};

}  // namespace quaternia
