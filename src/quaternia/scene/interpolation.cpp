#include "quaternia/scene/interpolation.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>

namespace quaternia {
namespace {

constexpr std::pair<const char*, Interpolation> kInterpolationNames[] = {
    {"smooth", Interpolation::Smooth},
    {"linear", Interpolation::Linear},
    {"ease", Interpolation::Ease},
    {"step", Interpolation::Step},
};

double sign(double x) {
    return x > 0 ? 1.0 : x < 0 ? -1.0 : 0.0;
}

// Hermite basis on one segment of length h at u in [0, 1], with end values y0, y1 and slopes
// m0, m1 (per unit time).
double hermite(double y0, double y1, double m0, double m1, double h, double u) {
    double u2 = u * u, u3 = u2 * u;
    return (2 * u3 - 3 * u2 + 1) * y0 + (u3 - 2 * u2 + u) * h * m0 + (-2 * u3 + 3 * u2) * y1 +
           (u3 - u2) * h * m1;
}

double norm(const std::vector<double>& v) {
    double sum = 0;
    for (double x : v)
        sum += x * x;
    return std::sqrt(sum);
}

std::vector<double> normalized(std::vector<double> v) {
    double length = norm(v);
    if (length > 0)
        for (double& x : v)
            x /= length;
    return v;
}

// Spherical linear interpolation between unit vectors a and b (Shoemake 1985), along the great
// circle through both; a and b opposite have no such circle, and one through a perpendicular
// of a is taken.
std::vector<double> slerp(const std::vector<double>& a, const std::vector<double>& b, double u) {
    double cosine = 0;
    for (std::size_t k = 0; k < a.size(); ++k)
        cosine += a[k] * b[k];
    cosine = std::clamp(cosine, -1.0, 1.0);
    std::vector<double> towards = b;
    if (cosine < -1 + 1e-12 && a.size() == 4) towards = {-a[1], a[0], -a[3], a[2]};
    // The component of `towards` perpendicular to a, made unit: a, e span the circle.
    double along = 0;
    for (std::size_t k = 0; k < a.size(); ++k)
        along += a[k] * towards[k];
    std::vector<double> e(a.size());
    for (std::size_t k = 0; k < a.size(); ++k)
        e[k] = towards[k] - along * a[k];
    double eLength = norm(e);
    if (eLength < 1e-300) return a;  // a == b
    double angle = std::acos(cosine) * u;
    std::vector<double> out(a.size());
    for (std::size_t k = 0; k < a.size(); ++k)
        out[k] = std::cos(angle) * a[k] + std::sin(angle) * e[k] / eLength;
    return out;
}

// The keys as the motion sees them: angles unwrapped where a key asks for the short way,
// rotations made unit.
std::vector<TrackKey> prepared(std::vector<TrackKey> keys, Motion motion) {
    if (motion == Motion::Angle) {
        for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
            if (!keys[i].shortest) continue;
            for (std::size_t k = 0; k < keys[i].value.size(); ++k) {
                double turns = std::round((keys[i + 1].value[k] - keys[i].value[k]) / 360);
                keys[i + 1].value[k] -= 360 * turns;
            }
        }
    } else if (motion == Motion::Rotation) {
        for (TrackKey& key : keys)
            key.value = normalized(key.value);
    }
    return keys;
}

double smoothstep(double u) {
    return u * u * (3 - 2 * u);
}

}  // namespace

const char* interpolationName(Interpolation interpolation) {
    for (const auto& [name, value] : kInterpolationNames)
        if (value == interpolation) return name;
    return "smooth";
}

std::optional<Interpolation> interpolationNamed(std::string_view name) {
    for (const auto& [word, value] : kInterpolationNames)
        if (name == word) return value;
    return std::nullopt;
}

std::vector<std::pair<std::string, Interpolation>> interpolationChoices() {
    std::vector<std::pair<std::string, Interpolation>> choices;
    for (const auto& [word, value] : kInterpolationNames)
        choices.emplace_back(word, value);
    return choices;
}

