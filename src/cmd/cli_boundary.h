// The command line's boundary, shared by quaternia and quaternia-explore: where parse errors and
// user errors become one line on standard error with exit code 2, and anything else an internal
// error with exit code 1. The library below never prints and never exits.
#pragma once

#include <cstdio>
#include <exception>
#include <optional>

#include <CLI/CLI.hpp>

#include "quaternia/util/error.h"

namespace quaternia {

// Parses the arguments; an exit code where the program ends here (help, version, a bad
// argument), nothing where the command is to run. `helpCommand` is named in the error line.
inline std::optional<int> parseCommandLine(CLI::App& app, int argc, char** argv,
                                           const char* helpCommand) {
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "quaternia: error: %s (see %s --help)\n", e.what(), helpCommand);
        return 2;
    }
    return std::nullopt;
}

// Runs the command and returns its exit code.
template <class Command>
int runAtBoundary(const Command& command) {
    try {
        return command();
    } catch (const UserError& e) {
        std::fprintf(stderr, "quaternia: error: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "quaternia: internal error: %s\n", e.what());
        return 1;
    }
}

}  // namespace quaternia
