// `quaternia plane`: 2D images of Julia sets, the Mandelbrot set, basins and slices of H.
#pragma once

#include <CLI/CLI.hpp>

#include "cmd/scene_command.h"

namespace quaternia {

struct PlaneCommandOptions : SceneCommandOptions {
    PlaneCommandOptions() { output = "plane.png"; }
    std::string certify;  // --certify: the classes' grey PNG (plane_certificate.h); empty: none
};

void addPlaneCommand(CLI::App& app, PlaneCommandOptions& options);
// Draws and writes the image; returns the process exit code. Throws UserError on bad input.
int runPlaneCommand(const PlaneCommandOptions& options);

}  // namespace quaternia
