// The bounds pass of program_bounds.h: per register its norm-bound polynomial, degree and
// top-degree minimum, from its operands' (the rules of the former tree pass of
// HypercomplexFormula, instruction by instruction).
#include "quaternia/algebra/program_bounds.h"

#include <algorithm>
#include <cmath>

#include "quaternia/algebra/complex_polynomial.h"

namespace quaternia {
namespace {

using Op = Instruction::Op;

std::vector<double> addBounds(const std::vector<double>& a, const std::vector<double>& b) {
    std::vector<double> sum(std::max(a.size(), b.size()), 0.0);
    for (std::size_t k = 0; k < a.size(); ++k)
        sum[k] += a[k];
    for (std::size_t k = 0; k < b.size(); ++k)
        sum[k] += b[k];
    return sum;
}

std::vector<double> multiplyBounds(const std::vector<double>& a, const std::vector<double>& b,
                                   double kappa) {
    std::vector<double> product(a.size() + b.size() - 1, 0.0);
    for (std::size_t i = 0; i < a.size(); ++i)
        for (std::size_t j = 0; j < b.size(); ++j)
            product[i + j] += kappa * a[i] * b[j];
    return product;
}

std::vector<double> scaled(double s, const std::vector<double>& a) {
    std::vector<double> b(a.size());
    for (std::size_t k = 0; k < a.size(); ++k)
        b[k] = s * a[k];
    return b;
}

// A 4x4 linear map's gain (row by row at m): its Frobenius norm bounds the operator norm. Where
// the norm is multiplicative the map is a product with constants, q x r = |q| |r| times an
// isometry, so every column has norm |q| |r| and half the Frobenius norm is exact, as a bound
// and as the minimum (the quaternions' maps: formula_program.h).
double linearGain(const double* m, bool multiplicative) {
    double sum = 0;
    for (int e = 0; e < 16; ++e)
        sum += m[e] * m[e];
    return multiplicative ? std::sqrt(sum) / 2 : std::sqrt(sum);
}

Quaternion quaternionPart(const Hypercomplex& a) {
    return {a[0], a[1], a[2], a[3]};
}

std::optional<Quaternion> complexAxisOf(const FormulaProgram& program) {
    Quaternion axis = kUnitI;
    for (const Hypercomplex& a : program.elements()) {
        if (imaginaryNorm(quaternionPart(a)) > 0) {
            axis = planeAxis(quaternionPart(a));
            break;
        }
    }
    for (const Hypercomplex& a : program.elements()) {
        for (std::size_t n = 4; n < a.size(); ++n)
            if (a[n] != 0) return std::nullopt;
        if (!inPlane(quaternionPart(a), axis)) return std::nullopt;
    }
    const MultiplicationTable& table = MultiplicationTable::of(program.algebra());
    Hypercomplex square = table.multiply({0, axis.x, axis.y, axis.z, 0, 0, 0, 0},
                                         {0, axis.x, axis.y, axis.z, 0, 0, 0, 0});
    square[0] += 1;
    if (!(euclideanNorm(square) <= 1e-12)) return std::nullopt;
    return axis;
}

}  // namespace

double productBound(Algebra algebra) {
    return algebraArithmetic(algebra).productBound;
}

ProgramBounds analyzeProgram(const FormulaProgram& program) {
    const AlgebraArithmetic& rules = algebraArithmetic(program.algebra());
    const double kappa = rules.productBound;
    const std::vector<Instruction>& code = program.instructions();
    std::vector<std::vector<double>> bounds(code.size());
    std::vector<int> degrees(code.size(), 0);
    // Per register: a lower bound of |top-degree part| on the unit sphere (multiplicative norms).
    std::vector<double> topMinima(code.size(), 0.0);
    ProgramBounds result;
    for (std::size_t n = 0; n < code.size(); ++n) {
        const Instruction& i = code[n];
        const std::size_t a = std::size_t(i.a);
        const std::size_t b = std::size_t(i.op == Op::kSquare ? i.a : i.b);
        switch (i.op) {
            case Op::kZ:
                bounds[n] = {0.0, 1.0};
                degrees[n] = 1;
                topMinima[n] = 1;
                break;
            case Op::kConstant:
                bounds[n] = {euclideanNorm(program.elements()[std::size_t(i.index)])};
                topMinima[n] = bounds[n][0];
                break;
            case Op::kNegate:
                bounds[n] = bounds[a];
                degrees[n] = degrees[a];
                topMinima[n] = topMinima[a];
                break;
            case Op::kAdd:
            case Op::kSubtract: {
                const int da = degrees[a], db = degrees[b];
                const double ta = topMinima[a], tb = topMinima[b];
                bounds[n] = addBounds(bounds[a], bounds[b]);
                degrees[n] = std::max(da, db);
                // Equal degrees: the top parts add and may cancel, |u + v| >= |u| - |v|.
                topMinima[n] = da > db   ? ta
                               : db > da ? tb
                                         : std::max({0.0, ta - bounds[b][std::size_t(db)],
                                                     tb - bounds[a][std::size_t(da)]});
                break;
            }
            case Op::kMultiply:
            case Op::kSquare:
                bounds[n] = multiplyBounds(bounds[a], bounds[b], kappa);
                degrees[n] = degrees[a] + degrees[b];
                topMinima[n] = topMinima[a] * topMinima[b];
                break;
            case Op::kPower:
                bounds[n] = {1.0};
                for (int e = 0; e < i.index; ++e)
                    bounds[n] = e == 0 ? bounds[a] : multiplyBounds(bounds[n], bounds[a], kappa);
                degrees[n] = i.index * degrees[a];
                topMinima[n] = std::pow(topMinima[a], i.index);
                break;
            case Op::kScale: {
                // |r x| = |r| |x| in every algebra: reals scale each component.
                const double r = std::abs(program.factors()[std::size_t(i.index)]);
                bounds[n] = scaled(r, bounds[a]);
                degrees[n] = degrees[a];
                topMinima[n] = r * topMinima[a];
                break;
            }
            case Op::kLinear: {
                const double* m = program.factors().data() + i.index;
                bounds[n] = scaled(linearGain(m, rules.multiplicativeNorm), bounds[a]);
                degrees[n] = degrees[a];
                topMinima[n] = rules.multiplicativeNorm ? linearGain(m, true) * topMinima[a] : 0;
                break;
            }
            case Op::kFunction:
            case Op::kRealPower:
                result.transcendental = true;
                bounds[n] = {0.0};  // no norm bound: transcendental
                break;
        }
    }
    const std::size_t last = std::size_t(program.result());
    result.degree = result.transcendental ? 2 : degrees[last];
    result.normBound = bounds[last];
    result.normBound.resize(std::size_t(result.degree) + 1, 0.0);
    result.topDegreeMinimum = rules.multiplicativeNorm ? topMinima[last] : 0.0;
    if (!result.transcendental) result.complexAxis = complexAxisOf(program);
    return result;
}

double ProgramBounds::derivativeNormBound(double r) const {
    double sum = 0;
    for (int k = degree; k >= 1; --k)
        sum = sum * r + double(k) * normBound[std::size_t(k)];
    return sum;
}

}  // namespace quaternia
