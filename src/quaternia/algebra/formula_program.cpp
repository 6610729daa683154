// The compiler of formula_program.h: one pass over the parse tree, each node becoming at most a
// few instructions, with constants folded and equal instructions shared.
#include "quaternia/algebra/formula_program.h"

#include <array>
#include <map>
#include <optional>
#include <tuple>

#include "quaternia/algebra/formula_tree.h"

namespace quaternia {

namespace {

using Op = Instruction::Op;

bool isReal(const Quaternion& q) {
    return q.x == 0 && q.y == 0 && q.z == 0;
}

class Compiler {
  public:
    explicit Compiler(const Quaternion& c) : c_(c) {}

    int node(const FormulaNode& n) {
        using Kind = FormulaNode::Kind;
        switch (n.kind) {
            case Kind::kConstant:
                return constant(n.value);
            case Kind::kC:
                return constant(c_);
            case Kind::kZ:
                return z();
            case Kind::kSum:
                return add(node(*n.left), node(*n.right));
            case Kind::kDifference:
                return subtract(node(*n.left), node(*n.right));
            case Kind::kNegate:
                return negate(node(*n.left));
            case Kind::kProduct:
                return multiply(node(*n.left), node(*n.right));
            case Kind::kPower:
                return power(node(*n.left), n.exponent);
            case Kind::kFunction:
            case Kind::kRealPower:
                refuseTranscendental(n);
        }
        return constant(Quaternion());
    }

    int constant(const Quaternion& value) {
        for (std::size_t k = 0; k < constants_.size(); ++k)
            if (constants_[k] == value) return emit({Op::kConstant, -1, -1, int(k)});
        constants_.push_back(value);
        return emit({Op::kConstant, -1, -1, int(constants_.size() - 1)});
    }

    int z() { return emit({Op::kZ}); }

    std::vector<Instruction> instructions_;
    std::vector<Quaternion> constants_;
    std::vector<double> factors_;

  private:
    std::optional<Quaternion> value(int r) const {
        if (instructions_[r].op != Op::kConstant) return std::nullopt;
        return constants_[instructions_[r].index];
    }
    bool is(int r, double real) const {
        const auto v = value(r);
        return v && *v == Quaternion(real);
    }

  public:
    int add(int a, int b) {
        if (value(a) && value(b)) return constant(*value(a) + *value(b));
        if (is(a, 0)) return b;
        if (is(b, 0)) return a;
        return emit({Op::kAdd, a, b});
    }
    int subtract(int a, int b) {
        if (value(a) && value(b)) return constant(*value(a) - *value(b));
        if (is(b, 0)) return a;
        if (is(a, 0)) return negate(b);
        return emit({Op::kSubtract, a, b});
    }
    int negate(int a) {
        if (value(a)) return constant(-*value(a));
        return emit({Op::kNegate, a});
    }
    int multiply(int a, int b) {
        if (value(a) && value(b)) return constant(*value(a) * *value(b));
        // A real factor commutes with everything: a scaling of the other factor.
        if (value(a) && isReal(*value(a))) return scale(b, value(a)->w);
        if (value(b) && isReal(*value(b))) return scale(a, value(b)->w);
        // Any other constant factor is a linear map of the other factor (q x, x q), composed
        // with the map that made it, if one did: q z r is one map, not two products.
        if (value(a)) return linear(productMatrix(*value(a), true), b);
        if (value(b)) return linear(productMatrix(*value(b), false), a);
        if (a == b) return emit({Op::kSquare, a});
        return emit({Op::kMultiply, a, b});
    }

  private:
    using Matrix = std::array<double, 16>;  // row by row

