#include "quaternia/algebra/hypercomplex_formula.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>

#include "quaternia/algebra/complex_polynomial.h"
#include "quaternia/algebra/formula_tree.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

std::vector<double> addBounds(const std::vector<double>& a, const std::vector<double>& b) {
    std::vector<double> sum(std::max(a.size(), b.size()), 0.0);
    for (size_t k = 0; k < a.size(); ++k)
        sum[k] += a[k];
    for (size_t k = 0; k < b.size(); ++k)
        sum[k] += b[k];
    return sum;
}

std::vector<double> multiplyBounds(const std::vector<double>& a, const std::vector<double>& b,
                                   double kappa) {
    std::vector<double> product(a.size() + b.size() - 1, 0.0);
    for (size_t i = 0; i < a.size(); ++i)
        for (size_t j = 0; j < b.size(); ++j)
            product[i + j] += kappa * a[i] * b[j];
    return product;
}

Hypercomplex negated(const Hypercomplex& a) {
    return -1.0 * a;
}

using Complex = std::complex<double>;

// f(w) and f'(w) on the principal branches of std::complex.
std::pair<Complex, Complex> complexFunction(FormulaFunction function, const Complex& w) {
    const Complex one(1);
    switch (function) {
        case FormulaFunction::kExp:
            return {std::exp(w), std::exp(w)};
        case FormulaFunction::kLog:
            return {std::log(w), one / w};
        case FormulaFunction::kSin:
            return {std::sin(w), std::cos(w)};
        case FormulaFunction::kCos:
            return {std::cos(w), -std::sin(w)};
        case FormulaFunction::kTan:
            return {std::tan(w), one / (std::cos(w) * std::cos(w))};
        case FormulaFunction::kSinh:
            return {std::sinh(w), std::cosh(w)};
        case FormulaFunction::kCosh:
            return {std::cosh(w), std::sinh(w)};
        case FormulaFunction::kTanh:
            return {std::tanh(w), one / (std::cosh(w) * std::cosh(w))};
        case FormulaFunction::kAsin:
            return {std::asin(w), one / std::sqrt(one - w * w)};
        case FormulaFunction::kAcos:
            return {std::acos(w), -one / std::sqrt(one - w * w)};
        case FormulaFunction::kAtan:
            return {std::atan(w), one / (one + w * w)};
        case FormulaFunction::kAsinh:
            return {std::asinh(w), one / std::sqrt(w * w + one)};
        case FormulaFunction::kAcosh:
            return {std::acosh(w), one / (std::sqrt(w - one) * std::sqrt(w + one))};
        case FormulaFunction::kAtanh:
            return {std::atanh(w), one / (one - w * w)};
        case FormulaFunction::kReciprocal:
            return {one / w, -one / (w * w)};
    }
    return {w, one};
}

}  // namespace

double productBound(Algebra algebra) {
    return algebra == Algebra::kQuaternion || algebra == Algebra::kOctonion ? 1.0 : std::sqrt(2.0);
}

HypercomplexFormula::HypercomplexFormula(const Formula& formula, Algebra algebra,
                                         const Hypercomplex& c)
    : algebra_(algebra),
      dimension_(algebraDimension(algebra)),
      table_(&MultiplicationTable::of(algebra)) {
    if (formula.root() == nullptr)
        throw UserError("fractal.formula", "fractal.formula: the formula has no terms");
    compile(*formula.root(), c);
    degree_ = transcendental_ ? 2 : degrees_.back();
    normBound_ = bounds_.back();
    normBound_.resize(size_t(degree_) + 1, 0.0);
    topDegreeMinimum_ = productBound(algebra) == 1.0 ? topMinima_.back() : 0.0;
}

