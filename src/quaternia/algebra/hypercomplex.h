// The hypercomplex algebras of the seed paper's section 2.3, each as a multiplication table of
// its basis: quaternions (Hamilton), bicomplex numbers (tessarines, POV-Ray's `hypercomplex`),
// coquaternions (split quaternions), biquaternions (complexified quaternions) and octonions
// (Cayley-Dickson). In every one of them the product of two basis elements is plus or minus a
// basis element, so a table of (index, sign) pairs is the whole algebra: the product of two
// elements is sum_ij sign(i, j) a_i b_j e_index(i, j). That one form serves the scalar code and,
// written out for a fixed table, the lanes.
//
// Definitions (components in this order):
// - quaternion (1, i, j, k): i^2 = j^2 = k^2 = ijk = -1 (quaternion.h).
// - bicomplex (1, i, j, k), commutative: i^2 = j^2 = -1, k^2 = +1, ij = k, jk = -i, ik = -j.
//   (x, y, z, w) -> ((x - w) + (y + z) i, (x + w) + (y - z) i) is an isomorphism onto C x C
//   with componentwise operations (POV-Ray's "duplex form").
// - coquaternion (1, i, j, k): i^2 = -1, j^2 = k^2 = +1, ij = -ji = k, jk = -kj = -i,
//   ki = -ik = j (Cockle 1849). The norm w^2 + x^2 - y^2 - z^2 is multiplicative and indefinite.
// - biquaternion (a0..a3, b0..b3) for a + b h, a and b quaternions, h^2 = -1 commuting with
//   everything: (a + b h)(c + d h) = (ac - bd) + (ad + bc) h (Hamilton's biquaternions).
// - octonion (a0..a3, b0..b3) for the pair (a, b) of quaternions: (a, b)(c, d) =
//   (ac - conj(d) b, d a + b conj(c)) (the Cayley-Dickson construction, as in Baez, "The
//   octonions", Bull. AMS 39, 2002, section 2.2). Not associative, but alternative, so z^n is
//   well defined.
#pragma once

#include <array>
#include <complex>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "quaternia/algebra/element.h"

namespace quaternia {

enum class Algebra { kQuaternion, kBicomplex, kCoquaternion, kBiquaternion, kOctonion };

constexpr int kMaxAlgebraDimension = 8;

// Components of an element along the algebra's basis (element.h); those past its dimension are
// zero.
using Hypercomplex = Element<double, kMaxAlgebraDimension>;

// Every algebra, in the order of the enum; names as the scene file spells them.
const std::vector<Algebra>& allAlgebras();
std::string_view algebraName(Algebra algebra);
std::optional<Algebra> algebraFromName(std::string_view name);

// e_i e_j = sign e_index.
struct BasisProduct {
    std::int8_t index = 0;
    std::int8_t sign = 1;
};

class MultiplicationTable {
  public:
    // The table of `algebra`, made once from its definition above.
    static const MultiplicationTable& of(Algebra algebra);

    Algebra algebra() const { return algebra_; }
    int dimension() const { return dimension_; }
    BasisProduct product(int i, int j) const { return products_[i][j]; }
    // The table by output: component k of a b is sum_i outputSign(k, i) a_i b_outputPartner(k, i)
    // (each e_i has one partner e_j with e_i e_j = +-e_k).
    int outputPartner(int k, int i) const { return outputPartner_[k][i]; }
    double outputSign(int k, int i) const { return outputSign_[k][i]; }

    // sum_ij sign(i, j) a_i b_j e_index(i, j).
    Hypercomplex multiply(const Hypercomplex& a, const Hypercomplex& b) const;
    // z^n (n >= 0; z^0 = 1) by repeated multiplication on the left, z (z (... z)): in an
    // alternative algebra every bracketing gives the same power.
    Hypercomplex power(const Hypercomplex& z, int n) const;

  private:
    MultiplicationTable(Algebra algebra, int dimension)
        : algebra_(algebra), dimension_(dimension) {}

    Algebra algebra_;
    int dimension_;
    std::array<std::array<BasisProduct, kMaxAlgebraDimension>, kMaxAlgebraDimension> products_{};
    // The same table by output: component k of a b is sum_i outputSign_[k][i] a_i
    // b_outputPartner_[k][i] (each e_i has one partner e_j with e_i e_j = +-e_k), a loop of
    // dimension^2 multiply-adds without scattered writes (filled by index()).
    std::array<std::array<std::int8_t, kMaxAlgebraDimension>, kMaxAlgebraDimension>
        outputPartner_{};
    std::array<std::array<double, kMaxAlgebraDimension>, kMaxAlgebraDimension> outputSign_{};
    void index();
    template <int Dimension>
    Hypercomplex multiplyFixed(const Hypercomplex& a, const Hypercomplex& b) const;
};

int algebraDimension(Algebra algebra);

// What the formula compiler (formula_program.h) and its bounds analysis (program_bounds.h) may
// assume of an algebra's arithmetic: one row per algebra, so that neither branches on the
// algebra itself.
struct AlgebraArithmetic {
    // kappa with |a b| <= kappa |a| |b| for all a, b: 1 where the norm is multiplicative
    // (quaternions, octonions), sqrt(2) for the bicomplex numbers (duplex form: |q|^2 is half
    // the sum of the two complex norms squared), the biquaternions (Cauchy-Schwarz on the
    // quaternion halves) and the coquaternions (2x2 real matrices, whose Frobenius norm is
    // sqrt(2) |q| and submultiplicative). Each is attained.
    double productBound = 1;
    // |a b| = |a| |b|: the top-degree part of a single term then has a positive minimum on the
    // unit sphere (program_bounds.h, topDegreeMinimum).
    bool multiplicativeNorm = false;
    // Functions and real powers (POV-Ray's julia_fractal functions), through the duplex form.
    bool transcendentalFunctions = false;
    // Whether the compiler may rewrite the formula's arithmetic: fold constant subexpressions
    // and drop sums with 0 and products with 1, turn products with reals into scalings and
    // products with other constants into 4x4 linear maps, and take powers by repeated
    // squaring. Each changes the floating-point result in the last bits (and the norm bounds,
    // which would follow the folded constants), so it is allowed only where the pictures were
    // made so: the quaternions, whose lanes have always run the rewritten program. The other
    // algebras evaluate every product as written, through the multiplication table, z^n as
    // z (z (... z)); the compiler only shares equal subexpressions there, which is exact.
    bool rewritesArithmetic = false;
};
const AlgebraArithmetic& algebraArithmetic(Algebra algebra);

// The basis element e_index.
Hypercomplex basisElement(int index);
// The real number r (r e_0).
Hypercomplex realElement(double r);
Hypercomplex operator+(const Hypercomplex& a, const Hypercomplex& b);
Hypercomplex operator-(const Hypercomplex& a, const Hypercomplex& b);
Hypercomplex operator*(double s, const Hypercomplex& a);
// The Euclidean norm of the components: the escape test's |z| in every algebra.
double euclideanNorm(const Hypercomplex& a);
// The Euclidean inner product of the components.
double dotProduct(const Hypercomplex& a, const Hypercomplex& b);
// Its square, the sum of the squared components.
double normSquared(const Hypercomplex& a);

// A bicomplex number's duplex form ((x - w) + (y + z) i, (x + w) + (y - z) i), an isomorphism
// onto C x C with componentwise operations, and its inverse.
std::array<std::complex<double>, 2> duplexForm(const Hypercomplex& q);
Hypercomplex fromDuplexForm(const std::complex<double>& a, const std::complex<double>& b);

}  // namespace quaternia
