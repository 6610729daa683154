// `quaternia render`: options, and running a render from them.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "cmd/scene_command.h"

namespace quaternia {

struct RenderCommandOptions : SceneCommandOptions {
    RenderCommandOptions() { output = "quaternia.png"; }
    std::string depthOutput;  // empty: no depth pass
};

void addRenderCommand(CLI::App& app, RenderCommandOptions& options);
// Renders and writes the files; returns the process exit code. Throws UserError on bad input.
int runRenderCommand(const RenderCommandOptions& options);

}  // namespace quaternia
