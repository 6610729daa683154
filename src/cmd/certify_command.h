// `quaternia certify`: the filled Julia set K itself, not K_N, by cell mapping (cellmap/): a
// classes PNG of a complex plane image (-o ending in .png), or the certified cells of the
// scene's set in its reduced space or as a product (any other -o, read back by
// render.certified).
#pragma once

#include <CLI/CLI.hpp>

#include "cmd/scene_command.h"

namespace quaternia {

struct CertifyCommandOptions : SceneCommandOptions {
    CertifyCommandOptions() { output = "certified.png"; }
    int resolution = 256;  // --resolution: finest cells per axis of the set's grid
};

void addCertifyCommand(CLI::App& app, CertifyCommandOptions& options);
// Certifies and writes; returns the process exit code. Throws UserError on bad input.
int runCertifyCommand(const CertifyCommandOptions& options);

}  // namespace quaternia
