// Scenes shared by the tests: the reference cases of tests/data/reference and analytic ones.
#pragma once

#include <string>

#include "quaternia/scene/scene.h"

namespace quaternia::testing {

// Path of a file under tests/data.
std::string testDataPath(const std::string& relative);
// A reference case by id (e.g. "case01_sqr_A"), loaded from its scene file.
Scene referenceScene(const std::string& id);
// c = 0: the unit ball of H, whose slice is the unit ball of R^3.
Scene unitBallScene(int width, int height);
// The unit ball lit by nothing (no key, fill or ambient light, no occlusion or highlight),
// solid white, gamma 1, opaque over a black background: a scene to add one light or material
// to and compare with optics.
Scene darkUnitBallScene(int width, int height);

}  // namespace quaternia::testing
