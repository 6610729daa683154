// The keys of a film in TOML: `[[animation.keys]]` tables in a scene file, or the same as an
// inline array for `--set animation.keys=[{time = 0, "fractal.c" = [...]}, ...]` and the
// explorer. Each key has a `time` in seconds, optionally an `interpolation` ("smooth",
// "linear", "ease" or "step") and `shortest = true`, and any numbers of parameters of the table
// by their full name, quoted ("fractal.c" = [...]) or as dotted keys (fractal.c = [...]).
#pragma once

#include <string>
#include <vector>

#include <toml++/toml.h>

#include "quaternia/scene/scene.h"

namespace quaternia {

// Reads an array of key tables. Every error is a UserError naming the parameter (or
// "animation.keys") whose message starts with the place in the source: an element that is not
// a table, a missing or negative time, keys out of time order or with equal times, an unknown
// parameter (with the nearest name), a parameter of [animation], a value the table refuses, and
// text, choices or booleans with an interpolation other than step (validateAnimation's rules).
std::vector<AnimationKey> parseAnimationKeys(const toml::node& node, const std::string& sourceName,
                                             Interpolation defaultInterpolation);

// `--set animation.keys=...`: the inline array in `text`.
std::vector<AnimationKey> parseAnimationKeysText(const std::string& text,
                                                 Interpolation defaultInterpolation);

// The keys as `[[animation.keys]]` tables (nothing for none), full precision.
std::string animationKeysToToml(const std::vector<AnimationKey>& keys);

// The keys as one inline TOML array, as --set and the explorer take them.
std::string animationKeysToInlineToml(const std::vector<AnimationKey>& keys);

}  // namespace quaternia
