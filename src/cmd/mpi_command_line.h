// quaternia-mpi's command line: its description and its commands, render and animate with
// quaternia's options. Declared apart from quaternia_mpi.cpp, and without MPI, so that
// `quaternia reference cli` lists quaternia-mpi's options from the very declarations its main
// parses with, on machines without MPI too.
#pragma once

#include <CLI/CLI.hpp>

#include "cmd/animate_command.h"
#include "cmd/render_command.h"

namespace quaternia {

struct MpiCommandLineOptions {
    RenderCommandOptions render;
    AnimateCommandOptions animate;
};

// Names and describes `app` as quaternia-mpi and adds its commands, parsed into `options`.
void describeMpiCommandLine(CLI::App& app, MpiCommandLineOptions& options);

}  // namespace quaternia
