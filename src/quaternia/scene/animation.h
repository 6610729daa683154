// Films of a scene: the [animation] section (scene.h, AnimationSettings) turned into the scene
// of each frame. Frames are numbered from 1; frame n is at time (n - 1) / fps seconds.
//
// A parameter named by keys moves between them as the key at the start of each segment says
// (interpolation.h), holds the first key's value before it and the last key's after it; a
// parameter no key names keeps the scene's value. The shortcuts then add their motion on top,
// each over the whole film so that it closes into a loop (the frame after the last would be the
// first): the slice turns `turns` times in `turn_plane`, the camera turns `orbit_turns` times
// about camera.look_at around camera.up, and c goes once around a circle of `c_radius` about
// its keyed value in `c_plane`.
#pragma once

#include <cstdint>
#include <string>

#include "quaternia/scene/scene.h"

namespace quaternia {

// Whether the scene has keys or a shortcut that moves something.
bool isAnimated(const Scene& scene);

// The number of frames: animation.frames if set, else round(duration * fps) if a duration is
// set, else every frame up to the last key. Throws UserError("animation", ...) when there are no
// keys and no shortcut, or a shortcut without a duration or frame count.
int64_t filmFrameCount(const Scene& scene);

// Checks every key (strictly increasing, non-negative times; known parameters outside
// [animation]; values checked against the table; text, choices and booleans only with step
// interpolation; every key of one parameter with as many components, e.g. fractal.c with 4 or
// with 8) and the frame count; throws a UserError naming the problem.
void validateAnimation(const Scene& scene);

// The scene at `seconds` into the film, with the animation section back at its defaults (no
// keys, no shortcuts), so that rendering it draws that moment. Throws UserError when a moved
// value leaves its parameter's range (the camera orbiting past the range, c circling out).
Scene sceneAtTime(const Scene& film, double seconds);

// sceneAtTime at frame n's time; requires 1 <= frame <= filmFrameCount(film).
Scene sceneAtFrame(const Scene& film, int64_t frame);

// The one-line reason a key or value is not animatable, or empty: an unknown name (with the
// nearest one), a parameter of [animation] itself.
std::string animatableProblem(const std::string& name);

}  // namespace quaternia