std::vector<double> monotoneSlopes(const std::vector<double>& times,
                                   const std::vector<double>& values) {
    const std::size_t n = times.size();
    std::vector<double> slopes(n, 0.0);
    if (n < 2) return slopes;
    std::vector<double> h(n - 1), secant(n - 1);
    for (std::size_t i = 0; i + 1 < n; ++i) {
        h[i] = times[i + 1] - times[i];
        secant[i] = (values[i + 1] - values[i]) / h[i];
    }
    if (n == 2) return {secant[0], secant[0]};
    // Interior keys: the parabola through three keys gives p; its slope is cut to at most twice
    // the smaller secant, and to 0 where the secants change sign (a local extremum stays one).
    for (std::size_t i = 1; i + 1 < n; ++i) {
        double p = (secant[i - 1] * h[i] + secant[i] * h[i - 1]) / (h[i - 1] + h[i]);
        slopes[i] = (sign(secant[i - 1]) + sign(secant[i])) *
                    std::min({std::abs(secant[i - 1]), std::abs(secant[i]), 0.5 * std::abs(p)});
    }
    // End keys: the slope of the parabola through the three keys at that end, kept between 0
    // and twice the end secant so that the end segment does not overshoot (Steffen, eq. 26-27).
    auto endSlope = [](double secantNear, double secantFar, double hNear, double hFar) {
        double p = secantNear * (1 + hNear / (hNear + hFar)) - secantFar * hNear / (hNear + hFar);
        if (p * secantNear <= 0) return 0.0;
        if (std::abs(p) > 2 * std::abs(secantNear)) return 2 * secantNear;
        return p;
    };
    slopes[0] = endSlope(secant[0], secant[1], h[0], h[1]);
    slopes[n - 1] = endSlope(secant[n - 2], secant[n - 3], h[n - 2], h[n - 3]);
    return slopes;
}

std::vector<double> interpolateTrack(const std::vector<TrackKey>& givenKeys, Motion motion,
                                     double time) {
    if (givenKeys.size() == 1 || time <= givenKeys.front().time) return givenKeys.front().value;
    if (time >= givenKeys.back().time) {
        // The last key's value as given (unwrapping may have moved it by whole turns).
        return givenKeys.back().value;
    }
    const std::vector<TrackKey> keys = prepared(givenKeys, motion);
    std::size_t i = 0;  // the segment [keys[i].time, keys[i + 1].time) holding `time`
    while (keys[i + 1].time <= time)
        ++i;
    const TrackKey& from = keys[i];
    const TrackKey& to = keys[i + 1];
    if (time == from.time) return givenKeys[i].value;
    const double h = to.time - from.time;
    const double u = (time - from.time) / h;
    const std::size_t dimension = from.value.size();

    std::vector<double> out(dimension);
    switch (from.interpolation) {
        case Interpolation::Step:
            return givenKeys[i].value;
        case Interpolation::Linear:
        case Interpolation::Ease: {
            double v = from.interpolation == Interpolation::Ease ? smoothstep(u) : u;
            if (motion == Motion::Rotation) return slerp(from.value, to.value, v);
            for (std::size_t k = 0; k < dimension; ++k)
                out[k] = from.value[k] + (to.value[k] - from.value[k]) * v;
            break;
        }
        case Interpolation::Smooth: {
            std::vector<double> times(keys.size()), component(keys.size());
            for (std::size_t j = 0; j < keys.size(); ++j)
                times[j] = keys[j].time;
            for (std::size_t k = 0; k < dimension; ++k) {
                for (std::size_t j = 0; j < keys.size(); ++j)
                    component[j] = keys[j].value[k];
                std::vector<double> slopes = monotoneSlopes(times, component);
                out[k] = hermite(from.value[k], to.value[k], slopes[i], slopes[i + 1], h, u);
            }
            if (motion == Motion::Rotation) {
                // Near 0 the projection is undefined: there the great circle stands in.
                if (norm(out) < 1e-6) return slerp(from.value, to.value, u);
                return normalized(out);
            }
            break;
        }
    }
    if (motion == Motion::Angle)
        for (double& angle : out)
            if (std::abs(angle) > 360) angle = std::fmod(angle, 360.0);
    return out;
}

}  // namespace quaternia
