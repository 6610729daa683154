// The explorer's timeline: the film of the view a request names (its animation.keys and
// [animation] keys). Every frame is the library's sceneAtFrame, never interpolated by the page,
// so that what the page plays is what `quaternia animate` renders.
#pragma once

#include <cstdint>
#include <string>

#include "quaternia/scene/scene.h"
#include "server/explore_request.h"

namespace quaternia {

// The query parameter of /api/frame that is not a scene key: the frame number, from 1.
inline constexpr const char* kFrameParameter = "frame";

// Removes "frame" from `query` and returns it. Throws UserError("frame", ...) when it is
// missing or not a whole number from 1.
int64_t takeFrameNumber(QueryParameters& query);

// Frame `frame` of the film, checked as /api/render checks a view (sceneFromQuery's bounds and
// checkInteractiveImage), since keys may move any parameter. Throws UserError naming the
// problem: a bad film (validateAnimation), a frame outside 1..filmFrameCount, a bound.
Scene filmFrame(const Scene& film, int64_t frame, const ExploreLimits& limits);

// {"frames": n, "fps": f, "seconds": n / f, "keys": [{"time", "interpolation", "shortest",
// "values": {name: value}}]}: frames 0 when the scene has no animation. A key's "values" are
// every parameter any key names, at that key's time (without the shortcuts' motion): the view
// the key shows. "interpolation" is null for a key that does not name one. Throws UserError
// for a bad film (validateAnimation).
std::string filmJson(const Scene& film);

}  // namespace quaternia
