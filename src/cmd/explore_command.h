// `quaternia explore [SCENE.toml] [--preset NAME] [--port 8080] [--bind 127.0.0.1]`: serves the
// live explorer (explore_server.h) until Ctrl-C, after printing its URL.
//
// The server runs in its own executable, quaternia-explore, beside quaternia, into which
// `quaternia explore` turns (execv, the same process): the HTTP library pulls in OpenSSL and
// Brotli, whose loading cost every other command milliseconds before it started. Both parse the
// options declared here.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "server/explore_server.h"

namespace quaternia {

struct ExploreCommandOptions {
    std::string scenePath;  // empty: the default scene
    std::string preset;     // empty: none; applied after the scene file (presets.h)
    std::string bind = "127.0.0.1";
    int port = 8080;
    int threads = 0;
    ExploreConnectionLimits connections;  // --connections, --connections-per-address, ...
    std::string memoryBudget = "auto";    // --memory-budget (memory_budget.h)
};

// The options of the command, declared on `command` (quaternia's explore subcommand, or
// quaternia-explore's own application).
void addExploreOptions(CLI::App& command, ExploreCommandOptions& options);
void addExploreCommand(CLI::App& app, ExploreCommandOptions& options);
// quaternia's side: becomes quaternia-explore with the parsed options; returns only if that
// fails, by throwing.
int runExploreCommand(const ExploreCommandOptions& options);
// quaternia-explore's side: serves until Ctrl-C or SIGTERM.
int serveExplorer(const ExploreCommandOptions& options);

}  // namespace quaternia
