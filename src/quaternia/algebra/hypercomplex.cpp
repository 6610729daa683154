// The multiplication tables of hypercomplex.h, each made from its algebra's definition: the
// defining relations for bicomplex numbers and coquaternions, and for the 8-dimensional algebras
// their formulas on pairs of quaternions (Hamilton's product, quaternion.h) applied to the basis.
#include "quaternia/algebra/hypercomplex.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "quaternia/algebra/quaternion.h"

namespace quaternia {

namespace {

struct AlgebraInfo {
    Algebra algebra;
    std::string_view name;
    int dimension;
    AlgebraArithmetic rules;  // productBound, multiplicativeNorm, transcendentalFunctions, rewrites
};

// sqrt(2), the product bound of the three algebras whose norm is not multiplicative, is
// std::numbers::sqrt2: the correctly rounded value, which std::sqrt(2.0) also returns.
constexpr std::array<AlgebraInfo, 5> kAlgebras = {{
    {Algebra::kQuaternion, "quaternion", 4, {1.0, true, false, true}},
    {Algebra::kBicomplex, "bicomplex", 4, {std::numbers::sqrt2, false, true, false}},
    {Algebra::kCoquaternion, "coquaternion", 4, {std::numbers::sqrt2, false, false, false}},
    {Algebra::kBiquaternion, "biquaternion", 8, {std::numbers::sqrt2, false, false, false}},
    {Algebra::kOctonion, "octonion", 8, {1.0, true, false, false}},
}};

const AlgebraInfo& info(Algebra algebra) {
    for (const AlgebraInfo& a : kAlgebras)
        if (a.algebra == algebra) return a;
    throw std::logic_error("unknown algebra");
}

Quaternion quaternionPart(const Hypercomplex& a, int first) {
    return {a[first], a[first + 1], a[first + 2], a[first + 3]};
}

Hypercomplex fromPair(const Quaternion& a, const Quaternion& b) {
    return {a.w, a.x, a.y, a.z, b.w, b.x, b.y, b.z};
}

// The product of whole elements by each 8-dimensional algebra's formula on quaternion pairs.
Hypercomplex pairProduct(Algebra algebra, const Hypercomplex& p, const Hypercomplex& q) {
    const Quaternion a = quaternionPart(p, 0), b = quaternionPart(p, 4);
    const Quaternion c = quaternionPart(q, 0), d = quaternionPart(q, 4);
    if (algebra == Algebra::kBiquaternion) return fromPair(a * c - b * d, a * d + b * c);
    return fromPair(a * c - conj(d) * b, d * a + b * conj(c));  // octonions
}

// A 4-dimensional algebra from the squares of i, j, k and the products ij, jk, ki, ji, kj, ik,
// each as (sign, index).
using Relation = std::pair<int, int>;
void setFourDimensional(
    std::array<std::array<BasisProduct, kMaxAlgebraDimension>, kMaxAlgebraDimension>& products,
    const std::array<int, 3>& squares, Relation ij, Relation jk, Relation ki, Relation ji,
    Relation kj, Relation ik) {
    for (int n = 0; n < 4; ++n) {
        products[0][n] = {std::int8_t(n), 1};
        products[n][0] = {std::int8_t(n), 1};
    }
    for (int n = 1; n < 4; ++n)
        products[n][n] = {0, std::int8_t(squares[n - 1])};
    auto set = [&](int i, int j, Relation r) {
        products[i][j] = {std::int8_t(r.second), std::int8_t(r.first)};
    };
    set(1, 2, ij), set(2, 3, jk), set(3, 1, ki), set(2, 1, ji), set(3, 2, kj), set(1, 3, ik);
}

}  // namespace

const std::vector<Algebra>& allAlgebras() {
    static const std::vector<Algebra> algebras = [] {
        std::vector<Algebra> all;
        for (const AlgebraInfo& a : kAlgebras)
            all.push_back(a.algebra);
        return all;
    }();
    return algebras;
}

std::string_view algebraName(Algebra algebra) {
    return info(algebra).name;
}

std::optional<Algebra> algebraFromName(std::string_view name) {
    for (const AlgebraInfo& a : kAlgebras)
        if (a.name == name) return a.algebra;
    return std::nullopt;
}

int algebraDimension(Algebra algebra) {
    return info(algebra).dimension;
}

const AlgebraArithmetic& algebraArithmetic(Algebra algebra) {
    return info(algebra).rules;
}

const MultiplicationTable& MultiplicationTable::of(Algebra algebra) {
    static const std::array<MultiplicationTable, kAlgebras.size()> tables = [] {
        auto make = [](Algebra kind) {
            MultiplicationTable t(kind, algebraDimension(kind));
            switch (kind) {
                case Algebra::kQuaternion:
                    setFourDimensional(t.products_, {-1, -1, -1}, {1, 3}, {1, 1}, {1, 2}, {-1, 3},
                                       {-1, 1}, {-1, 2});
                    break;
                case Algebra::kBicomplex:
                    setFourDimensional(t.products_, {-1, -1, 1}, {1, 3}, {-1, 1}, {-1, 2}, {1, 3},
                                       {-1, 1}, {-1, 2});
                    break;
                case Algebra::kCoquaternion:
                    setFourDimensional(t.products_, {-1, 1, 1}, {1, 3}, {-1, 1}, {1, 2}, {-1, 3},
                                       {1, 1}, {-1, 2});
                    break;
                case Algebra::kBiquaternion:
                case Algebra::kOctonion:
                    for (int i = 0; i < 8; ++i) {
                        for (int j = 0; j < 8; ++j) {
                            const Hypercomplex e =
                                pairProduct(kind, basisElement(i), basisElement(j));
                            for (int n = 0; n < 8; ++n)
                                if (e[n] != 0)
                                    t.products_[i][j] = {std::int8_t(n), std::int8_t(e[n])};
                        }
                    }
                    break;
            }
            t.index();
            return t;
        };
        return std::array<MultiplicationTable, kAlgebras.size()>{
            make(Algebra::kQuaternion), make(Algebra::kBicomplex), make(Algebra::kCoquaternion),
            make(Algebra::kBiquaternion), make(Algebra::kOctonion)};
    }();
    return tables[static_cast<size_t>(algebra)];
}

void MultiplicationTable::index() {
    for (int i = 0; i < dimension_; ++i) {
        for (int j = 0; j < dimension_; ++j) {
            const BasisProduct e = products_[i][j];
            outputPartner_[e.index][i] = std::int8_t(j);
            outputSign_[e.index][i] = e.sign;
        }
    }
}

template <int Dimension>
Hypercomplex MultiplicationTable::multiplyFixed(const Hypercomplex& a,
                                                const Hypercomplex& b) const {
    Hypercomplex product{};
    for (int k = 0; k < Dimension; ++k) {
        double sum = 0;
        for (int i = 0; i < Dimension; ++i)
            sum += outputSign_[k][i] * (a[i] * b[outputPartner_[k][i]]);
        product[k] = sum;
    }
    return product;
}

Hypercomplex MultiplicationTable::multiply(const Hypercomplex& a, const Hypercomplex& b) const {
    return dimension_ == 4 ? multiplyFixed<4>(a, b) : multiplyFixed<8>(a, b);
}

Hypercomplex MultiplicationTable::power(const Hypercomplex& z, int n) const {
    Hypercomplex p = realElement(1);
    for (int k = 0; k < n; ++k)
        p = multiply(z, p);
    return p;
}

Hypercomplex basisElement(int index) {
    Hypercomplex e{};
    e[index] = 1;
    return e;
}

Hypercomplex realElement(double r) {
    Hypercomplex e{};
    e[0] = r;
    return e;
}

Hypercomplex operator+(const Hypercomplex& a, const Hypercomplex& b) {
    Hypercomplex sum;
    for (int n = 0; n < kMaxAlgebraDimension; ++n)
        sum[n] = a[n] + b[n];
    return sum;
}

Hypercomplex operator-(const Hypercomplex& a, const Hypercomplex& b) {
    Hypercomplex difference;
    for (int n = 0; n < kMaxAlgebraDimension; ++n)
        difference[n] = a[n] - b[n];
    return difference;
}

Hypercomplex operator*(double s, const Hypercomplex& a) {
    Hypercomplex scaled;
    for (int n = 0; n < kMaxAlgebraDimension; ++n)
        scaled[n] = s * a[n];
    return scaled;
}

std::array<std::complex<double>, 2> duplexForm(const Hypercomplex& q) {
    return {std::complex<double>(q[0] - q[3], q[1] + q[2]),
            std::complex<double>(q[0] + q[3], q[1] - q[2])};
}

Hypercomplex fromDuplexForm(const std::complex<double>& a, const std::complex<double>& b) {
    return {0.5 * (a.real() + b.real()),
            0.5 * (a.imag() + b.imag()),
            0.5 * (a.imag() - b.imag()),
            0.5 * (b.real() - a.real()),
            0,
            0,
            0,
            0};
}

double normSquared(const Hypercomplex& a) {
    double sum = 0;
    for (double x : a)
        sum += x * x;
    return sum;
}

double dotProduct(const Hypercomplex& a, const Hypercomplex& b) {
    double sum = 0;
    for (size_t n = 0; n < a.size(); ++n)
        sum += a[n] * b[n];
    return sum;
}

double euclideanNorm(const Hypercomplex& a) {
    double sum = 0;
    for (double v : a)
        sum += v * v;
    return std::sqrt(sum);
}

}  // namespace quaternia
