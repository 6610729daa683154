// `quaternia render`: options, and running a render from them.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace quaternia {

struct RenderCommandOptions {
    std::string scenePath;  // empty: the embedded default scene
    std::string output = "quaternia.png";
    std::string depthOutput;               // empty: no depth pass
    std::optional<int64_t> width, height;  // unset: from the scene
    std::vector<std::string> overrides;    // section.key=value
    int threads = 0;
    bool json = false;
};

void addRenderCommand(CLI::App& app, RenderCommandOptions& options);
// Renders and writes the files; returns the process exit code. Throws UserError on bad input.
int runRenderCommand(const RenderCommandOptions& options);

}  // namespace quaternia
