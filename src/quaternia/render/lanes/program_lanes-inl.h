// The general form in SIMD lanes: any eq. 2.10 polynomial as its compiled program
// (algebra/formula_program.h) run on quaternions of lane vectors, and the running bound of the
// derivative's norm that the scalar reference carries (distance.h: rho <- P'(|z|) rho).
//
// Like estimate_lanes-inl.h, this file has no namespace of its own: march_lanes-inl.h includes
// it inside its per-target namespace, once per SIMD target, after the quaternion arithmetic for
// the target's vectors and lane_state.h, with hn naming the target's Highway namespace.

#if defined(QUATERNIA_PROGRAM_LANES_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef QUATERNIA_PROGRAM_LANES_INL_H_
#undef QUATERNIA_PROGRAM_LANES_INL_H_
#else
#define QUATERNIA_PROGRAM_LANES_INL_H_
#endif

// P'(r) of a LaneFractal (LaneFractal::derivativeBound) as lanes: the squared gain of the running
// derivative bound at |z|^2 = r2. With P'(r) = E(r^2) + r O(r^2) (its even and odd powers), the
// square is E(r2)^2 where P' has no odd powers (z^3: 3 r^2), r2 O(r2)^2 where it has no even
// ones (z^2: 2 r), and needs a square root only where it has both (z^2 + 0.1 z: 2 r + 0.1).
template <class D>
struct DerivativeBoundLanes {
    using V = hn::Vec<D>;

    DerivativeBoundLanes(D d, const std::vector<double>& coefficients) {
        using T = hn::TFromD<D>;
        for (std::size_t k = 0; k < coefficients.size(); ++k) {
            (k % 2 == 0 ? even_ : odd_).push_back(hn::Set(d, T(coefficients[k])));
            if (coefficients[k] != 0) (k % 2 == 0 ? hasEven_ : hasOdd_) = true;
        }
        if (even_.empty()) even_.push_back(hn::Zero(d));
        if (odd_.empty()) odd_.push_back(hn::Zero(d));
    }

    HWY_INLINE V gainSquared(V r2) const {
        if (!hasOdd_) {
            const V e = inSquare(even_, r2);
            return e * e;
        }
        const V o = inSquare(odd_, r2);
        if (!hasEven_) return r2 * o * o;
        const V bound = hn::MulAdd(hn::Sqrt(r2), o, inSquare(even_, r2));
        return bound * bound;
    }

  private:
    // sum_m coefficients[m] r2^m by Horner's rule.
    static HWY_INLINE V inSquare(const LaneVector<V>& coefficients, V r2) {
        V sum = coefficients.back();
        for (std::size_t m = coefficients.size() - 1; m-- > 0;)
            sum = hn::MulAdd(sum, r2, coefficients[m]);
        return sum;
    }

    LaneVector<V> even_, odd_;  // the coefficients of r^(2m) and of r^(2m+1), by m
    bool hasEven_ = false, hasOdd_ = false;
};

// A LaneFractal's program with its constants and real factors (scalings and linear maps' matrices)
// as lanes, and the registers to run it in (scratch: one ProgramLanes per thread, as
// LaneConstants is).
template <class D>
struct ProgramLanes {
    using V = hn::Vec<D>;
    using Q = QuaternionT<V>;

    ProgramLanes(D d, const LaneFractal& f) : program_(f.program) {
        using T = hn::TFromD<D>;
        if (!program_) return;
        if (f.squareMap) {
            squareMap_ = true;
            for (double entry : *f.squareMap)
                map_.push_back(hn::Set(d, T(entry)));
            c_ = Q{hn::Set(d, T(f.c[0])), hn::Set(d, T(f.c[1])), hn::Set(d, T(f.c[2])),
                   hn::Set(d, T(f.c[3]))};
            return;  // step() and stepWithTangents() need no registers
        }
        const std::vector<Instruction>& code = program_->instructions();
        for (const Quaternion& q : program_->constants())
            constants_.push_back(
                Q{hn::Set(d, T(q.w)), hn::Set(d, T(q.x)), hn::Set(d, T(q.y)), hn::Set(d, T(q.z))});
        for (double factor : program_->factors())
            factors_.push_back(hn::Set(d, T(factor)));
        // The groups' registers interleaved, register n of group j at n * kLaneGroups + j, the
        // constants' written once here: step() runs every instruction but those.
        registers_.assign(code.size() * kLaneGroups, constants_.empty() ? Q{} : constants_[0]);
        for (std::size_t n = 0; n < code.size(); ++n) {
            if (code[n].op != Instruction::Op::kConstant) continue;
            for (std::size_t j = 0; j < kLaneGroups; ++j)
                registers_[n * kLaneGroups + j] = constants_[std::size_t(code[n].index)];
        }
        gradientRegisters_.resize(code.size(), registers_.front());
        tangentRegisters_.resize(3 * code.size(), registers_.front());
    }

    explicit operator bool() const { return program_ != nullptr; }

