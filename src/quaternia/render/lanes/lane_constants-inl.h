// The fractal's constants as lanes (LaneConstants), shared by every lane kernel: the slice map
// from 3D points to what the iterations take, and the polynomial's numbers, broadcast once per
// batch.
//
// Like estimate_lanes-inl.h, this file has no namespace of its own: march_lanes-inl.h includes it
// inside its per-target namespace, once per SIMD target (the HWY_TARGET_TOGGLE guard below lets
// it in again for each), after program_lanes-inl.h, whose lanes it holds.

#if defined(QUATERNIA_LANE_CONSTANTS_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef QUATERNIA_LANE_CONSTANTS_INL_H_
#undef QUATERNIA_LANE_CONSTANTS_INL_H_
#else
#define QUATERNIA_LANE_CONSTANTS_INL_H_
#endif

// The fractal's constants broadcast to lanes of type T.
template <class D>
struct LaneConstants {
    using V = hn::Vec<D>;
    QuaternionT<V> origin, axis0, axis1, axis2, c;
    QuaternionT<V> axis3, loopAxis3;  // of a fourth coordinate (LaneFractal::axes[3])
    V scale, bailoutSquared, escapeRadiusSquared, estimateRadiusSquared, stepScale, maxIterations;
    V gainFactor;        // 4 s^2 for d = 2, s^2 d^2 otherwise
    V normSquaredScale;  // LaneFractal::normSquaredScale: |z|^2 from the iterate's |w|^2
    V normScale;         // its square root, |z| / |w|
    // The float loop of s z^2 + c in u = 2 s z (estimateThreeNumbers): the slice map times 2 s,
    // 2 s c (complex there: scaledC + scaledCi i), the radii squared times 4 s^2, and 1 / (4 s^2).
    QuaternionT<V> loopOrigin, loopAxis0, loopAxis1, loopAxis2;
    V scaledC, scaledCi, scaledBailoutSquared, scaledEscapeRadiusSquared,
        scaledEstimateRadiusSquared, inverseFourScaleSquared;
    int degree, maxIterationCount;
    bool certified;  // bailout >= the certified escape radius: every escape is final
    // Estimates take estimateThreeNumbers: float lanes, z^2 + c, a certified bailout.
    bool threeNumbers;
    // The general form: the polynomial's program (false for s z^d + c).
    ProgramLanes<D> program;
    // P'(r), whose value at |z| bounds the derivative's gain (programs and real forms).
    DerivativeBoundLanes<D> derivativeBound;
    // Estimates take estimateThreeNumbers with RealThreeNumbersGroup: float lanes, a polynomial
    // sum a_k z^k + c with real a_k other than s z^2 + c, a certified bailout. realCoefficients
    // holds the a_k.
    bool realThreeNumbers;
    bool realForm;  // realCoefficients holds the a_k (any precision)
    LaneVector<V> realCoefficients;
    // A bicomplex polynomial (LaneFractal::bicomplex; bicomplex_lanes-inl.h): each duplex
    // component's coefficients, lowest degree first, as real and imaginary parts; whether both
    // are w^2 + c_i; their escape radii squared.
    bool bicomplex = false, bicomplexSquare = false;
    LaneVector<V> bicomplexReal[2], bicomplexImaginary[2];
    V componentEscapeRadiusSquared[2];
    // Components with a disconnected K (LaneFractal::Bicomplex): G*, ln|a_d| / (d - 1), ln d,
    // and the scalar reference for the pull-back (null where both are connected).
    bool componentConnected[2] = {true, true}, componentBinomial[2] = {false, false};
    V criticalPotential[2], leadLog[2], logDegree, inverseLead[2], pullBackLimit[2];
    V expm1Critical[2];  // e^G* - 1
    const JuliaSet* bicomplexReference = nullptr;
    // A folded octonion slice (LaneFractal::folded): the fold's rows 4 and 5 (origin, axes),
    // and 2 s, the loop's scale.
    bool folded = false;
    V foldOrigin[2], foldAxis[3][2], loopScale;

    // Float lanes take the fractal through LaneFractal::withComplexConstant, which changes no
    // estimate, membership or gradient product: their quadratic loop then needs c = c.w + c.x i.
    // Double lanes keep the slice as given, to round as the scalar reference does.
    LaneConstants(D d, const LaneFractal& given)
        : LaneConstants(d, sizeof(hn::TFromD<D>) == 4 ? given.withComplexConstant() : given, 0) {}

