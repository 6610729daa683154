// The one compiler in every algebra: quaternion programs exactly as the quaternion compiler
// made them, the other algebras' programs the formula's operations as written, evaluated
// bit for bit as the parse tree evaluates through the multiplication table.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>

#include "quaternia/algebra/formula.h"
#include "quaternia/algebra/formula_program.h"
#include "quaternia/algebra/formula_tree.h"

namespace quaternia {
namespace {

using Op = Instruction::Op;

std::string number(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", x);
    return text;
}

// Register r as an expression of z and the constants, sharing written out: a form that does not
// depend on the order of independent registers.
std::string expression(const FormulaProgram& p, int r) {
    const Instruction& i = p.instructions()[std::size_t(r)];
    auto operand = [&](int n) { return expression(p, n); };
    switch (i.op) {
        case Op::kZ:
            return "z";
        case Op::kConstant: {
            const Quaternion& q = p.constants()[std::size_t(i.index)];
            return "(" + number(q.w) + " " + number(q.x) + " " + number(q.y) + " " + number(q.z) +
                   ")";
        }
        case Op::kAdd:
            return "add(" + operand(i.a) + " " + operand(i.b) + ")";
        case Op::kSubtract:
            return "subtract(" + operand(i.a) + " " + operand(i.b) + ")";
        case Op::kNegate:
            return "negate(" + operand(i.a) + ")";
        case Op::kMultiply:
            return "multiply(" + operand(i.a) + " " + operand(i.b) + ")";
        case Op::kSquare:
            return "square(" + operand(i.a) + ")";
        case Op::kScale:
            return "scale(" + operand(i.a) + " " + number(p.factors()[std::size_t(i.index)]) + ")";
        case Op::kLinear: {
            std::string m;
            for (int e = 0; e < 16; ++e) {
                if (e > 0) m += ' ';
                m += number(p.factors()[std::size_t(i.index + e)]);
            }
            return "linear(" + operand(i.a) + " [" + m + "])";
        }
        case Op::kPower:
        case Op::kFunction:
        case Op::kRealPower:
            break;
    }
    return "?";
}

TEST(FormulaProgram, QuaternionProgramsAreThoseOfTheQuaternionCompiler) {
    // Written out from the programs of the quaternion compiler before it compiled for every
    // algebra (commit 140b180), with their instruction counts: the same instructions, the
    // same constants, linear maps and scalings, bit for bit.
    struct Case {
        const char* formula;
        int instructions;
        const char* program;
    };
    const std::string c =
        "(-0.20000000000000001 0.59999999999999998 0.20000000000000001 "
        "0.20000000000000001)";
    const Case cases[] = {
        {"z^2 + 0.1*z + c", 6, "add(add(square(z) scale(z 0.10000000000000001)) C)"},
        {"(z + c)^12", 7, "multiply(square(square(add(z C))) square(square(square(add(z C)))))"},
        {"(1+0.2i) z (1-0.1k) z + c", 5,
         "add(multiply(linear(z [1 -0.20000000000000001 0.020000000000000004 "
         "0.10000000000000001 0.20000000000000001 1 -0.10000000000000001 0.020000000000000004 "
         "0.020000000000000004 0.10000000000000001 1 -0.20000000000000001 -0.10000000000000001 "
         "0.020000000000000004 0.20000000000000001 1]) z) C)"},
        {"i*z*j*z + c", 5, "add(multiply(linear(z [0 0 0 1 0 0 -1 0 0 -1 0 0 1 0 0 0]) z) C)"},
        {"(1 + i)(1 - i) z^2 + c", 5, "add(scale(square(z) 2) C)"},
        {"c + z*0", 1, "C"},
        {"-(z^3) - 2 z + c", 8, "add(subtract(negate(multiply(z square(z))) scale(z 2)) C)"},
        {"z^5 - 0.3 z^4 + i z^2 + c", 10,
         "add(add(subtract(multiply(z square(square(z))) scale(square(square(z)) "
         "0.29999999999999999)) linear(square(z) [0 -1 0 0 1 0 0 0 0 0 0 -1 0 0 1 0])) C)"},
        {"(z^2 + c)(z - c) + 0.5", 8, "add(multiply(add(square(z) C) subtract(z C)) (0.5 0 0 0))"},
    };
    for (const Case& k : cases) {
        const FormulaProgram p =
            FormulaProgram::compile(Formula::parse(k.formula), Quaternion(-0.2, 0.6, 0.2, 0.2));
        std::string expected = k.program;
        for (std::size_t at; (at = expected.find('C')) != std::string::npos;)
            expected.replace(at, 1, c);
        EXPECT_EQ(expression(p, p.result()), expected) << k.formula;
        EXPECT_EQ(int(p.instructions().size()), k.instructions) << k.formula;
        EXPECT_EQ(p.algebra(), Algebra::kQuaternion);
    }
}

TEST(FormulaProgram, OtherAlgebrasKeepEveryOperationAsWritten) {
    // No folding, no scalings or maps, powers as one instruction; equal subexpressions shared.
    const Hypercomplex c{-0.2, 0.6, 0.2, 0.2, 0.1, 0, 0.05, 0};
    for (Algebra algebra : {Algebra::kBicomplex, Algebra::kCoquaternion, Algebra::kBiquaternion,
                            Algebra::kOctonion}) {
        const FormulaProgram p = FormulaProgram::compile(
            Formula::parse("(1 + i)(1 - i) z^5 + 0.5 z + 1 z + (z + c)*(z + c) + 0 + c"), algebra,
            c);
        EXPECT_EQ(p.algebra(), algebra);
        EXPECT_EQ(p.count(Op::kPower), 1) << algebraName(algebra);
        EXPECT_EQ(p.count(Op::kScale) + p.count(Op::kLinear), 0) << algebraName(algebra);
        // 8 written, z + c twice: 7.
        EXPECT_EQ(p.count(Op::kAdd), 7) << algebraName(algebra);
        EXPECT_EQ(p.count(Op::kSquare), 1) << algebraName(algebra);  // (z + c)*(z + c)
        // 1 + i, 1 - i, their product, the product with z^5, 0.5 z, 1 z.
        EXPECT_EQ(p.count(Op::kMultiply), 4) << algebraName(algebra);
        EXPECT_EQ(p.result(), int(p.instructions().size()) - 1);
        // The constants in the order written, each once: 1, i, 0.5, c, 0 (1 again shared).
        ASSERT_EQ(p.elements().size(), 5u) << algebraName(algebra);
        EXPECT_EQ(p.elements()[1], basisElement(1));
        EXPECT_EQ(p.elements()[3], c);
        EXPECT_EQ(p.constants()[3], Quaternion(-0.2, 0.6, 0.2, 0.2));
    }
}

// The formula evaluated from its parse tree, as HypercomplexFormula evaluated it before it ran
// programs: products through the table in the order written, z^n = z (z (... z)).
Hypercomplex treeValue(const FormulaNode& n, const MultiplicationTable& table,
                       const Hypercomplex& z, const Hypercomplex& c) {
    using Kind = FormulaNode::Kind;
    switch (n.kind) {
        case Kind::kConstant:
            return {n.value.w, n.value.x, n.value.y, n.value.z, 0, 0, 0, 0};
        case Kind::kC:
            return c;
        case Kind::kZ:
            return z;
        case Kind::kSum:
            return treeValue(*n.left, table, z, c) + treeValue(*n.right, table, z, c);
        case Kind::kDifference:
            return treeValue(*n.left, table, z, c) - treeValue(*n.right, table, z, c);
        case Kind::kNegate:
            return -1.0 * treeValue(*n.left, table, z, c);
        case Kind::kProduct:
            return table.multiply(treeValue(*n.left, table, z, c),
                                  treeValue(*n.right, table, z, c));
        case Kind::kPower:
            return table.power(treeValue(*n.left, table, z, c), n.exponent);
        case Kind::kFunction:
        case Kind::kRealPower:
            break;
    }
    return {};
}

TEST(FormulaProgram, EvaluatesBitForBitAsTheTreeThroughTheTable) {
    const char* formulas[] = {"z^2 + c",
                              "z^3 + c",
                              "(1+0.2i) z (1-0.1k) z + c",
                              "i*z*j*z + c",
                              "(z + c)^5 - z*z*z",
                              "-(z^3) - 2 z + c",
                              "(z*i)*j + z*(i*j) + c",
                              "0.5 z^4 - (1 + i)(1 - i) z^2 + z^0 + c",
                              "z (z z) - (z z) z + c"};
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1.2, 1.2);
    for (Algebra algebra : {Algebra::kBicomplex, Algebra::kCoquaternion, Algebra::kBiquaternion,
                            Algebra::kOctonion}) {
        const MultiplicationTable& table = MultiplicationTable::of(algebra);
        for (const char* text : formulas) {
            const Formula formula = Formula::parse(text);
            Hypercomplex c{}, z{};
            for (int n = 0; n < algebraDimension(algebra); ++n)
                c[n] = u(rng) / 2, z[n] = u(rng);
            const FormulaProgram p = FormulaProgram::compile(formula, algebra, c);
            const Hypercomplex expected = treeValue(*formula.root(), table, z, c);
            const Hypercomplex value = evaluateInAlgebra(p, table, z);
            EXPECT_EQ(std::memcmp(value.data(), expected.data(), sizeof value), 0)
                << text << " in " << algebraName(algebra);
            EXPECT_EQ(std::memcmp(evaluateInAlgebraWithDerivative(p, table, z, z).first.data(),
                                  expected.data(), sizeof value),
                      0)
                << text << " in " << algebraName(algebra);
        }
    }
}

TEST(FormulaProgram, QuaternionProgramsRunThroughRunProgramInEveryEntry) {
    // evaluateInAlgebra of a quaternion program is the renderer's runProgram, bit for bit, and
    // its derivative runProgramWithTangents'.
    const FormulaProgram p = FormulaProgram::compile(
        Formula::parse("(1+0.2i) z (1-0.1k) z + 0.3 z^3 + c"), Quaternion(-0.2, 0.6, 0.2, 0.2));
    const MultiplicationTable& table = MultiplicationTable::of(Algebra::kQuaternion);
    const Quaternion z(0.3, -0.2, 0.1, 0.4), h(0.1, 0.2, -0.3, 0.05);
    const Hypercomplex zh{z.w, z.x, z.y, z.z, 0, 0, 0, 0}, hh{h.w, h.x, h.y, h.z, 0, 0, 0, 0};
    const Quaternion value = p.evaluate(z);
    const Hypercomplex v = evaluateInAlgebra(p, table, zh);
    EXPECT_EQ(Quaternion(v[0], v[1], v[2], v[3]), value);
    std::vector<Quaternion> registers(p.instructions().size()), tangents(registers.size());
    const Quaternion direction[1] = {h};
    Quaternion derivative[1];
    runProgramWithTangents<1>(p.instructions(), p.result(), z, direction, Quaternion(0),
                              p.constants().data(), p.factors().data(), registers.data(),
                              tangents.data(), derivative);
    const Hypercomplex d = evaluateInAlgebraWithDerivative(p, table, zh, hh).second;
    EXPECT_EQ(Quaternion(d[0], d[1], d[2], d[3]), derivative[0]);
}

TEST(FormulaProgram, FunctionsCompileOnlyWhereTheAlgebraHasThem) {
    const Formula formula = Formula::parse("sin(z) + z^2.5 + sin(z) + c");
    const FormulaProgram p = FormulaProgram::compile(formula, Algebra::kBicomplex, Hypercomplex{});
    EXPECT_EQ(p.count(Op::kFunction), 1);  // sin(z) once, shared
    EXPECT_EQ(p.count(Op::kRealPower), 1);
    for (Algebra algebra : allAlgebras()) {
        if (algebraArithmetic(algebra).transcendentalFunctions) continue;
        EXPECT_THROW(FormulaProgram::compile(formula, algebra, Hypercomplex{}), FormulaError)
            << algebraName(algebra);
    }
}

TEST(FormulaProgram, ThreeDirectionsAtOnceAreEachDirectionAlone) {
    // The normal's three tangents in one pass: the value once, each derivative bit for bit the
    // one-direction pass's (so normals keep their bytes), in every algebra, functions and real
    // powers included.
    // The last two, with functions and a real power, in the bicomplex numbers alone.
    const char* formulas[] = {"(1+0.2i) z (1-0.1k) z + 0.3 z^3 + c", "i z^2 j - z + c",
                              "0.5 z^4 - (z + 0.1j)^2 + c", "sin(z) + 0.2 exp(z) + c",
                              "z^1.5 + cos(z^2) + c"};
    constexpr int kPolynomials = 3;
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> u(-1.2, 1.2);
    for (Algebra algebra : {Algebra::kQuaternion, Algebra::kBicomplex, Algebra::kCoquaternion,
                            Algebra::kBiquaternion, Algebra::kOctonion}) {
        const MultiplicationTable& table = MultiplicationTable::of(algebra);
        for (int f = 0; f < 5; ++f) {
            if (f >= kPolynomials && algebra != Algebra::kBicomplex) continue;
            const char* text = formulas[f];
            const Formula formula = Formula::parse(text);
            Hypercomplex c{}, z{};
            std::array<Hypercomplex, 3> h{};
            for (int n = 0; n < algebraDimension(algebra); ++n) {
                c[n] = u(rng) / 2, z[n] = u(rng);
                for (auto& direction : h)
                    direction[n] = u(rng);
            }
            const FormulaProgram p = FormulaProgram::compile(formula, algebra, c);
            const auto [value, derivatives] = evaluateInAlgebraWithDerivatives(p, table, z, h);
            for (std::size_t s = 0; s < 3; ++s) {
                const auto [alone, derivative] = evaluateInAlgebraWithDerivative(p, table, z, h[s]);
                EXPECT_EQ(std::memcmp(value.data(), alone.data(), sizeof value), 0)
                    << text << " in " << algebraName(algebra);
                EXPECT_EQ(std::memcmp(derivatives[s].data(), derivative.data(), sizeof value), 0)
                    << text << " in " << algebraName(algebra) << ", direction " << s;
                // And a derivative indeed: the difference quotient agrees to first order.
                const double step = 1e-6;
                const Hypercomplex ahead = evaluateInAlgebra(p, table, z + step * h[s]);
                const Hypercomplex quotient = (1 / step) * (ahead - alone);
                EXPECT_LT(euclideanNorm(quotient - derivative),
                          1e-4 * (1 + euclideanNorm(derivative)))
                    << text << " in " << algebraName(algebra);
            }
        }
    }
}

}  // namespace
}  // namespace quaternia