    // The matrix of x -> q x (left) or x -> x q: column c is q e_c or e_c q.
    static Matrix productMatrix(const Quaternion& q, bool left) {
        const Quaternion basis[4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
        Matrix m{};
        for (int c = 0; c < 4; ++c) {
            const Quaternion column = left ? q * basis[c] : basis[c] * q;
            m[0 + c] = column.w, m[4 + c] = column.x, m[8 + c] = column.y, m[12 + c] = column.z;
        }
        return m;
    }
    const double* matrixOf(int r) const { return &factors_[instructions_[r].index]; }

    // m applied to register a; where a is itself a linear map of x, the product matrix applied
    // to x.
    int linear(Matrix m, int a) {
        if (instructions_[a].op == Op::kLinear) {
            const double* inner = matrixOf(a);
            Matrix product{};
            for (int r = 0; r < 4; ++r)
                for (int c = 0; c < 4; ++c)
                    for (int k = 0; k < 4; ++k)
                        product[r * 4 + c] += m[r * 4 + k] * inner[k * 4 + c];
            return linear(product, instructions_[a].a);
        }
        const int index = int(factors_.size());
        factors_.insert(factors_.end(), m.begin(), m.end());
        return emit({Op::kLinear, a, -1, index});
    }

    int scale(int a, double factor) {
        if (factor == 0) return constant(Quaternion());
        if (factor == 1) return a;
        if (factor == -1) return negate(a);
        if (instructions_[a].op == Op::kLinear) {  // folded into the map
            Matrix m;
            const double* inner = matrixOf(a);
            for (int e = 0; e < 16; ++e)
                m[e] = factor * inner[e];
            return linear(m, instructions_[a].a);
        }
        std::size_t k = 0;
        while (k < factors_.size() && factors_[k] != factor)
            ++k;
        if (k == factors_.size()) factors_.push_back(factor);
        return emit({Op::kScale, a, -1, int(k)});
    }

  private:
    // x^n by repeated squaring; x^0 = 1, as the expansion has it for 0^0.
    int power(int x, int n) {
        int result = constant(Quaternion(1));
        for (int base = x; n > 0; n >>= 1) {
            if (n & 1) result = multiply(result, base);
            if (n > 1) base = multiply(base, base);
        }
        return result;
    }

    // Appends `i`, or returns the register of an equal instruction already there.
    int emit(Instruction i) {
        const auto key = std::make_tuple(int(i.op), i.a, i.b, i.index);
        const auto [it, inserted] = seen_.emplace(key, int(instructions_.size()));
        if (inserted) instructions_.push_back(i);
        return it->second;
    }

    Quaternion c_;
    std::map<std::tuple<int, int, int, int>, int> seen_;
};

}  // namespace

FormulaProgram FormulaProgram::compile(const Formula& formula, const Quaternion& c) {
    Compiler compiler(c);
    const int result = formula.root() ? compiler.node(*formula.root()) : compiler.constant({});
    return assemble(compiler.instructions_, std::move(compiler.constants_),
                    std::move(compiler.factors_), result);
}

FormulaProgram FormulaProgram::fromPolynomial(const Polynomial& polynomial) {
    Compiler compiler(Quaternion{});
    int sum = compiler.constant({});
    for (const Term& term : polynomial.terms()) {
        // a0 z a1 z ... z ak, left to right. Real coefficients are central: their product
        // scales the term once at the end, and the z's between them make powers that the terms
        // share (z z is a squaring, found again by the next term).
        double factor = 1;
        int product = -1;  // nothing yet: the product is 1
        auto times = [&](int r) { product = product < 0 ? r : compiler.multiply(product, r); };
        for (std::size_t k = 0; k < term.coefficients.size(); ++k) {
            if (k > 0) times(compiler.z());
            const Quaternion& a = term.coefficients[k];
            if (a.x == 0 && a.y == 0 && a.z == 0) {
                factor *= a.w;
            } else {
                times(compiler.constant(a));
            }
        }
        const int one = compiler.constant(Quaternion(1));
        sum = compiler.add(sum, compiler.multiply(compiler.constant(Quaternion(factor)),
                                                  product < 0 ? one : product));
    }
    return assemble(compiler.instructions_, std::move(compiler.constants_),
                    std::move(compiler.factors_), sum);
}

FormulaProgram FormulaProgram::assemble(const std::vector<Instruction>& all,
                                        std::vector<Quaternion> constants,
                                        std::vector<double> factors, int result) {
    // Only what the result needs: folding and powers leave instructions nothing reads.
    std::vector<bool> live(all.size(), false);
    live[result] = true;
    for (int n = result; n >= 0; --n) {
        if (!live[n]) continue;
        if (all[n].a >= 0) live[all[n].a] = true;
        if (all[n].b >= 0) live[all[n].b] = true;
    }
    FormulaProgram program;
    std::vector<int> renumbered(all.size(), -1);
    for (int n = 0; n <= result; ++n) {
        if (!live[n]) continue;
        Instruction i = all[n];
        if (i.a >= 0) i.a = renumbered[i.a];
        if (i.b >= 0) i.b = renumbered[i.b];
        renumbered[n] = int(program.instructions_.size());
        program.instructions_.push_back(i);
    }
    program.constants_ = std::move(constants);
    program.factors_ = std::move(factors);
    program.result_ = renumbered[result];
    return program;
}

int FormulaProgram::count(Instruction::Op op) const {
    int n = 0;
    for (const Instruction& i : instructions_)
        n += i.op == op;
    return n;
}

Quaternion FormulaProgram::evaluate(const Quaternion& z) const {
    std::vector<Quaternion> registers(instructions_.size());
    return runProgram(instructions_, result_, z, constants_.data(), factors_.data(),
                      registers.data());
}

}  // namespace quaternia
