// `quaternia render`: options, and running a render from them.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "cmd/scene_command.h"
#include "quaternia/render/render.h"
#include "quaternia/scene/json.h"

namespace quaternia {

struct RenderCommandOptions : SceneCommandOptions {
    RenderCommandOptions() { output = "quaternia.png"; }
    std::string depthOutput;     // empty: no depth pass
    std::string certifyOutput;   // --certify: the classes PNG (pixel_certificate.h); empty: none
    bool tintUndecided = false;  // --tint-undecided: undecided pixels tinted over the picture
};

// The summary of a render on stdout: one line, or with --json an object, `extra`'s fields added.
void printRenderSummary(const RenderCommandOptions& options, const Scene& scene,
                        const RenderStats& stats, const Json& extra = Json::object());

void addRenderCommand(CLI::App& app, RenderCommandOptions& options);
// Renders and writes the files; returns the process exit code. Throws UserError on bad input.
int runRenderCommand(const RenderCommandOptions& options);

// Whether an output path names an OpenEXR file (*.exr, any case): `render` then writes the
// linear colour and passes (render_exr.h).
bool isExrPath(const std::string& path);

}  // namespace quaternia