int HypercomplexFormula::compile(const FormulaNode& node, const Hypercomplex& c) {
    using Kind = FormulaNode::Kind;
    Operation op;
    std::vector<double> bound;
    int degree = 0;
    double top = 0;  // lower bound of |top-degree part| on the unit sphere (multiplicative norms)
    const double kappa = productBound(algebra_);
    auto constant = [&](const Hypercomplex& value) {
        op.kind = Operation::Kind::kConstant;
        op.value = int(constants_.size());
        constants_.push_back(value);
        bound = {euclideanNorm(value)};
        top = bound[0];
    };
    switch (node.kind) {
        case Kind::kConstant:
            constant(Hypercomplex{node.value.w, node.value.x, node.value.y, node.value.z});
            break;
        case Kind::kC:
            constant(c);
            break;
        case Kind::kZ:
            op.kind = Operation::Kind::kZ;
            bound = {0.0, 1.0};
            degree = 1;
            top = 1;
            break;
        case Kind::kNegate:
            op.kind = Operation::Kind::kNegate;
            op.a = compile(*node.left, c);
            bound = bounds_[size_t(op.a)];
            degree = degrees_[size_t(op.a)];
            top = topMinima_[size_t(op.a)];
            break;
        case Kind::kPower: {
            op.kind = Operation::Kind::kPower;
            op.a = compile(*node.left, c);
            op.value = node.exponent;
            bound = {1.0};
            for (int n = 0; n < node.exponent; ++n)
                bound = n == 0 ? bounds_[size_t(op.a)]
                               : multiplyBounds(bound, bounds_[size_t(op.a)], kappa);
            degree = node.exponent * degrees_[size_t(op.a)];
            top = std::pow(topMinima_[size_t(op.a)], node.exponent);
            break;
        }
        case Kind::kFunction:
        case Kind::kRealPower:
            if (algebra_ != Algebra::kBicomplex) refuseTranscendental(node);
            transcendental_ = true;
            op.kind = node.kind == Kind::kFunction ? Operation::Kind::kFunction
                                                   : Operation::Kind::kRealPower;
            op.a = compile(*node.left, c);
            op.value = int(node.function);
            op.real = node.realExponent;
            bound = {0.0};  // no norm bound: transcendental()
            break;
        case Kind::kSum:
        case Kind::kDifference:
        case Kind::kProduct: {
            op.kind = node.kind == Kind::kSum          ? Operation::Kind::kSum
                      : node.kind == Kind::kDifference ? Operation::Kind::kDifference
                                                       : Operation::Kind::kProduct;
            op.a = compile(*node.left, c);
            op.b = compile(*node.right, c);
            const auto& left = bounds_[size_t(op.a)];
            const auto& right = bounds_[size_t(op.b)];
            const int da = degrees_[size_t(op.a)], db = degrees_[size_t(op.b)];
            const double ta = topMinima_[size_t(op.a)], tb = topMinima_[size_t(op.b)];
            if (op.kind == Operation::Kind::kProduct) {
                bound = multiplyBounds(left, right, kappa);
                degree = da + db;
                top = ta * tb;
            } else {
                bound = addBounds(left, right);
                degree = std::max(da, db);
                // Equal degrees: the top parts add and may cancel, |u + v| >= |u| - |v|.
                top = da > db   ? ta
                      : db > da ? tb
                                : std::max({0.0, ta - right[size_t(db)], tb - left[size_t(da)]});
            }
            break;
        }
    }
    operations_.push_back(op);
    bounds_.push_back(std::move(bound));
    degrees_.push_back(degree);
    topMinima_.push_back(top);
    return int(operations_.size()) - 1;
}

