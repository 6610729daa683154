// `quaternia cycles`: every periodic point of a given period of a complex polynomial, grouped
// into cycles, with multipliers and classes, as a table or JSON.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace quaternia {

struct CyclesCommandOptions {
    std::string formula = "z^2 + c";
    std::string c = "0";
    int period = 1;
    bool json = false;
};

void addCyclesCommand(CLI::App& app, CyclesCommandOptions& options);
// Prints the cycles; returns the exit code. Throws UserError on bad input.
int runCyclesCommand(const CyclesCommandOptions& options);

}  // namespace quaternia
