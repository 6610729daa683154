// Estimates and normals of points in SIMD lanes (estimatePoints, potentialNormals and their kin),
// compiled once per instruction set by Highway's foreach_target and chosen at run time
// (HWY_DYNAMIC_DISPATCH); march_lanes.h says what it computes. The machinery the march lanes share
// is march_lanes-inl.h.

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "quaternia/render/lanes/point_lanes.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
// clang-format off: the order matters, highway.h after foreach_target.h
#include <hwy/contrib/math/math-inl.h>
#include <hwy/highway.h>
// clang-format on

#include <algorithm>
#include <cmath>
#include <cstring>
#include <type_traits>
#include <utility>

#include "quaternia/algebra/quaternion.h"
#include "quaternia/render/lanes/lane_state.h"
#include "quaternia/render/lanes/march_lanes.h"
#include "quaternia/render/lanes/march_rules.h"

HWY_BEFORE_NAMESPACE();
namespace quaternia {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

#include "quaternia/render/lanes/march_lanes-inl.h"

// Fractal::estimate for a batch of points, lanes filled in order (the last chunk padded). With
// kOrbit the whole PointEstimate; without, only the distance (0 inside): store(begin, count,
// out) takes them from out, an EstimateLanes.
template <bool kQuadratic, bool kOrbit, class D, class Store>
void estimatePointLanes(D d, const LaneFractal& fractal, const PointBatch& points,
                        LaneCounters& counters, const Store& store) {
    using T = hn::TFromD<D>;
    const LaneConstants<D> k(d, fractal);
    const size_t lanes = hn::Lanes(d);
    Vector3Lanes<T> in;
    EstimateLanes<T> out;
    const bool fourth = !points.w.empty();
    for (size_t begin = 0; begin < points.size(); begin += lanes) {
        size_t count = std::min(lanes, points.size() - begin);
        in.gather(points, begin, count);
        const hn::Mask<D> live[1] = {hn::FirstN(d, count)};
        const auto x = hn::Load(d, in.x), y = hn::Load(d, in.y), z = hn::Load(d, in.z);
        // The point as the iteration takes it (`loop`: u = 2 s z), moved by its fourth
        // coordinate where it has one.
        auto pointOf = [&](bool loop) {
            const QuaternionT<hn::Vec<D>> q =
                loop ? k.loopFromWorld(x, y, z) : k.quaternionFromWorld(x, y, z);
            return fourth ? k.plusFourth(q, hn::Load(d, in.w), loop) : q;
        };
        LaneEstimate<D> estimates[1];
        if (k.bicomplex) {
            const QuaternionT<hn::Vec<D>> q[1] = {pointOf(false)};
            estimateBicomplex<kOrbit>(d, k, q, live, estimates, counters);
        } else if (kQuadratic && k.threeNumbers) {
            const QuaternionT<hn::Vec<D>> u[1] = {pointOf(true)};
            estimateThreeNumbers<kOrbit, ThreeNumbersGroup<D>>(d, k, u, live, estimates, counters);
        } else if (!kQuadratic && k.realThreeNumbers) {
            const QuaternionT<hn::Vec<D>> q[1] = {pointOf(false)};
            estimateThreeNumbers<kOrbit, RealThreeNumbersGroup<D>>(d, k, q, live, estimates,
                                                                   counters);
        } else {
            QuaternionT<hn::Vec<D>> q[1] = {pointOf(false)};
            estimateLanes<kQuadratic, kOrbit>(d, k, q, live, estimates, counters);
        }
        const LaneEstimate<D>& e = estimates[0];
        counters.estimates += int64_t(count);
        hn::Store(e.distance, d, out.distance);
        if constexpr (kOrbit) {
            hn::Store(hn::Sqrt(e.trapSquared), d, out.trap);
            hn::Store(e.iterations, d, out.iterations);
            hn::Store(e.radiusSquared, d, out.radiusSquared);
            out.insideLanes = laneBits(d, e.inside);
        }
        store(begin, count, out);
    }
}

template <bool kQuadratic, class D>
void estimatePointLanes(D d, const LaneFractal& fractal, const PointBatch& points,
                        std::vector<PointEstimate>& results, LaneCounters& counters) {
    results.assign(points.size(), PointEstimate{});
    estimatePointLanes<kQuadratic, true>(d, fractal, points, counters,
                                         [&](size_t begin, size_t count, const auto& out) {
                                             for (size_t lane = 0; lane < count; ++lane) {
                                                 PointEstimate& r = results[begin + lane];
                                                 r.distance = out.distance[lane];
                                                 r.trap = out.trap[lane];
                                                 r.iterations = int(out.iterations[lane]);
                                                 r.radiusSquared = out.radiusSquared[lane];
                                                 r.inside = (out.insideLanes >> lane) & 1;
                                             }
                                         });
}

// Fractal::normal / QuaternionJuliaSet::potentialGradient for a batch of points, M_i iterations in
// lane i (iterations[i]; without `iterations`, the M that each point's estimate reaches, found on
// the way: float lanes of z^2 + c with a certified bailout only, LaneConstants::threeNumbers): the
// gradient of the potential along the slice's axes, then the outward unit normal.
template <bool kQuadratic, class D>
void potentialNormalLanes(D d, const LaneFractal& fractal, const PointBatch& points,
                          const std::vector<int>* iterations, std::vector<Vector3d>& normals,
                          LaneCounters& counters) {
    using V = hn::Vec<D>;
    using T = hn::TFromD<D>;
    const LaneConstants<D> k(d, fractal);
    const size_t lanes = hn::Lanes(d);
    normals.assign(points.size(), Vector3d());
    Vector3Lanes<T> in, gradient;
    QUATERNIA_LANE_ARRAY(T, iterationCounts);  // M per lane
    for (size_t begin = 0; begin < points.size(); begin += lanes) {
        size_t count = std::min(lanes, points.size() - begin);
        in.gather(points, begin, count);
        const V x = hn::Load(d, in.x), y = hn::Load(d, in.y), z = hn::Load(d, in.z);
        V gx, gy, gz;  // the gradient along the slice's axes
        if (!iterations) {
            if constexpr (kQuadratic && sizeof(T) == 4) {
                threeNumberGradientToItsCount(d, k, x, y, z, hn::FirstN(d, count), gx, gy, gz,
                                              counters);
            }
        } else {
            int most = 0;
            for (size_t lane = 0; lane < lanes; ++lane) {
                int m = lane < count ? (*iterations)[begin + lane] : 0;
                iterationCounts[lane] = T(m);
                most = std::max(most, m);
            }
            const V m = hn::Load(d, iterationCounts);
            const int fewest = int(hn::GetLane(hn::MinOfLanes(d, m)));
            if (k.bicomplex) {
                bicomplexGradient(d, k, x, y, z, m, fewest, most, gx, gy, gz, counters);
            } else if constexpr (kQuadratic && sizeof(T) == 4) {
                threeNumberGradient(d, k, x, y, z, m, fewest, most, gx, gy, gz, counters);
            } else {
                quaternionGradient<kQuadratic>(d, k, x, y, z, m, fewest, most, gx, gy, gz,
                                               counters);
            }
        }
        hn::Store(gx, d, gradient.x);
        hn::Store(gy, d, gradient.y);
        hn::Store(gz, d, gradient.z);
        for (size_t lane = 0; lane < count; ++lane) {
            Vector3d g(gradient.x[lane], gradient.y[lane], gradient.z[lane]);
            Point3d p(points.x[begin + lane], points.y[begin + lane], points.z[begin + lane]);
            normals[begin + lane] = normalOrOutward(g, p);
        }
    }
}

void EstimatePoints(const LaneFractal& fractal, const PointBatch& points,
                    std::vector<PointEstimate>& results, LaneCounters& counters) {
    run(fractal, [&](auto d, auto quadratic) {
        estimatePointLanes<quadratic()>(d, fractal, points, results, counters);
    });
}
void EstimateDistances(const LaneFractal& fractal, const PointBatch& points,
                       std::vector<double>& distances, LaneCounters& counters) {
    distances.assign(points.size(), 0.0);
    run(fractal, [&](auto d, auto quadratic) {
        estimatePointLanes<quadratic(), false>(
            d, fractal, points, counters, [&](size_t begin, size_t count, const auto& out) {
                std::copy(out.distance, out.distance + count,
                          distances.begin() + std::ptrdiff_t(begin));
            });
    });
}
void PotentialNormals(const LaneFractal& fractal, const PointBatch& points,
                      const std::vector<int>& iterations, std::vector<Vector3d>& normals,
                      LaneCounters& counters) {
    run(fractal, [&](auto d, auto quadratic) {
        potentialNormalLanes<quadratic()>(d, fractal, points, &iterations, normals, counters);
    });
}
void PotentialNormalsAlone(const LaneFractal& fractal, const PointBatch& points,
                           std::vector<Vector3d>& normals, LaneCounters& counters) {
    run(fractal, [&](auto d, auto quadratic) {
        if constexpr (quadratic() && sizeof(hn::TFromD<decltype(d)>) == 4) {
            if (LaneConstants<decltype(d)>(d, fractal).threeNumbers) {
                potentialNormalLanes<true>(d, fractal, points, nullptr, normals, counters);
                return;
            }
        }
        // Elsewhere the counts come from the estimates.
        std::vector<PointEstimate> estimates;
        estimatePointLanes<quadratic()>(d, fractal, points, estimates, counters);
        std::vector<int> iterations(points.size());
        for (size_t i = 0; i < points.size(); ++i)
            iterations[i] = gradientIterationsOf(estimates[i], fractal.maxIterations);
        potentialNormalLanes<quadratic()>(d, fractal, points, &iterations, normals, counters);
    });
}
const char* TargetName() {
    return hwy::TargetName(HWY_TARGET);
}

}  // namespace HWY_NAMESPACE
}  // namespace quaternia
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace quaternia {

HWY_EXPORT(EstimatePoints);
HWY_EXPORT(EstimateDistances);
HWY_EXPORT(PotentialNormals);
HWY_EXPORT(PotentialNormalsAlone);
HWY_EXPORT(TargetName);

void estimatePoints(const LaneFractal& fractal, const PointBatch& points,
                    std::vector<PointEstimate>& results, LaneCounters& counters) {
    HWY_DYNAMIC_DISPATCH(EstimatePoints)(fractal, points, results, counters);
}
void estimateDistances(const LaneFractal& fractal, const PointBatch& points,
                       std::vector<double>& distances, LaneCounters& counters) {
    HWY_DYNAMIC_DISPATCH(EstimateDistances)(fractal, points, distances, counters);
}
void potentialNormals(const LaneFractal& fractal, const PointBatch& points,
                      const std::vector<int>& iterations, std::vector<Vector3d>& normals,
                      LaneCounters& counters) {
    HWY_DYNAMIC_DISPATCH(PotentialNormals)(fractal, points, iterations, normals, counters);
}
void potentialNormalsAlone(const LaneFractal& fractal, const PointBatch& points,
                           std::vector<Vector3d>& normals, LaneCounters& counters) {
    HWY_DYNAMIC_DISPATCH(PotentialNormalsAlone)(fractal, points, normals, counters);
}
const char* laneTargetName() {
    return HWY_DYNAMIC_DISPATCH(TargetName)();
}

}  // namespace quaternia
#endif  // HWY_ONCE
