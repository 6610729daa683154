#include "cmd/explore_command.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "quaternia/scene/presets.h"
#include "quaternia/util/number_format.h"

namespace quaternia {

void addExploreOptions(CLI::App& command, ExploreCommandOptions& options) {
    command.add_option("scene", options.scenePath,
                       "Scene file (TOML) the page starts from; without one the default scene");
    command.add_option("--preset", options.preset,
                       "Start from a preset, applied after the scene file: " + presetNames() +
                           " (described below)");
    command.footer(presetHelp());
    command.add_option("--port", options.port, "TCP port (0: any free port)")
        ->capture_default_str()
        ->check(CLI::Range(0, 65535));
    command
        .add_option("--bind", options.bind,
                    "Address to listen on; the default serves this machine only")
        ->capture_default_str();
    command.add_option("--threads", options.threads, "Worker threads per render (0 = every core)")
        ->capture_default_str()
        ->check(CLI::Range(0, 1024));
    ExploreConnectionLimits& limits = options.connections;
    command
        .add_option("--connections", limits.total,
                    "Connections served at once in all; more are refused (HTTP 503)")
        ->capture_default_str()
        ->check(CLI::Range(1, 4096));
    command
        .add_option("--connections-per-address", limits.perAddress,
                    "Connections served at once from one address; more are refused (HTTP 503)")
        ->capture_default_str()
        ->check(CLI::Range(1, 4096));
    command
        .add_option("--request-timeout", limits.requestSeconds,
                    "Seconds a client has to send a request, from its first byte; a slower one "
                    "is disconnected")
        ->capture_default_str()
        ->check(CLI::Range(0.1, 600.0));
    command
        .add_option("--memory-budget", options.memoryBudget,
                    "Memory the renders may take, shared by the two at once: a size (512M, 8G), "
                    "auto (what the server can still take) or unlimited; a request estimated to "
                    "need more than its share is refused")
        ->capture_default_str();
}

void addExploreCommand(CLI::App& app, ExploreCommandOptions& options) {
    CLI::App* explore = app.add_subcommand(
        "explore", "Serve the live explorer: a web page to orbit, tune and export the set");
    addExploreOptions(*explore, options);
}

int runExploreCommand(const ExploreCommandOptions& options) {
    std::error_code error;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
    if (error) throw std::runtime_error("cannot find this program's path: " + error.message());
    const std::string server = (self.parent_path() / "quaternia-explore").string();
    std::vector<std::string> arguments = {
        server,       "--port",    std::to_string(options.port),   "--bind",
        options.bind, "--threads", std::to_string(options.threads)};
    const ExploreConnectionLimits& limits = options.connections;
    // Digits that read back exactly, so that the server gets the very number.
    const std::string seconds = shortestNumber(limits.requestSeconds);
    arguments.insert(arguments.end(),
                     {"--connections", std::to_string(limits.total), "--connections-per-address",
                      std::to_string(limits.perAddress), "--request-timeout", seconds,
                      "--memory-budget", options.memoryBudget});
    if (!options.preset.empty()) arguments.insert(arguments.end(), {"--preset", options.preset});
    // After "--", a scene path that starts with '-' is still a path.
    if (!options.scenePath.empty()) arguments.insert(arguments.end(), {"--", options.scenePath});
    std::vector<char*> argv;
    for (std::string& argument : arguments)
        argv.push_back(argument.data());
    argv.push_back(nullptr);
    execv(server.c_str(), argv.data());
    throw std::runtime_error("cannot start " + server + ": " + std::strerror(errno));
}

}  // namespace quaternia