    // z[j] <- p(z[j]) for K groups of lanes, each instruction decoded once for all K.
    template <size_t K>
    HWY_INLINE void step(QuaternionT<V> (&z)[K]) const {
        static_assert(K <= kLaneGroups);
        if (squareMap_) {
            // A(z^2) + c in registers (LaneFractal::squareMap): the program's three instructions
            // without their trips through memory.
            const V* m = map_.data();
            for (size_t j = 0; j < K; ++j)
                z[j] = mapPlusC(m, square(z[j]));
            return;
        }
        using Op = Instruction::Op;
        const std::vector<Instruction>& code = program_->instructions();
        Q* r = registers_.data();
        constexpr size_t G = kLaneGroups;
        for (std::size_t n = 0; n < code.size(); ++n) {
            const Instruction& i = code[n];
            Q* out = r + n * G;
            // Operands an instruction lacks are -1: point them at register 0, not before r.
            const Q* a = r + std::size_t(std::max(i.a, 0)) * G;
            const Q* b = r + std::size_t(std::max(i.b, 0)) * G;
            switch (i.op) {
                case Op::kZ:
                    for (size_t j = 0; j < K; ++j)
                        out[j] = z[j];
                    break;
                case Op::kConstant:
                    break;  // written by the constructor
                case Op::kAdd:
                    for (size_t j = 0; j < K; ++j)
                        out[j] = a[j] + b[j];
                    break;
                case Op::kSubtract:
                    for (size_t j = 0; j < K; ++j)
                        out[j] = a[j] - b[j];
                    break;
                case Op::kNegate:
                    for (size_t j = 0; j < K; ++j)
                        out[j] = -a[j];
                    break;
                case Op::kMultiply:
                    for (size_t j = 0; j < K; ++j)
                        out[j] = a[j] * b[j];
                    break;
                case Op::kSquare:
                    for (size_t j = 0; j < K; ++j)
                        out[j] = square(a[j]);
                    break;
                case Op::kScale: {
                    const V factor = factors_[std::size_t(i.index)];
                    for (size_t j = 0; j < K; ++j)
                        out[j] = a[j] * factor;
                    break;
                }
                case Op::kLinear:
                    linear(&factors_[std::size_t(i.index)], a, out, K);
                    break;
                case Op::kPower:
                case Op::kFunction:
                case Op::kRealPower:
                    break;  // never in a quaternion program (formula_program.h)
            }
        }
        const Q* result = r + std::size_t(program_->result()) * G;
        for (size_t j = 0; j < K; ++j)
            z[j] = result[j];
    }

    // p(z) and its derivative along the three tangents h (Dp(z)[h_m], the product rule in the
    // order written), for the analytic normal.
    HWY_INLINE Q stepWithTangents(D d, const Q& z, const Q (&h)[3], Q (&derivative)[3]) const {
        if (squareMap_) {
            // D(A(z^2) + c)[h] = A(z h + h z).
            const V* m = map_.data();
            const Q zero{hn::Zero(d), hn::Zero(d), hn::Zero(d), hn::Zero(d)};
            for (int t = 0; t < 3; ++t)
                derivative[t] = mapPlus(m, z * h[t] + h[t] * z, zero);
            return mapPlusC(m, square(z));
        }
        const Q zero{hn::Zero(d), hn::Zero(d), hn::Zero(d), hn::Zero(d)};
        return HWY_NAMESPACE::runProgramWithTangents<3>(
            program_->instructions(), program_->result(), z, h, zero, constants_.data(),
            factors_.data(), gradientRegisters_.data(), tangentRegisters_.data(), derivative);
    }

  private:
    HWY_INLINE Q mapPlusC(const V* m, const Q& a) const { return mapPlus(m, a, c_); }

    // m a + b, m a 4x4 matrix row by row: each row as two multiply-adds chains of two.
    static HWY_INLINE Q mapPlus(const V* m, const Q& a, const Q& b) {
        auto row = [&](int r, V add) {
            return hn::MulAdd(m[4 * r], a.w, hn::MulAdd(m[4 * r + 1], a.x, add)) +
                   hn::MulAdd(m[4 * r + 2], a.y, m[4 * r + 3] * a.z);
        };
        return Q{row(0, b.w), row(1, b.x), row(2, b.y), row(3, b.z)};
    }

    // out[j] = m a[j] for `groups` groups: each row as two multiply-adds and a sum (three deep,
    // not seven), the row's four entries loaded once for all groups.
    static HWY_INLINE void linear(const V* m, const Q* a, Q* out, size_t groups) {
        V rows[4][kLaneGroups];
        for (int r = 0; r < 4; ++r) {
            const V m0 = m[4 * r], m1 = m[4 * r + 1], m2 = m[4 * r + 2], m3 = m[4 * r + 3];
            for (size_t j = 0; j < groups; ++j)
                rows[r][j] =
                    hn::MulAdd(m0, a[j].w, m1 * a[j].x) + hn::MulAdd(m2, a[j].y, m3 * a[j].z);
        }
        for (size_t j = 0; j < groups; ++j)
            out[j] = Q{rows[0][j], rows[1][j], rows[2][j], rows[3][j]};
    }

    std::shared_ptr<const FormulaProgram> program_;
    bool squareMap_ = false;  // LaneFractal::squareMap: z <- A(z^2) + c, A in map_
    LaneVector<V> map_;
    Q c_;
    LaneVector<Q> constants_;
    LaneVector<V> factors_;
    mutable LaneVector<Q> registers_;
    mutable LaneVector<Q> gradientRegisters_;
    mutable LaneVector<Q> tangentRegisters_;
};

#endif  // QUATERNIA_PROGRAM_LANES_INL_H_
