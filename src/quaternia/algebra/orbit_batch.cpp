#include "quaternia/algebra/orbit_batch.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace quaternia {
namespace {

// Lanes of points: 8 measured faster than 4 or 16 (coquaternion z^2 + c, 480x270).
constexpr std::size_t kLanes = 8;

using Op = Instruction::Op;
// L points side by side (kLanes, or 1 for one point alone).
template <std::size_t L>
using Lane = std::array<double, L>;

// D components of L points, component by component. Components D .. 7 of the one-point
// arithmetic stay zero (constants, products and linear maps leave them so) and add nothing to
// its norm, so they are not kept.
template <int D, std::size_t L>
using Lanes = std::array<Lane<L>, D>;

// evaluateInAlgebra's product (MultiplicationTable::multiplyFixed): component k sums
// sign * (a_i b_partner) over i in order, from 0. `product` is neither a nor b.
template <int D, std::size_t L>
void multiply(const MultiplicationTable& table, const Lanes<D, L>& a, const Lanes<D, L>& b,
              Lanes<D, L>& product) {
    for (int k = 0; k < D; ++k) {
        Lane<L> sum{};
        for (int i = 0; i < D; ++i) {
            // sum + sign * (x y) with sign +-1 is sum + x y or sum - x y, exactly.
            const Lane<L>& x = a[std::size_t(i)];
            const Lane<L>& y = b[std::size_t(table.outputPartner(k, i))];
            if (table.outputSign(k, i) > 0) {
                for (std::size_t l = 0; l < L; ++l)
                    sum[l] += x[l] * y[l];
            } else {
                for (std::size_t l = 0; l < L; ++l)
                    sum[l] -= x[l] * y[l];
            }
        }
        product[std::size_t(k)] = sum;
    }
}

// The program on every lane into `value`, as formula_program_evaluate.cpp's run<false>. The
// lanes' points are in the register of the first kZ instruction, `zRegister`; the constants'
// registers are filled once, by fillConstants.
template <int D, std::size_t L>
void run(const FormulaProgram& program, const MultiplicationTable& table, std::size_t zRegister,
         std::vector<Lanes<D, L>>& value) {
    const std::vector<Instruction>& code = program.instructions();
    const double* factors = program.factors().data();
    for (std::size_t n = 0; n < code.size(); ++n) {
        const Instruction& i = code[n];
        const std::size_t a = std::size_t(i.a), b = std::size_t(i.b);
        Lanes<D, L>& out = value[n];
        switch (i.op) {
            case Op::kZ:
                if (n != zRegister) out = value[zRegister];
                break;
            case Op::kConstant:
                break;
            case Op::kAdd:
                for (std::size_t k = 0; k < std::size_t(D); ++k)
                    for (std::size_t l = 0; l < L; ++l)
                        out[k][l] = value[a][k][l] + value[b][k][l];
                break;
            case Op::kSubtract:
                for (std::size_t k = 0; k < std::size_t(D); ++k)
                    for (std::size_t l = 0; l < L; ++l)
                        out[k][l] = value[a][k][l] - value[b][k][l];
                break;
            case Op::kNegate:
            case Op::kScale: {
                // negated(x) is -1.0 * x.
                const double f = i.op == Op::kNegate ? -1.0 : factors[i.index];
                for (std::size_t k = 0; k < std::size_t(D); ++k)
                    for (std::size_t l = 0; l < L; ++l)
                        out[k][l] = f * value[a][k][l];
                break;
            }
            case Op::kMultiply:
            case Op::kSquare:
                multiply<D, L>(table, value[a], value[i.op == Op::kSquare ? a : b], out);
                break;
            case Op::kLinear: {
                // linearMap: components 0 .. 3 by the matrix, the others zero.
                const double* m = factors + i.index;
                Lanes<D, L> mapped{};
                for (std::size_t r = 0; r < 4; ++r)
                    for (std::size_t l = 0; l < L; ++l)
                        mapped[r][l] =
                            m[r * 4 + 0] * value[a][0][l] + m[r * 4 + 1] * value[a][1][l] +
                            m[r * 4 + 2] * value[a][2][l] + m[r * 4 + 3] * value[a][3][l];
                out = mapped;
                break;
            }
            case Op::kPower: {
                // x (x (... x)), x^0 = 1.
                if (i.index == 0) {
                    out = Lanes<D, L>{};
                    out[0].fill(1);
                    break;
                }
                if (i.index == 1) {
                    out = value[a];
                    break;
                }
                multiply<D, L>(table, value[a], value[a], out);
                for (int e = 2; e < i.index; ++e) {
                    const Lanes<D, L> power = out;
                    multiply<D, L>(table, value[a], power, out);
                }
                break;
            }
            case Op::kFunction:
            case Op::kRealPower:
                break;  // refused by batchesOrbits
        }
    }
}

// The registers of kConstant instructions, which no instruction overwrites; and the first kZ
// register, where the lanes' points are kept (the program's size if it has none).
template <int D, std::size_t L>
std::size_t fillConstants(const FormulaProgram& program, std::vector<Lanes<D, L>>& value) {
    const std::vector<Instruction>& code = program.instructions();
    std::size_t zRegister = code.size();
    for (std::size_t n = 0; n < code.size(); ++n) {
        if (code[n].op == Op::kZ && zRegister == code.size()) zRegister = n;
        if (code[n].op != Op::kConstant) continue;
        for (std::size_t k = 0; k < std::size_t(D); ++k)
            value[n][k].fill(program.elements()[std::size_t(code[n].index)][k]);
    }
    return zRegister;
}

// Each lane follows one point's orbit and takes the next point as soon as its own is decided,
// so that a point costs its own iterations, not the slowest of a fixed group's. Points past
// the first found inside are not needed.
template <int D, std::size_t L>
int firstInside(const FormulaProgram& program, const MultiplicationTable& table,
                const Hypercomplex* points, int count, int maxIterations, double bailoutSquared) {
    thread_local std::vector<Lanes<D, L>> registers;
    // One register past the program's: the points' own where the program has no kZ.
    if (registers.size() < program.instructions().size() + 1)
        registers.resize(program.instructions().size() + 1);
    const std::size_t zRegister = fillConstants<D, L>(program, registers);
    const std::size_t result = std::size_t(program.result());
    Lanes<D, L>& z = registers[zRegister];
    std::array<int, L> point{}, iteration{};
    int next = 0, first = count;
    // Gives lane l the next point whose orbit decides something, deciding at once those whose
    // z_0 escapes or whose N is 1; -1 where none is left.
    auto refill = [&](std::size_t l) {
        for (;;) {
            if (next >= first) {
                point[l] = -1;
                return;
            }
            const Hypercomplex& p = points[next];
            if (!(normSquared(p) > bailoutSquared)) {
                if (maxIterations <= 1) {
                    first = next;
                    point[l] = -1;
                    return;
                }
                for (std::size_t k = 0; k < std::size_t(D); ++k)
                    z[k][l] = p[k];
                point[l] = next++;
                iteration[l] = 0;
                return;
            }
            ++next;
        }
    };
    for (std::size_t l = 0; l < L; ++l)
        refill(l);
    for (;;) {
        bool active = false;
        for (std::size_t l = 0; l < L; ++l)
            active = active || point[l] >= 0;
        if (!active) return first;
        run<D, L>(program, table, zRegister, registers);
        if (result != zRegister) z = registers[result];
        // normSquared: the squares summed in order, from 0.
        Lane<L> norm{};
        for (std::size_t k = 0; k < std::size_t(D); ++k)
            for (std::size_t l = 0; l < L; ++l)
                norm[l] += z[k][l] * z[k][l];
        for (std::size_t l = 0; l < L; ++l) {
            if (point[l] < 0) continue;
            if (point[l] > first) {
                point[l] = -1;
            } else if (norm[l] > bailoutSquared) {
                refill(l);
            } else if (++iteration[l] + 1 >= maxIterations) {
                first = std::min(first, point[l]);
                refill(l);
            }
        }
    }
}

}  // namespace

bool batchesOrbits(const FormulaProgram& program) {
    if (program.algebra() == Algebra::kQuaternion) return false;
    for (const Instruction& i : program.instructions())
        if (i.op == Op::kFunction || i.op == Op::kRealPower) return false;
    return true;
}

int firstInsideOfBatch(const FormulaProgram& program, const MultiplicationTable& table,
                       const Hypercomplex* points, int count, int maxIterations,
                       double bailoutSquared) {
    if (count <= 0) return 0;
    if (table.dimension() == 4) {
        return count == 1
                   ? firstInside<4, 1>(program, table, points, count, maxIterations, bailoutSquared)
                   : firstInside<4, kLanes>(program, table, points, count, maxIterations,
                                            bailoutSquared);
    }
    return count == 1
               ? firstInside<8, 1>(program, table, points, count, maxIterations, bailoutSquared)
               : firstInside<8, kLanes>(program, table, points, count, maxIterations,
                                        bailoutSquared);
}

}  // namespace quaternia
