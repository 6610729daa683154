// The compiler of formula_program.h: one pass over the parse tree, each node becoming at most a
// few instructions, equal instructions shared, and where the algebra's rules allow, constants
// folded and products rewritten.
#include "quaternia/algebra/formula_program.h"

#include <array>
#include <cstring>
#include <map>
#include <optional>
#include <tuple>

#include "quaternia/algebra/formula_tree.h"

namespace quaternia {

namespace {

using Op = Instruction::Op;

Hypercomplex elementOf(const Quaternion& q) {
    return {q.w, q.x, q.y, q.z, 0, 0, 0, 0};
}
Quaternion quaternionOf(const Hypercomplex& a) {
    return {a[0], a[1], a[2], a[3]};
}
bool isReal(const Hypercomplex& a) {
    for (std::size_t n = 1; n < a.size(); ++n)
        if (a[n] != 0) return false;
    return true;
}
bool sameBits(const Hypercomplex& a, const Hypercomplex& b) {
    return std::memcmp(a.data(), b.data(), sizeof(double) * a.size()) == 0;
}

class Compiler {
  public:
    Compiler(Algebra algebra, const Hypercomplex& c)
        : algebra_(algebra),
          rewrites_(algebraArithmetic(algebra).rewritesArithmetic),
          functions_(algebraArithmetic(algebra).transcendentalFunctions),
          table_(MultiplicationTable::of(algebra)),
          c_(c) {}

    // The left operand is compiled first, so that the constants come in the order written
    // (what complexAxis takes its axis from).
    int node(const FormulaNode& n) {
        using Kind = FormulaNode::Kind;
        switch (n.kind) {
            case Kind::kConstant:
                return constant(elementOf(n.value));
            case Kind::kC:
                return constant(c_);
            case Kind::kZ:
                return z();
            case Kind::kSum: {
                const int left = node(*n.left);
                return add(left, node(*n.right));
            }
            case Kind::kDifference: {
                const int left = node(*n.left);
                return subtract(left, node(*n.right));
            }
            case Kind::kNegate:
                return negate(node(*n.left));
            case Kind::kProduct: {
                const int left = node(*n.left);
                return multiply(left, node(*n.right));
            }
            case Kind::kPower:
                return power(node(*n.left), n.exponent);
            case Kind::kFunction:
            case Kind::kRealPower:
                return transcendental(n);
        }
        return constant(Hypercomplex{});
    }

    int constant(const Hypercomplex& value) {
        // Where arithmetic is rewritten, constants equal in value are interchangeable (0 and -0
        // fold alike); elsewhere each keeps the formula's bits.
        for (std::size_t k = 0; k < elements_.size(); ++k)
            if (rewrites_ ? elements_[k] == value : sameBits(elements_[k], value))
                return emit({Op::kConstant, -1, -1, int(k)});
        elements_.push_back(value);
        return emit({Op::kConstant, -1, -1, int(elements_.size() - 1)});
    }

    int z() { return emit({Op::kZ}); }

    std::vector<Instruction> instructions_;
    std::vector<Hypercomplex> elements_;
    std::vector<double> factors_;

  private:
    std::optional<Hypercomplex> value(int r) const {
        if (!rewrites_ || instructions_[r].op != Op::kConstant) return std::nullopt;
        return elements_[instructions_[r].index];
    }
    bool is(int r, double real) const {
        const auto v = value(r);
        return v && *v == realElement(real);
    }
    // The product as the program's evaluation computes it (formula_program_evaluate.cpp):
    // Hamilton's product of quaternion.h for quaternions, the table's otherwise.
    Hypercomplex product(const Hypercomplex& a, const Hypercomplex& b) const {
        if (algebra_ == Algebra::kQuaternion) return elementOf(quaternionOf(a) * quaternionOf(b));
        return table_.multiply(a, b);
    }
    static Hypercomplex negative(const Hypercomplex& a) {
        Hypercomplex n;
        for (std::size_t k = 0; k < a.size(); ++k)
            n[k] = -a[k];
        return n;
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
        if (value(a)) return constant(negative(*value(a)));
        return emit({Op::kNegate, a});
    }
    int multiply(int a, int b) {
        if (value(a) && value(b)) return constant(product(*value(a), *value(b)));
        // A real factor commutes with everything: a scaling of the other factor.
        if (value(a) && isReal(*value(a))) return scale(b, (*value(a))[0]);
        if (value(b) && isReal(*value(b))) return scale(a, (*value(b))[0]);
        // Any other constant factor is a linear map of the other factor (q x, x q), composed
        // with the map that made it, if one did: q z r is one map, not two products. The
        // maps are 4x4: the 4-component algebras only.
        if (table_.dimension() == 4) {
            if (value(a)) return linear(productMatrix(*value(a), true), b);
            if (value(b)) return linear(productMatrix(*value(b), false), a);
        }
        if (a == b) return emit({Op::kSquare, a});
        return emit({Op::kMultiply, a, b});
    }

