// The interpreters of formula_program.h's quaternion programs, templates over the element type:
// runProgram and runProgramWithTangents (the other algebras' programs run through their
// multiplication table: formula_program_evaluate.cpp). formula_program.h includes this file into
// namespace quaternia; the lane code (render/lanes/march_lanes-inl.h) includes it again into each
// SIMD target's namespace, where the lane vectors' arithmetic is defined (quaternion.h says why
// templates for lanes are defined there) and calls it by its qualified name, so that the two never
// compete. No include guard, for that reason; each place includes it once.

// The linear map whose 4x4 matrix, row by row, starts at m (Instruction::Op::kLinear). Called
// as (applyLinear)(...): the parentheses keep argument-dependent lookup from finding the other
// namespace's copy of this file.
template <class Element, class Real>
Element applyLinear(const Real* m, const Element& a) {
    return {m[0] * a.w + m[1] * a.x + m[2] * a.y + m[3] * a.z,
            m[4] * a.w + m[5] * a.x + m[6] * a.y + m[7] * a.z,
            m[8] * a.w + m[9] * a.x + m[10] * a.y + m[11] * a.z,
            m[12] * a.w + m[13] * a.x + m[14] * a.y + m[15] * a.z};
}

// Runs `code` at z with `registers` (at least code.size() of them): `constants` and `factors` are
// the program's, converted to Element and Real. Returns register `result`.
template <class Element, class Real>
Element runProgram(const std::vector<Instruction>& code, int result, const Element& z,
                   const Element* constants, const Real* factors, Element* registers) {
    using Op = Instruction::Op;
    for (std::size_t n = 0; n < code.size(); ++n) {
        const Instruction& i = code[n];
        switch (i.op) {
            case Op::kZ:
                registers[n] = z;
                break;
            case Op::kConstant:
                registers[n] = constants[i.index];
                break;
            case Op::kAdd:
                registers[n] = registers[i.a] + registers[i.b];
                break;
            case Op::kSubtract:
                registers[n] = registers[i.a] - registers[i.b];
                break;
            case Op::kNegate:
                registers[n] = -registers[i.a];
                break;
            case Op::kMultiply:
                registers[n] = registers[i.a] * registers[i.b];
                break;
            case Op::kSquare:
                registers[n] = square(registers[i.a]);
                break;
            case Op::kScale:
                registers[n] = registers[i.a] * factors[i.index];
                break;
            case Op::kLinear:
                registers[n] = (applyLinear)(factors + i.index, registers[i.a]);
                break;
            case Op::kPower:
            case Op::kFunction:
            case Op::kRealPower:
                // Never in a quaternion program: the quaternions' rules take powers by
                // squaring and refuse functions (hypercomplex.h, AlgebraArithmetic).
                break;
        }
    }
    return registers[result];
}

// runProgram with the directional derivatives Dp(z)[h_m] along M tangents h_m, by the product
// rule in the order written (d(ab) = da b + a db: the factors do not commute), as the analytic
// normals and the Jacobians of orbits need them. `tangentRegisters` holds M per register
// (register n's at n M);
// `zero` is the element 0 (lane vectors have no default value).
template <int M, class Element, class Real>
Element runProgramWithTangents(const std::vector<Instruction>& code, int result, const Element& z,
                               const Element (&h)[M], const Element& zero, const Element* constants,
                               const Real* factors, Element* registers, Element* tangentRegisters,
                               Element (&derivative)[M]) {
    using Op = Instruction::Op;
    for (std::size_t n = 0; n < code.size(); ++n) {
        const Instruction& i = code[n];
        Element* t = tangentRegisters + n * M;
        switch (i.op) {
            case Op::kZ:
                registers[n] = z;
                for (int m = 0; m < M; ++m)
                    t[m] = h[m];
                break;
            case Op::kConstant:
                registers[n] = constants[i.index];
                for (int m = 0; m < M; ++m)
                    t[m] = zero;
                break;
            case Op::kAdd:
                registers[n] = registers[i.a] + registers[i.b];
                for (int m = 0; m < M; ++m)
                    t[m] = tangentRegisters[std::size_t(i.a) * M + m] +
                           tangentRegisters[std::size_t(i.b) * M + m];
                break;
            case Op::kSubtract:
                registers[n] = registers[i.a] - registers[i.b];
                for (int m = 0; m < M; ++m)
                    t[m] = tangentRegisters[std::size_t(i.a) * M + m] -
                           tangentRegisters[std::size_t(i.b) * M + m];
                break;
            case Op::kNegate:
                registers[n] = -registers[i.a];
                for (int m = 0; m < M; ++m)
                    t[m] = -tangentRegisters[std::size_t(i.a) * M + m];
                break;
            case Op::kMultiply:
            case Op::kSquare: {
                const int b = i.op == Op::kSquare ? i.a : i.b;
                registers[n] =
                    i.op == Op::kSquare ? square(registers[i.a]) : registers[i.a] * registers[b];
                for (int m = 0; m < M; ++m)
                    t[m] = tangentRegisters[std::size_t(i.a) * M + m] * registers[b] +
                           registers[i.a] * tangentRegisters[std::size_t(b) * M + m];
                break;
            }
            case Op::kScale:
                registers[n] = registers[i.a] * factors[i.index];
                for (int m = 0; m < M; ++m)
                    t[m] = tangentRegisters[std::size_t(i.a) * M + m] * factors[i.index];
                break;
            case Op::kLinear:
                registers[n] = (applyLinear)(factors + i.index, registers[i.a]);
                for (int m = 0; m < M; ++m)
                    t[m] = (applyLinear)(factors + i.index,
                                         tangentRegisters[std::size_t(i.a) * M + m]);
                break;
            case Op::kPower:
            case Op::kFunction:
            case Op::kRealPower:
                break;  // never in a quaternion program, as in runProgram
        }
    }
    for (int m = 0; m < M; ++m)
        derivative[m] = tangentRegisters[std::size_t(result) * M + m];
    return registers[result];
}
