// quaternia-mpi: quaternia's `render` and `animate` on the ranks of an MPI job (mpirun, srun).
// Every rank parses the same command line; rank 0 hands out the work and writes the image (or
// encodes the film), and prints; the others render. See mpi_commands.h.
#include <CLI/CLI.hpp>

#include "cmd/cli_boundary.h"
#include "cmd/mpi_boundary.h"
#include "cmd/mpi_command_line.h"
#include "cmd/mpi_commands.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/presets.h"

int main(int argc, char** argv) {
    using namespace quaternia;
    MpiSession mpi(argc, argv);
    reportFileSizeLimitAsAnError();
    CLI::App app;
    MpiCommandLineOptions options;
    describeMpiCommandLine(app, options);
    if (auto code = parseOnEveryRank(mpi, app, argc, argv)) return *code;
    if (app.got_subcommand("render")) return runMpiRender(mpi, options.render);
    return runMpiAnimate(mpi, options.animate);
}
