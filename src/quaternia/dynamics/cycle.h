// Cycles and their multipliers (seed paper section 2.2; docs/facts.md, Cycles and multipliers of
// z^2 + c, and Cycles of z^2 + c in H). A cycle z_0 -> z_1 -> ... -> z_{n-1} -> z_0 of a complex
// map has the multiplier lambda = (f^n)'(z_0) = prod f'(z_k); a cycle of a quaternion map has the
// 4x4 Jacobian of f^n, the product of the Jacobians of p at the cycle points, and its eigenvalues;
// in the other algebras of hypercomplex.h the Jacobian is 4x4 or 8x8, as their dimension.
#pragma once

#include <array>
#include <complex>
#include <string>
#include <vector>

#include "quaternia/algebra/polynomial.h"
#include "quaternia/algebra/quaternion.h"

namespace quaternia {

// Superattracting |lambda| = 0, attracting < 1, neutral = 1, repelling > 1 (seed paper 2.2);
// in H a saddle has some eigenvalues inside the unit circle and some outside.
enum class Stability { Superattracting, Attracting, Neutral, Repelling, Saddle };

std::string toString(Stability stability);

struct Classification {
    Stability stability = Stability::Neutral;
    // The deciding modulus lies within kUnsureBand of a boundary (0 or 1) without being within
    // kClassTolerance of it: rounding in the multiplier could change the class.
    bool unsure = false;
};

// |lambda| within this of 0 is superattracting, within this of 1 neutral. Multipliers computed
// from a refined cycle carry errors of a few ulps times the cycle's condition; 1e-9 absorbs them
// for the short cycles the tools look at.
inline constexpr double kClassTolerance = 1e-9;
inline constexpr double kUnsureBand = 1e-6;

Classification classifyMultiplier(std::complex<double> lambda);
// The class in H from all eigenvalues of the Jacobian of f^n: superattracting if all are ~0,
// attracting if all are inside the unit circle, repelling if all outside, saddle if some are
// inside and some outside, neutral if the largest is ~1 and none is outside. When the smallest
// is ~1 and some are outside, the cycle is weakly repelling: repelling, marked unsure.
Classification classifyEigenvalues(const std::vector<std::complex<double>>& eigenvalues);

// Row-major real N x N matrix on the coordinates of an algebra: N = 4 for H, (w, x, y, z), and
// the 4-component algebras; 8 for the 8-component ones (hypercomplex.h).
template <std::size_t N>
using Matrix = std::array<std::array<double, N>, N>;
using Matrix4 = Matrix<4>;
using Matrix8 = Matrix<8>;

template <std::size_t N>
Matrix<N> identityMatrix();
inline Matrix4 identityMatrix4() {
    return identityMatrix<4>();
}
template <std::size_t N>
Matrix<N> operator*(const Matrix<N>& a, const Matrix<N>& b);
// The Jacobian of p at z: column a is the directional derivative p.derivative(z, e_a).
Matrix4 jacobian(const Polynomial& p, const Quaternion& z);
// The Jacobian of f^n at cycle[0]: J(cycle[n-1]) ... J(cycle[1]) J(cycle[0]) (chain rule).
Matrix4 cycleJacobian(const Polynomial& p, const std::vector<Quaternion>& cycle);
// The N eigenvalues, by Hessenberg reduction and a complex QR iteration with Wilkinson
// shifts, sorted by decreasing modulus, then real part, then imaginary part (moduli and real
// parts compared to 12 decimals). N is 4 or 8 (instantiated in cycle.cpp).
template <std::size_t N>
std::array<std::complex<double>, N> eigenvalues(const Matrix<N>& m);
// Solves m x = b by Gaussian elimination with partial pivoting; false when m is singular to
// working precision (a pivot below 1e-14 times the largest entry). N is 4 or 8.
template <std::size_t N>
bool solve(Matrix<N> m, std::array<double, N> b, std::array<double, N>& x);

}  // namespace quaternia
