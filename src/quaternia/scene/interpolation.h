// Interpolation of one animated parameter between its keys (animation.h). A track is the keys
// that name one parameter: strictly increasing times, a value of the same dimension at each,
// and for each segment [t_i, t_i+1] the way it moves (the key at its start says which).
//
// - Step holds the value of the key at the segment's start.
// - Linear moves at constant speed; Ease starts and stops with zero speed (3u^2 - 2u^3).
// - Smooth is the monotone cubic Hermite spline of Steffen (1990, "A simple method for
//   monotonic interpolation in one dimension", A&A 239, 443): it passes through every key with
//   a continuous first derivative, and where three consecutive keys are monotone it stays
//   monotone between them (no overshoot), because each key's slope is limited by the secant
//   slopes on both sides.
// Vectors move component by component; unit quaternions (Motion::Rotation) move on the unit
// sphere: slerp for Linear and Ease, the componentwise Smooth curve projected back onto the
// sphere for Smooth (a projection of a C^1 curve that avoids 0 is C^1, and unit values at the
// keys are kept exactly), so a 4D rotation stays a rotation between keys.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace quaternia {

enum class Interpolation { Linear, Smooth, Ease, Step };

// The words scene files use: "smooth", "linear", "ease", "step".
const char* interpolationName(Interpolation interpolation);
std::optional<Interpolation> interpolationNamed(std::string_view name);
// Every word with its interpolation, smooth first (the parameter table's choices).
std::vector<std::pair<std::string, Interpolation>> interpolationChoices();

// What the numbers of a track are, which decides how they may move.
enum class Motion {
    Numeric,  // reals, integers, vectors: component by component
    Angle,    // degrees; keys marked `shortest` move to the next by at most 180 per component
    Rotation  // a quaternion used as a rotation: kept on the unit sphere
};

struct TrackKey {
    double time = 0;
    std::vector<double> value;
    Interpolation interpolation = Interpolation::Smooth;  // of the segment from this key
    bool shortest = false;  // Motion::Angle: the segment from this key takes the short way
};

// The track's value at `time`: the first key's value before it, the last key's after it.
// Requires at least one key, strictly increasing times and values of one dimension (the caller,
// animation.cpp, checks those and reports them as user errors).
std::vector<double> interpolateTrack(const std::vector<TrackKey>& keys, Motion motion, double time);

// Steffen's slopes of the points (times[i], values[i]), one per point.
std::vector<double> monotoneSlopes(const std::vector<double>& times,
                                   const std::vector<double>& values);

}  // namespace quaternia