  private:
    LaneConstants(D d, const LaneFractal& f, int)
        : program(d, f), derivativeBound(d, f.derivativeBound) {
        using T = hn::TFromD<D>;
        degree = f.degree;
        maxIterationCount = f.maxIterations;
        certified = f.bailoutSquared >= f.escapeRadiusSquared;
        threeNumbers = sizeof(T) == 4 && f.degree == 2 && !f.program && certified;
        realThreeNumbers =
            sizeof(T) == 4 && !threeNumbers && certified && !f.realCoefficients.empty();
        realForm = !f.realCoefficients.empty();
        if (f.bicomplex) {
            bicomplex = true;
            threeNumbers = realThreeNumbers = false;
            bicomplexSquare = true;
            for (size_t i = 0; i < 2; ++i) {
                const auto& coefficients = f.bicomplex->coefficients[i];
                // The duplex form's coefficients come from a discrete Fourier transform: exact
                // up to rounding.
                bicomplexSquare = bicomplexSquare && coefficients.size() == 3 &&
                                  std::abs(coefficients[2] - 1.0) < 1e-12 &&
                                  std::abs(coefficients[1]) < 1e-12;
                for (const auto& a : coefficients) {
                    bicomplexReal[i].push_back(hn::Set(d, T(a.real())));
                    bicomplexImaginary[i].push_back(hn::Set(d, T(a.imag())));
                }
                componentEscapeRadiusSquared[i] =
                    hn::Set(d, T(f.bicomplex->escapeRadiusSquared[i]));
                componentConnected[i] = f.bicomplex->criticalPotential[i] == 0;
                criticalPotential[i] = hn::Set(d, T(f.bicomplex->criticalPotential[i]));
                leadLog[i] = hn::Set(d, T(f.bicomplex->leadLog[i]));
                componentBinomial[i] = f.bicomplex->binomial[i];
                inverseLead[i] = hn::Set(d, T(f.bicomplex->inverseLead[i]));
                pullBackLimit[i] = hn::Set(d, T(f.bicomplex->pullBackLimit[i]));
                const double critical = f.bicomplex->criticalPotential[i];
                expm1Critical[i] = hn::Set(d, T(std::expm1(critical)));
            }
            logDegree = hn::Set(d, T(std::log(double(f.degree))));
            if (f.bicomplex->reference) bicomplexReference = f.bicomplex->reference.get();
        } else {
            componentEscapeRadiusSquared[0] = componentEscapeRadiusSquared[1] = hn::Zero(d);
            criticalPotential[0] = criticalPotential[1] = leadLog[0] = leadLog[1] = hn::Zero(d);
            inverseLead[0] = inverseLead[1] = pullBackLimit[0] = pullBackLimit[1] = hn::Zero(d);
            expm1Critical[0] = expm1Critical[1] = hn::Zero(d);
            logDegree = hn::Zero(d);
        }
        for (double a : f.realCoefficients)
            realCoefficients.push_back(hn::Set(d, T(a)));
        auto lanes = [&](const std::array<double, 4>& q, double factor = 1) {
            return QuaternionT<V>{hn::Set(d, T(factor * q[0])), hn::Set(d, T(factor * q[1])),
                                  hn::Set(d, T(factor * q[2])), hn::Set(d, T(factor * q[3]))};
        };
        origin = lanes(f.origin);
        axis0 = lanes(f.axes[0]);
        axis1 = lanes(f.axes[1]);
        axis2 = lanes(f.axes[2]);
        axis3 = lanes(f.axes[3]);
        c = lanes(f.c);
        scale = hn::Set(d, T(f.scale));
        bailoutSquared = hn::Set(d, T(f.bailoutSquared));
        escapeRadiusSquared = hn::Set(d, T(f.escapeRadiusSquared));
        // (In the iterate's scale: |w|^2 = |z|^2 / normSquaredScale.)
        estimateRadiusSquared =
            hn::Set(d, T(continuationRadiusSquared<T>(f.degree) / f.normSquaredScale));
        stepScale = hn::Set(d, T(f.stepScale));
        maxIterations = hn::Set(d, T(f.maxIterations));
        gainFactor = hn::Set(d, T(f.scale * f.scale * f.degree * f.degree));
        normSquaredScale = hn::Set(d, T(f.normSquaredScale));
        normScale = hn::Set(d, T(std::sqrt(f.normSquaredScale)));
        const double fourScaleSquared = 4 * f.scale * f.scale;
        loopOrigin = lanes(f.origin, 2 * f.scale);
        loopAxis0 = lanes(f.axes[0], 2 * f.scale);
        loopAxis1 = lanes(f.axes[1], 2 * f.scale);
        loopAxis2 = lanes(f.axes[2], 2 * f.scale);
        loopAxis3 = lanes(f.axes[3], 2 * f.scale);
        scaledC = hn::Set(d, T(2 * f.scale * f.c[0]));
        scaledCi = hn::Set(d, T(2 * f.scale * f.c[1]));
        scaledBailoutSquared = hn::Set(d, T(fourScaleSquared * f.bailoutSquared));
        scaledEscapeRadiusSquared = hn::Set(d, T(fourScaleSquared * f.escapeRadiusSquared));
        scaledEstimateRadiusSquared =
            hn::Set(d, T(fourScaleSquared * continuationRadiusSquared<T>(f.degree)));
        inverseFourScaleSquared = hn::Set(d, T(1 / fourScaleSquared));
        folded = f.folded;
        loopScale = hn::Set(d, T(2 * f.scale));
        for (size_t r = 0; r < 2; ++r) {
            foldOrigin[r] = hn::Set(d, T(f.foldRows[r][0]));
            for (size_t a = 0; a < 3; ++a)
                foldAxis[a][r] = hn::Set(d, T(f.foldRows[r][a + 1]));
        }
    }

