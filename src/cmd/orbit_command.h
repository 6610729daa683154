// `quaternia orbit`: the fate of one orbit (escape, fixed, periodic, strictly preperiodic,
// attracted, undecided), its cycle's multipliers and class, and whether K is connected.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "cmd/dynamics_input.h"
#include "cmd/scene_command.h"

namespace quaternia {

// The scene ([SCENE.toml], --preset, --set) gives the map (fractal.formula, fractal.c) and
// [orbit]; the short flags override single keys after --set.
struct OrbitCommandOptions : SceneCommandOptions {
    MapFlags map;
    std::optional<std::string> z0;         // orbit.z0, in parseConstant's syntax
    std::optional<int64_t> maxIterations;  // orbit.max_iterations
};

void addOrbitCommand(CLI::App& app, OrbitCommandOptions& options);
// Prints the report; returns the exit code. Throws UserError on bad input.
int runOrbitCommand(const OrbitCommandOptions& options);

}  // namespace quaternia
