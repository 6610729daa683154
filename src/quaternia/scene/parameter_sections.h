// The parameter table declared per section of the scene file: one function per section, each in
// the file of its group (parameter_table.cpp: what set is drawn; parameter_table_rendering.cpp:
// how it is seen and lit; parameter_table_scenery.cpp: the lights, material and ground;
// parameter_table_commands.cpp: the other commands and the film). buildParameterTable
// (parameter_table.cpp) joins them in the order below, the order in which --help, scene files
// and the explorer list the keys, so an entry's place within its function is its place there.
#pragma once

#include <vector>

#include "quaternia/scene/parameter_builders.h"
#include "quaternia/scene/parameters.h"

namespace quaternia::parameter_builders {

std::vector<Parameter> fractalParameters();
std::vector<Parameter> sliceParameters();
std::vector<Parameter> cameraParameters();
std::vector<Parameter> renderParameters();
std::vector<Parameter> shadingParameters();
// sceneryParameters() (parameter_builders.h): [light1] .. [light7], [material], [ground].
std::vector<Parameter> planeParameters();
std::vector<Parameter> meshParameters();
std::vector<Parameter> orbitParameters();
std::vector<Parameter> cyclesParameters();
std::vector<Parameter> animationParameters();

// `p` moved between animation keys by `motion` rather than numerically.
inline Parameter withMotion(Parameter p, Motion motion) {
    p.motion = motion;
    return p;
}

}  // namespace quaternia::parameter_builders
