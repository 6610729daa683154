// `quaternia mesh`: options, and meshing a scene's set to an STL, PLY or OBJ file.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace quaternia {

struct MeshCommandOptions {
    std::string scenePath;  // empty: the embedded default scene
    std::string output = "quaternia.stl";
    std::optional<int64_t> resolution;        // unset: mesh.resolution of the scene
    std::optional<double> iso, minComponent;  // unset: mesh.iso, mesh.min_component
    std::vector<std::string> overrides;       // section.key=value
    int threads = 0;
    bool json = false;
};

void addMeshCommand(CLI::App& app, MeshCommandOptions& options);
// Meshes and writes the file; returns the process exit code. Throws UserError on bad input.
int runMeshCommand(const MeshCommandOptions& options);

}  // namespace quaternia
