#include "quaternia/scene/animation.h"

#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "quaternia/scene/parameters.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

std::vector<double> asNumbers(const ParameterValue& value) {
    if (const auto* real = std::get_if<double>(&value)) return {*real};
    if (const auto* integer = std::get_if<int64_t>(&value)) return {double(*integer)};
    if (const auto* vector = std::get_if<std::vector<double>>(&value)) return *vector;
    return {};
}

bool isNumeric(const Parameter& p) {
    return p.type != ParameterType::Text && p.type != ParameterType::Choice &&
           p.type != ParameterType::Boolean;
}

// The value of a numeric parameter from interpolated numbers: integers rounded to the nearest.
ParameterValue fromNumbers(const Parameter& p, const std::vector<double>& numbers) {
    if (p.type == ParameterType::Real) return numbers[0];
    if (p.type == ParameterType::Integer) return int64_t(std::llround(numbers[0]));
    return numbers;
}

// The parameters the keys name, in table order, each with the keys that name it.
struct Track {
    const Parameter* parameter;
    std::vector<TrackKey> numericKeys;                     // numeric parameters
    std::vector<std::pair<double, ParameterValue>> steps;  // text, choices and booleans
};

std::string keyLabel(std::size_t index, const AnimationKey& key) {
    return "animation key " + std::to_string(index + 1) + " (time " + formatValue(key.time) + ")";
}

// Throws UserError(name) where a parameter whose length may vary (fractal.c: 4 or 8) has keys of
// different lengths: they cannot be interpolated into each other.
std::vector<Track> tracksOf(const AnimationSettings& animation) {
    std::vector<Track> tracks;
    for (const Parameter& p : parameterTable()) {
        Track track{&p, {}, {}};
        for (std::size_t i = 0; i < animation.keys.size(); ++i) {
            const AnimationKey& key = animation.keys[i];
            for (const auto& [name, value] : key.values) {
                if (name != p.name()) continue;
                if (isNumeric(p)) {
                    std::vector<double> numbers = asNumbers(value);
                    if (!track.numericKeys.empty() &&
                        numbers.size() != track.numericKeys.front().value.size())
                        throw UserError(name,
                                        keyLabel(i, key) + ": " + name + " has " +
                                            std::to_string(numbers.size()) +
                                            " components, but an earlier key gives it " +
                                            std::to_string(track.numericKeys.front().value.size()) +
                                            "; every key of a parameter needs as many");
                    track.numericKeys.push_back(
                        {key.time, std::move(numbers),
                         key.interpolation.value_or(animation.interpolation), key.shortest});
                } else {
                    track.steps.emplace_back(key.time, value);
                }
            }
        }
        if (!track.numericKeys.empty() || !track.steps.empty()) tracks.push_back(track);
    }
    return tracks;
}

ParameterValue stepValueAt(const std::vector<std::pair<double, ParameterValue>>& steps,
                           double seconds) {
    const ParameterValue* value = &steps.front().second;
    for (const auto& [time, stepValue] : steps)
        if (time <= seconds) value = &stepValue;
    return *value;
}

// Components (a, b) of H that a rotation plane turns, in (1, i, j, k) order.
std::pair<int, int> planeAxes(RotationPlane plane) {
    switch (plane) {
        case RotationPlane::OneI:
            return {0, 1};
        case RotationPlane::OneJ:
            return {0, 2};
        case RotationPlane::OneK:
            return {0, 3};
        case RotationPlane::IJ:
            return {1, 2};
        case RotationPlane::IK:
            return {1, 3};
        case RotationPlane::JK:
            return {2, 3};
        case RotationPlane::None:
            break;
    }
    return {-1, -1};
}

bool hasShortcut(const AnimationSettings& a) {
    return (a.turnPlane != RotationPlane::None && a.turns != 0) || a.orbitTurns != 0 ||
           a.cRadius != 0;
}

double wrapDegrees(double angle) {
    return std::abs(angle) > 360 ? std::fmod(angle, 360.0) : angle;
}

