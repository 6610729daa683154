// Interpolation between keys (interpolation.h): through every key exactly, monotone between
// monotone keys (Steffen 1990), continuous first derivative, rotations on the unit sphere.
#include "quaternia/scene/interpolation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace quaternia {
namespace {

std::vector<TrackKey> keysOf(const std::vector<double>& times, const std::vector<double>& values,
                             Interpolation interpolation) {
    std::vector<TrackKey> keys;
    for (std::size_t i = 0; i < times.size(); ++i)
        keys.push_back({times[i], {values[i]}, interpolation, false});
    return keys;
}

double at(const std::vector<TrackKey>& keys, double time, Motion motion = Motion::Numeric) {
    return interpolateTrack(keys, motion, time)[0];
}

TEST(Interpolation, PassesThroughEveryKeyExactly) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> value(-50, 50), gap(0.1, 3);
    for (Interpolation mode :
         {Interpolation::Smooth, Interpolation::Linear, Interpolation::Ease, Interpolation::Step}) {
        std::vector<double> times{0}, values{value(rng)};
        for (int i = 0; i < 9; ++i) {
            times.push_back(times.back() + gap(rng));
            values.push_back(value(rng));
        }
        auto keys = keysOf(times, values, mode);
        for (std::size_t i = 0; i < times.size(); ++i)
            EXPECT_EQ(at(keys, times[i]), values[i]) << int(mode) << " key " << i;
        EXPECT_EQ(at(keys, -1), values.front());
        EXPECT_EQ(at(keys, times.back() + 1), values.back());
    }
}

TEST(Interpolation, SmoothIsMonotoneBetweenMonotoneKeysWithoutOvershoot) {
    // Rising keys with uneven steps (a flat stretch, a jump): a Catmull-Rom spline overshoots
    // the jump and dips in the flat part; Steffen's slopes must not.
    std::vector<double> times{0, 1, 2, 2.5, 4, 5}, values{0, 0.1, 0.1, 3, 3.2, 3.2};
    auto keys = keysOf(times, values, Interpolation::Smooth);
    double previous = at(keys, 0);
    for (int step = 1; step <= 5000; ++step) {
        double t = 5.0 * step / 5000, v = at(keys, t);
        EXPECT_GE(v, previous - 1e-12) << "t = " << t;
        previous = v;
        // Within each segment, between its two keys.
        std::size_t i = 0;
        while (i + 2 < times.size() && times[i + 1] <= t)
            ++i;
        EXPECT_GE(v, std::min(values[i], values[i + 1]) - 1e-12) << "t = " << t;
        EXPECT_LE(v, std::max(values[i], values[i + 1]) + 1e-12) << "t = " << t;
    }
}

TEST(Interpolation, SmoothHasAContinuousFirstDerivative) {
    std::vector<double> times{0, 0.7, 2, 3.1, 4}, values{1, -2, 0.5, 0.4, 3};
    auto keys = keysOf(times, values, Interpolation::Smooth);
    const double h = 1e-6;
    for (std::size_t i = 1; i + 1 < times.size(); ++i) {
        double left = (at(keys, times[i]) - at(keys, times[i] - h)) / h;
        double right = (at(keys, times[i] + h) - at(keys, times[i])) / h;
        EXPECT_NEAR(left, right, 1e-4) << "key " << i;
    }
    // And the linear segments' kinks are real, so the measure can tell.
    auto linear = keysOf(times, values, Interpolation::Linear);
    double left = (at(linear, 0.7) - at(linear, 0.7 - h)) / h;
    double right = (at(linear, 0.7 + h) - at(linear, 0.7)) / h;
    EXPECT_GT(std::abs(left - right), 1);
}

TEST(Interpolation, SmoothKeepsAStraightLineStraight) {
    auto keys = keysOf({0, 1, 3, 4}, {2, 4, 8, 10}, Interpolation::Smooth);
    for (double t = 0; t <= 4; t += 0.125)
        EXPECT_NEAR(at(keys, t), 2 + 2 * t, 1e-12);
}

TEST(Interpolation, EaseStopsAtKeysAndStepHolds) {
    auto ease = keysOf({0, 2}, {0, 10}, Interpolation::Ease);
    EXPECT_NEAR(at(ease, 1e-4) / 1e-4, 0, 1e-3);  // zero speed at the start
    EXPECT_DOUBLE_EQ(at(ease, 1), 5);             // half way at half time
    auto step = keysOf({0, 2, 3}, {1, 5, 9}, Interpolation::Step);
    EXPECT_EQ(at(step, 1.999), 1);
    EXPECT_EQ(at(step, 2), 5);
    EXPECT_EQ(at(step, 2.5), 5);
}

TEST(Interpolation, AnglesTakeTheShortWayOnlyWhereAsked) {
    auto keys = keysOf({0, 1}, {350, 10}, Interpolation::Linear);
    EXPECT_DOUBLE_EQ(at(keys, 0.5, Motion::Angle), 180);  // the long way, as written
    keys[0].shortest = true;
    EXPECT_NEAR(std::remainder(at(keys, 0.5, Motion::Angle), 360), 0, 1e-12);
    EXPECT_NEAR(std::remainder(at(keys, 0.25, Motion::Angle), 360), -5, 1e-12);
    EXPECT_EQ(at(keys, 1, Motion::Angle), 10);  // the key as given
}

TEST(Interpolation, RotationsStayUnitAndPassThroughTheirKeys) {
    std::mt19937 rng(3);
    std::normal_distribution<double> normal;
    std::vector<TrackKey> keys;
    for (int i = 0; i < 6; ++i) {
        std::vector<double> q{normal(rng), normal(rng), normal(rng), normal(rng)};
        double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        for (double& x : q)
            x /= n;
        keys.push_back({double(i), q, Interpolation(i % 3), false});  // linear, smooth, ease
    }
    for (double t = 0; t <= 5; t += 0.01) {
        auto q = interpolateTrack(keys, Motion::Rotation, t);
        double n2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
        EXPECT_NEAR(n2, 1, 1e-12) << "t = " << t;
    }
    for (const TrackKey& key : keys)
        for (int k = 0; k < 4; ++k)
            EXPECT_NEAR(interpolateTrack(keys, Motion::Rotation, key.time)[k], key.value[k], 1e-15);
}

TEST(Interpolation, LinearRotationTurnsAtConstantSpeed) {
    // From 1 to exp(i pi/3) = cos 60 + i sin 60: a third of the time turns 20 degrees.
    std::vector<TrackKey> keys{{0, {1, 0, 0, 0}, Interpolation::Linear, false},
                               {3, {0.5, std::sqrt(3) / 2, 0, 0}, Interpolation::Linear, false}};
    auto q = interpolateTrack(keys, Motion::Rotation, 1);
    EXPECT_NEAR(q[0], std::cos(M_PI / 9), 1e-12);
    EXPECT_NEAR(q[1], std::sin(M_PI / 9), 1e-12);
}

}  // namespace
}  // namespace quaternia
