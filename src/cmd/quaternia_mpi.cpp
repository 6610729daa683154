// quaternia-mpi: quaternia's `render` and `animate` on the ranks of an MPI job (mpirun, srun).
// Every rank parses the same command line; rank 0 hands out the work and writes the image (or
// encodes the film), and prints; the others render. See mpi_commands.h.
#include <CLI/CLI.hpp>

#include "cmd/cli_boundary.h"
#include "cmd/mpi_boundary.h"
#include "cmd/mpi_commands.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/presets.h"

int main(int argc, char** argv) {
    using namespace quaternia;
    MpiSession mpi(argc, argv);
    reportFileSizeLimitAsAnError();
    CLI::App app(
        "quaternia-mpi: quaternia's render and animate spread over the ranks of an MPI job "
        "(mpirun -np N quaternia-mpi render ...). The files are byte for byte those of "
        "quaternia's commands.",
        "quaternia-mpi");
    app.require_subcommand(1);
    app.set_version_flag("--version", "quaternia-mpi 0.1.0");
    app.footer("Run `quaternia-mpi COMMAND --help` for a command's options (render, animate).");
    RenderCommandOptions renderOptions;
    addRenderCommand(app, renderOptions);
    AnimateCommandOptions animateOptions;
    addAnimateCommand(app, animateOptions);
    if (auto code = parseOnEveryRank(mpi, app, argc, argv)) return *code;
    if (app.got_subcommand("render")) return runMpiRender(mpi, renderOptions);
    return runMpiAnimate(mpi, animateOptions);
}
