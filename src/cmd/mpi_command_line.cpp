#include "cmd/mpi_command_line.h"

namespace quaternia {

void describeMpiCommandLine(CLI::App& app, MpiCommandLineOptions& options) {
    app.name("quaternia-mpi");
    app.description(
        "quaternia-mpi: quaternia's render and animate spread over the ranks of an MPI job "
        "(mpirun -np N quaternia-mpi render ...). The files are byte for byte those of "
        "quaternia's commands.");
    app.require_subcommand(1);
    app.set_version_flag("--version", "quaternia-mpi 0.1.0");
    app.footer("Run `quaternia-mpi COMMAND --help` for a command's options (render, animate).");
    addRenderCommand(app, options.render);
    addAnimateCommand(app, options.animate);
}

}  // namespace quaternia
