// The general form in SIMD lanes: any eq. 2.10 polynomial as its compiled program
// (algebra/formula_program.h) run on quaternions of lane vectors, with the running bound of the
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

// A LaneFractal's program with its constants, scale factors and P'(r) as lanes, and the
// registers to run it in (scratch: one ProgramLanes per thread, as LaneConstants is).
template <class D>
struct ProgramLanes {
    using V = hn::Vec<D>;
    using Q = QuaternionT<V>;

    ProgramLanes(D d, const LaneFractal& f) : program_(f.program) {
        using T = hn::TFromD<D>;
        if (!program_) return;
        const std::vector<Instruction>& code = program_->instructions();
        for (const Quaternion& q : program_->constants())
            constants_.push_back(
                Q{hn::Set(d, T(q.w)), hn::Set(d, T(q.x)), hn::Set(d, T(q.y)), hn::Set(d, T(q.z))});
        for (double factor : program_->factors())
            factors_.push_back(hn::Set(d, T(factor)));
        for (double b : f.derivativeBound)
            derivativeBound_.push_back(hn::Set(d, T(b)));
        if (derivativeBound_.empty()) derivativeBound_.push_back(hn::Zero(d));
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
        using Op = Instruction::Op;
        const std::vector<Instruction>& code = program_->instructions();
        Q* r = registers_.data();
        constexpr size_t G = kLaneGroups;
        for (std::size_t n = 0; n < code.size(); ++n) {
            const Instruction& i = code[n];
            Q* out = r + n * G;
            const Q* a = r + std::size_t(i.a) * G;
            const Q* b = r + std::size_t(i.b) * G;
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
            }
        }
        const Q* result = r + std::size_t(program_->result()) * G;
        for (size_t j = 0; j < K; ++j)
            z[j] = result[j];
    }

    // The squared gain of the running derivative bound at |z|^2 = r2: P'(|z|)^2, by Horner's
    // rule from P'(r)'s coefficients.
    HWY_INLINE V gainSquared(V r2) const {
        const V r = hn::Sqrt(r2);
        V bound = derivativeBound_.back();
        for (std::size_t k = derivativeBound_.size() - 1; k-- > 0;)
            bound = hn::MulAdd(bound, r, derivativeBound_[k]);
        return bound * bound;
    }

    // p(z) and its derivative along the three tangents h (Dp(z)[h_m], the product rule in the
    // order written), for the analytic normal.
    HWY_INLINE Q stepWithTangents(D d, const Q& z, const Q (&h)[3], Q (&derivative)[3]) const {
        const Q zero{hn::Zero(d), hn::Zero(d), hn::Zero(d), hn::Zero(d)};
        return HWY_NAMESPACE::runProgramWithTangents<3>(
            program_->instructions(), program_->result(), z, h, zero, constants_.data(),
            factors_.data(), gradientRegisters_.data(), tangentRegisters_.data(), derivative);
    }

  private:
    std::shared_ptr<const FormulaProgram> program_;
    LaneVector<Q> constants_;
    LaneVector<V> factors_;
    LaneVector<V> derivativeBound_;  // P'(r)'s coefficients, lowest degree first
    mutable LaneVector<Q> registers_;
    mutable LaneVector<Q> gradientRegisters_;
    mutable LaneVector<Q> tangentRegisters_;
};

#endif  // QUATERNIA_PROGRAM_LANES_INL_H_