  private:
    using Matrix = std::array<double, 16>;  // row by row

    // The matrix of x -> q x (left) or x -> x q: column c is q e_c or e_c q.
    Matrix productMatrix(const Hypercomplex& q, bool left) const {
        Matrix m{};
        for (int c = 0; c < 4; ++c) {
            const Hypercomplex basis = basisElement(c);
            const Hypercomplex column = left ? product(q, basis) : product(basis, q);
            for (int r = 0; r < 4; ++r)
                m[r * 4 + c] = column[r];
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
        if (factor == 0) return constant(Hypercomplex{});
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

    // x^n by repeated squaring where arithmetic is rewritten (x^0 = 1, as the expansion has it
    // for 0^0); otherwise one instruction, x (x (... x)) as the table has always taken it.
    int power(int x, int n) {
        if (!rewrites_) return emit({Op::kPower, x, -1, n});
        int result = constant(realElement(1));
        for (int base = x; n > 0; n >>= 1) {
            if (n & 1) result = multiply(result, base);
            if (n > 1) base = multiply(base, base);
        }
        return result;
    }

    // A function or real power: refused (before its operand is compiled, so that the outermost
    // is named) where the algebra has none.
    int transcendental(const FormulaNode& n) {
        if (!functions_) refuseTranscendental(n);
        const int x = node(*n.left);
        if (n.kind == FormulaNode::Kind::kFunction)
            return emit({Op::kFunction, x, -1, int(n.function)});
        std::size_t k = 0;
        while (k < factors_.size() && std::memcmp(&factors_[k], &n.realExponent, sizeof(double)))
            ++k;
        if (k == factors_.size()) factors_.push_back(n.realExponent);
        return emit({Op::kRealPower, x, -1, int(k)});
    }

    // Appends `i`, or returns the register of an equal instruction already there.
    int emit(Instruction i) {
        const auto key = std::make_tuple(int(i.op), i.a, i.b, i.index);
        const auto [it, inserted] = seen_.emplace(key, int(instructions_.size()));
        if (inserted) instructions_.push_back(i);
        return it->second;
    }

    Algebra algebra_;
    bool rewrites_;
    bool functions_;
    const MultiplicationTable& table_;
    Hypercomplex c_;
    std::map<std::tuple<int, int, int, int>, int> seen_;
};

}  // namespace

FormulaProgram FormulaProgram::compile(const Formula& formula, Algebra algebra,
                                       const Hypercomplex& c) {
    Compiler compiler(algebra, c);
    const int result = formula.root() ? compiler.node(*formula.root()) : compiler.constant({});
    return assemble(algebra, compiler.instructions_, std::move(compiler.elements_),
                    std::move(compiler.factors_), result);
}

FormulaProgram FormulaProgram::compile(const Formula& formula, const Quaternion& c) {
    return compile(formula, Algebra::kQuaternion, elementOf(c));
}

FormulaProgram FormulaProgram::fromPolynomial(const Polynomial& polynomial) {
    Compiler compiler(Algebra::kQuaternion, Hypercomplex{});
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
                times(compiler.constant(elementOf(a)));
            }
        }
        const int one = compiler.constant(realElement(1));
        sum = compiler.add(sum, compiler.multiply(compiler.constant(realElement(factor)),
                                                  product < 0 ? one : product));
    }
    return assemble(Algebra::kQuaternion, compiler.instructions_, std::move(compiler.elements_),
                    std::move(compiler.factors_), sum);
}

FormulaProgram FormulaProgram::assemble(Algebra algebra, const std::vector<Instruction>& all,
                                        std::vector<Hypercomplex> elements,
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
    program.algebra_ = algebra;
    std::vector<int> renumbered(all.size(), -1);
    for (int n = 0; n <= result; ++n) {
        if (!live[n]) continue;
        Instruction i = all[n];
        if (i.a >= 0) i.a = renumbered[i.a];
        if (i.b >= 0) i.b = renumbered[i.b];
        renumbered[n] = int(program.instructions_.size());
        program.instructions_.push_back(i);
    }
    for (const Hypercomplex& a : elements)
        program.constants_.push_back(quaternionOf(a));
    program.elements_ = std::move(elements);
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