  public:
    // The slice: a 3D point to its quaternion (folded: (row 0, row 1, |rows 2 to 5|, 0)).
    QuaternionT<V> quaternionFromWorld(V x, V y, V z) const {
        QuaternionT<V> q = affine(origin, axis0, axis1, axis2, x, y, z);
        if (folded) {
            const V r4 = foldRow(0, x, y, z), r5 = foldRow(1, x, y, z);
            q.y = hn::Sqrt(hn::MulAdd(r5, r5, hn::MulAdd(r4, r4, hn::MulAdd(q.z, q.z, q.y * q.y))));
            q.z = hn::Zero(hn::DFromV<V>());
        }
        return q;
    }
    // A point of quaternionFromWorld (or, `loop`, loopFromWorld) moved by its fourth coordinate
    // w (points of the algebra, LaneCoordinates::Algebra; never folded).
    QuaternionT<V> plusFourth(const QuaternionT<V>& q, V w, bool loop) const {
        const QuaternionT<V>& axis = loop ? loopAxis3 : axis3;
        return QuaternionT<V>{hn::MulAdd(w, axis.w, q.w), hn::MulAdd(w, axis.x, q.x),
                              hn::MulAdd(w, axis.y, q.y), hn::MulAdd(w, axis.z, q.z)};
    }
    // The same point as estimateThreeNumbers takes it: u = 2 s z.
    QuaternionT<V> loopFromWorld(V x, V y, V z) const {
        if (folded) return quaternionFromWorld(x, y, z) * loopScale;
        return affine(loopOrigin, loopAxis0, loopAxis1, loopAxis2, x, y, z);
    }
    // The derivatives of that point along the three axes (of u = 2 s z where `loop`): the axes
    // of the affine slices; for a folded slice, with the derivative of |rows 2 to 5| in the j
    // component (0 where that part vanishes: only the direction of a gradient is used).
    void tangentsAt(V x, V y, V z, bool loop, QuaternionT<V> (&t)[3]) const {
        const QuaternionT<V>* axes[3] = {&axis0, &axis1, &axis2};
        const QuaternionT<V>* loopAxes[3] = {&loopAxis0, &loopAxis1, &loopAxis2};
        for (size_t a = 0; a < 3; ++a)
            t[a] = loop && !folded ? *loopAxes[a] : *axes[a];
        if (!folded) return;
        const QuaternionT<V> q = affine(origin, axis0, axis1, axis2, x, y, z);
        const V r4 = foldRow(0, x, y, z), r5 = foldRow(1, x, y, z);
        const V length =
            hn::Sqrt(hn::MulAdd(r5, r5, hn::MulAdd(r4, r4, hn::MulAdd(q.z, q.z, q.y * q.y))));
        const hn::DFromV<V> d;
        const V inverse = hn::IfThenElseZero(length > hn::Zero(d),
                                             hn::Set(d, hn::TFromD<decltype(d)>(1)) / length);
        for (size_t a = 0; a < 3; ++a) {
            const V along =
                hn::MulAdd(r5, foldAxis[a][1],
                           hn::MulAdd(r4, foldAxis[a][0], hn::MulAdd(q.z, t[a].z, q.y * t[a].y)));
            t[a].y = along * inverse;
            t[a].z = hn::Zero(d);
            if (loop) t[a] = t[a] * loopScale;
        }
    }

  private:
    V foldRow(size_t r, V x, V y, V z) const {
        return hn::MulAdd(
            z, foldAxis[2][r],
            hn::MulAdd(y, foldAxis[1][r], hn::MulAdd(x, foldAxis[0][r], foldOrigin[r])));
    }
    static QuaternionT<V> affine(const QuaternionT<V>& o, const QuaternionT<V>& a0,
                                 const QuaternionT<V>& a1, const QuaternionT<V>& a2, V x, V y,
                                 V z) {
        return {hn::MulAdd(z, a2.w, hn::MulAdd(y, a1.w, hn::MulAdd(x, a0.w, o.w))),
                hn::MulAdd(z, a2.x, hn::MulAdd(y, a1.x, hn::MulAdd(x, a0.x, o.x))),
                hn::MulAdd(z, a2.y, hn::MulAdd(y, a1.y, hn::MulAdd(x, a0.y, o.y))),
                hn::MulAdd(z, a2.z, hn::MulAdd(y, a1.z, hn::MulAdd(x, a0.z, o.z)))};
    }
};

#endif  // QUATERNIA_LANE_CONSTANTS_INL_H_
