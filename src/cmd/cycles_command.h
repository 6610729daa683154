// `quaternia cycles`: every periodic point of a given period of a complex polynomial, grouped
// into cycles, with multipliers and classes, as a table or JSON.
#pragma once

#include <cstdint>
#include <optional>

#include <CLI/CLI.hpp>

#include "cmd/dynamics_input.h"
#include "cmd/scene_command.h"

namespace quaternia {

// The scene ([SCENE.toml], --preset, --set) gives the map (fractal.formula, fractal.c) and
// cycles.period; the short flags override single keys after --set.
struct CyclesCommandOptions : SceneCommandOptions {
    MapFlags map;
    std::optional<int64_t> period;  // cycles.period
};

void addCyclesCommand(CLI::App& app, CyclesCommandOptions& options);
// Prints the cycles; returns the exit code. Throws UserError on bad input.
int runCyclesCommand(const CyclesCommandOptions& options);

}  // namespace quaternia
