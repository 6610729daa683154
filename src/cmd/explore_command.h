// `quaternia explore [SCENE.toml] [--port 8080] [--bind 127.0.0.1]`: serves the live explorer
// (explore_server.h) until Ctrl-C, after printing its URL.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace quaternia {

struct ExploreCommandOptions {
    std::string scenePath;  // empty: the default scene
    std::string bind = "127.0.0.1";
    int port = 8080;
    int threads = 0;
};

void addExploreCommand(CLI::App& app, ExploreCommandOptions& options);
int runExploreCommand(const ExploreCommandOptions& options);

}  // namespace quaternia