// The shortcuts' motion at `fraction` of the film (0 at the first frame, 1 one frame after the
// last), added to the keyed scene.
void applyShortcuts(const AnimationSettings& a, double fraction, Scene& scene) {
    constexpr double kTau = 2 * std::numbers::pi;
    if (a.turnPlane != RotationPlane::None && a.turns != 0) {
        // slice.angles lists its planes in RotationPlane's order, after None.
        int index = int(a.turnPlane) - 1;
        std::vector<double> angles(scene.slice.anglesDegrees.begin(),
                                   scene.slice.anglesDegrees.end());
        angles[index] = wrapDegrees(angles[index] + 360 * a.turns * fraction);
        setParameter(scene, "slice.angles", angles);
    }
    if (a.orbitTurns != 0) {
        // Rodrigues' rotation of the camera about the axis camera.up through camera.look_at.
        double angle = kTau * a.orbitTurns * fraction;
        Vector3d axis = normalize(scene.camera.up);
        Vector3d v = scene.camera.position - scene.camera.lookAt;
        Vector3d turned = v * std::cos(angle) + cross(axis, v) * std::sin(angle) +
                          axis * (dot(axis, v) * (1 - std::cos(angle)));
        Point3d position = scene.camera.lookAt + turned;
        setParameter(scene, "camera.position",
                     std::vector<double>{position.x, position.y, position.z});
    }
    if (a.cRadius != 0) {
        auto [first, second] = planeAxes(a.cPlane);
        double angle = kTau * fraction;
        // All of c's components (8 in the 8-component algebras); the plane turns two of the
        // first 4.
        auto c = std::get<std::vector<double>>(findParameter("fractal.c")->read(scene));
        c[std::size_t(first)] += a.cRadius * std::cos(angle);
        c[std::size_t(second)] += a.cRadius * std::sin(angle);
        setParameter(scene, "fractal.c", c);
    }
}

}  // namespace

std::string animatableProblem(const std::string& name) {
    const Parameter* p = findParameter(name);
    if (p == nullptr)
        return "unknown parameter '" + name + "' (did you mean '" + nearestParameterName(name) +
               "'?)";
    if (p->section == "animation") return name + " is the animation's own setting, not animatable";
    return {};
}

bool isAnimated(const Scene& scene) {
    return !scene.animation.keys.empty() || hasShortcut(scene.animation);
}

int64_t filmFrameCount(const Scene& scene) {
    const AnimationSettings& a = scene.animation;
    if (!isAnimated(scene))
        throw UserError("animation",
                        "the scene has no animation: add [[animation.keys]] or a shortcut "
                        "(animation.turn_plane, animation.orbit_turns, animation.c_radius)");
    if (a.frames > 0) return a.frames;
    if (a.duration > 0) return std::max<int64_t>(1, std::llround(a.duration * a.fps));
    if (hasShortcut(a))
        throw UserError("animation.duration",
                        "the shortcut motions last the whole film: set animation.duration or "
                        "animation.frames");
    // Every frame whose time is at most the last key's (with a little slack for rounding).
    return int64_t(std::floor(a.keys.back().time * a.fps + 1e-9)) + 1;
}

void validateAnimation(const Scene& scene) {
    const AnimationSettings& a = scene.animation;
    for (std::size_t i = 0; i < a.keys.size(); ++i) {
        const AnimationKey& key = a.keys[i];
        std::string where = keyLabel(i, key);
        if (!std::isfinite(key.time) || key.time < 0)
            throw UserError("animation.keys", where + ": time must be a number >= 0");
        if (i > 0 && !(key.time > a.keys[i - 1].time))
            throw UserError("animation.keys",
                            where +
                                ": keys must be in increasing time order with different "
                                "times (the key before is at " +
                                formatValue(a.keys[i - 1].time) + ")");
        if (key.values.empty()) throw UserError("animation.keys", where + " names no parameter");
        for (const auto& [name, value] : key.values) {
            if (std::string problem = animatableProblem(name); !problem.empty())
                throw UserError(name, where + ": " + problem);
            const Parameter& p = *findParameter(name);
            checkedValue(p, value);
            if (!isNumeric(p) && key.interpolation.value_or(a.interpolation) != Interpolation::Step)
                throw UserError(name, where + ": " + name + " is " + describeType(p) +
                                          " and can change only at a key: give this key "
                                          "interpolation = \"step\"");
        }
    }
    tracksOf(a);  // keys of one parameter with different lengths
    filmFrameCount(scene);
}

Scene sceneAtTime(const Scene& film, double seconds) {
    Scene scene = film;
    scene.animation = defaultScene().animation;
    for (const Track& track : tracksOf(film.animation)) {
        const Parameter& p = *track.parameter;
        ParameterValue value =
            isNumeric(p) ? fromNumbers(p, interpolateTrack(track.numericKeys, p.motion, seconds))
                         : stepValueAt(track.steps, seconds);
        setParameter(scene, p.name(), value);
    }
    if (hasShortcut(film.animation)) {
        double filmSeconds = double(filmFrameCount(film)) / film.animation.fps;
        applyShortcuts(film.animation, seconds / filmSeconds, scene);
    }
    return scene;
}

Scene sceneAtFrame(const Scene& film, int64_t frame) {
    return sceneAtTime(film, double(frame - 1) / film.animation.fps);
}

}  // namespace quaternia
