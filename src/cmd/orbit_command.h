// `quaternia orbit`: the fate of one orbit (escape, fixed, periodic, strictly preperiodic,
// attracted, undecided), its cycle's multipliers and class, and whether K is connected.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace quaternia {

struct OrbitCommandOptions {
    std::string formula = "z^2 + c";
    std::string c = "0";
    std::string z0 = "0";
    int maxIterations = 1000;
    bool json = false;
};

inline constexpr int kMaxOrbitIterations = 1000000;

void addOrbitCommand(CLI::App& app, OrbitCommandOptions& options);
// Prints the report; returns the exit code. Throws UserError on bad input.
int runOrbitCommand(const OrbitCommandOptions& options);

}  // namespace quaternia
