// The command line's boundary, shared by quaternia and quaternia-explore: where parse errors and
// user errors become one line on standard error with exit code 2, and anything else an internal
// error with exit code 1. The library below never prints and never exits.
#pragma once

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>
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

// A file-size limit (RLIMIT_FSIZE, `ulimit -f`) kills a process that writes past it with
// SIGXFSZ, mid-file and without a word. Ignored, the write fails with EFBIG instead, and the
// output's AtomicFile reports it and leaves no partial file. Children (ffmpeg) inherit it.
inline void reportFileSizeLimitAsAnError() {
    std::signal(SIGXFSZ, SIG_IGN);
}

// Standard output (the summary, the JSON, orbit's and cycles' answers) that could not be written
// (a full disk, a closed descriptor) is a failure like any other output's: one line, exit 2.
inline int checkStandardOutput(int code) {
    const int error = std::fflush(stdout) != 0 ? errno : 0;
    if (error == 0 && !std::ferror(stdout)) return code;
    std::fprintf(stderr, "quaternia: error: cannot write standard output%s%s\n", error ? ": " : "",
                 error ? std::strerror(error) : "");
    return code != 0 ? code : 2;
}

// Runs the command and returns its exit code.
template <class Command>
int runAtBoundary(const Command& command) {
    reportFileSizeLimitAsAnError();
    int code;
    try {
        code = command();
    } catch (const UserError& e) {
        std::fprintf(stderr, "quaternia: error: %s\n", e.what());
        code = 2;
    } catch (const std::bad_alloc&) {
        // The estimates before the work (--memory-budget) missed, or the budget was set above
        // what the process may take: the outputs' temporaries are gone with the unwinding.
        std::fprintf(stderr,
                     "quaternia: error: out of memory: the request needs more memory than this "
                     "process could take (see --memory-budget)\n");
        code = 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "quaternia: internal error: %s\n", e.what());
        code = 1;
    }
    return checkStandardOutput(code);
}

}  // namespace quaternia
