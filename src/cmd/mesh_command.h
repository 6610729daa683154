// `quaternia mesh`: options, and meshing a scene's set to an STL, PLY or OBJ file.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cmd/scene_command.h"

namespace quaternia {

struct MeshCommandOptions : SceneCommandOptions {
    MeshCommandOptions() { output = "quaternia.stl"; }
    std::optional<int64_t> resolution;        // unset: mesh.resolution of the scene
    std::optional<double> iso, minComponent;  // unset: mesh.iso, mesh.min_component
};

void addMeshCommand(CLI::App& app, MeshCommandOptions& options);
// Meshes and writes the file; returns the process exit code. Throws UserError on bad input.
int runMeshCommand(const MeshCommandOptions& options);

}  // namespace quaternia
