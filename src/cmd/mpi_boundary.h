// quaternia-mpi's boundary: as cli_boundary.h, but with many ranks, every one of which parses
// the same command line and reads the same scene. An error is reported once: by rank 0 where it
// has one, else by each rank that has (a file it cannot see, say), and every rank then ends with
// the same exit code before any work.
#pragma once

#include <functional>
#include <optional>

#include <CLI/CLI.hpp>

#include "quaternia/distribute/mpi_channel.h"

namespace quaternia {

// Parses on every rank; help, version and parse errors are printed by rank 0 alone. An exit
// code where the program ends here.
std::optional<int> parseOnEveryRank(const MpiSession& mpi, CLI::App& app, int argc, char** argv);

// Runs setUp on every rank (reading and checking the scene, opening outputs on rank 0); 0 when
// every rank succeeded, else the exit code (2 for a UserError) after the error line.
int setUpOnEveryRank(const MpiSession& mpi, const std::function<void()>& setUp);

// Runs the work after a successful set-up: an error now ends the whole job (MPI_Abort) after its
// line, since the other ranks may be waiting for this one.
int runOrAbort(const MpiSession& mpi, const std::function<int()>& work);

}  // namespace quaternia