template <bool kSlope>
void HypercomplexFormula::run(const Hypercomplex& z, const Hypercomplex& h, Hypercomplex* value,
                              Hypercomplex* slope) const {
    using Kind = Operation::Kind;
    const MultiplicationTable& table = *table_;
    for (size_t n = 0; n < operations_.size(); ++n) {
        const Operation& op = operations_[n];
        const size_t a = size_t(op.a), b = size_t(op.b);
        switch (op.kind) {
            case Kind::kZ:
                value[n] = z;
                if constexpr (kSlope) slope[n] = h;
                break;
            case Kind::kConstant:
                value[n] = constants_[size_t(op.value)];
                if constexpr (kSlope) slope[n] = Hypercomplex{};
                break;
            case Kind::kSum:
                value[n] = value[a] + value[b];
                if constexpr (kSlope) slope[n] = slope[a] + slope[b];
                break;
            case Kind::kDifference:
                value[n] = value[a] - value[b];
                if constexpr (kSlope) slope[n] = slope[a] - slope[b];
                break;
            case Kind::kNegate:
                value[n] = negated(value[a]);
                if constexpr (kSlope) slope[n] = negated(slope[a]);
                break;
            case Kind::kProduct:
                // d(uv) = du v + u dv, in the order written.
                if constexpr (kSlope)
                    slope[n] =
                        table.multiply(slope[a], value[b]) + table.multiply(value[a], slope[b]);
                value[n] = table.multiply(value[a], value[b]);
                break;
            case Kind::kPower: {
                // x^e = x (x (... x)), the derivative by the product rule at each factor.
                Hypercomplex power = realElement(1), powerSlope{};
                for (int e = 0; e < op.value; ++e) {
                    if constexpr (kSlope)
                        powerSlope =
                            table.multiply(slope[a], power) + table.multiply(value[a], powerSlope);
                    power = e == 0 ? value[a] : table.multiply(value[a], power);
                }
                value[n] = power;
                if constexpr (kSlope) slope[n] = powerSlope;
                break;
            }
            case Kind::kFunction:
            case Kind::kRealPower: {
                // The duplex form: f applied to each complex component, and the chain rule
                // f'(A) dA likewise.
                const auto w = duplexForm(value[a]);
                const auto dw = kSlope ? duplexForm(slope[a]) : std::array<Complex, 2>{};
                std::array<Complex, 2> f, df;
                for (size_t i = 0; i < 2; ++i) {
                    const auto [fi, derivative] =
                        op.kind == Kind::kFunction
                            ? complexFunction(FormulaFunction(op.value), w[i])
                            : std::pair{std::pow(w[i], op.real),
                                        op.real * std::pow(w[i], op.real - 1)};
                    f[i] = fi;
                    df[i] = derivative * dw[i];
                }
                value[n] = fromDuplexForm(f[0], f[1]);
                if constexpr (kSlope) slope[n] = fromDuplexForm(df[0], df[1]);
                break;
            }
        }
    }
}

namespace {

// Registers on the stack for the usual short formulas, on the heap past that.
constexpr size_t kStackRegisters = 16;

struct Registers {
    explicit Registers(size_t count) {
        if (count > kStackRegisters) heap.resize(count);
    }
    Hypercomplex* data() { return heap.empty() ? stack.data() : heap.data(); }
    std::array<Hypercomplex, kStackRegisters> stack;  // written before read, one by one
    std::vector<Hypercomplex> heap;
};

}  // namespace

Hypercomplex HypercomplexFormula::evaluate(const Hypercomplex& z) const {
    Registers value(operations_.size());
    run<false>(z, z, value.data(), nullptr);
    return value.data()[operations_.size() - 1];
}

std::pair<Hypercomplex, Hypercomplex> HypercomplexFormula::evaluateWithDerivative(
    const Hypercomplex& z, const Hypercomplex& h) const {
    Registers value(operations_.size()), slope(operations_.size());
    run<true>(z, h, value.data(), slope.data());
    const size_t last = operations_.size() - 1;
    return {value.data()[last], slope.data()[last]};
}

double HypercomplexFormula::derivativeNormBound(double r) const {
    double sum = 0;
    for (int k = degree_; k >= 1; --k)
        sum = sum * r + double(k) * normBound_[size_t(k)];
    return sum;
}

std::optional<Quaternion> HypercomplexFormula::complexAxis() const {
    if (transcendental_) return std::nullopt;
    auto quaternionPart = [](const Hypercomplex& a) { return Quaternion(a[0], a[1], a[2], a[3]); };
    Quaternion axis = kUnitI;
    for (const Hypercomplex& a : constants_) {
        if (imaginaryNorm(quaternionPart(a)) > 0) {
            axis = planeAxis(quaternionPart(a));
            break;
        }
    }
    for (const Hypercomplex& a : constants_) {
        for (size_t n = 4; n < a.size(); ++n)
            if (a[n] != 0) return std::nullopt;
        if (!inPlane(quaternionPart(a), axis)) return std::nullopt;
    }
    Hypercomplex square = table_->multiply({0, axis.x, axis.y, axis.z, 0, 0, 0, 0},
                                           {0, axis.x, axis.y, axis.z, 0, 0, 0, 0});
    square[0] += 1;
    if (!(euclideanNorm(square) <= 1e-12)) return std::nullopt;
    return axis;
}

}  // namespace quaternia
