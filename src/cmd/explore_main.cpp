// quaternia-explore: the server of `quaternia explore` (explore_command.h), which turns into
// this program with its parsed options. The boundary is quaternia's (cli_boundary.h): user
// errors become one line on standard error and exit code 2.
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <exception>
#include <thread>

#include <CLI/CLI.hpp>

#include "cmd/cli_boundary.h"
#include "cmd/explore_command.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/presets.h"
#include "quaternia/scene/scene_file.h"
#include "quaternia/util/error.h"
#include "quaternia/util/memory_budget.h"
#include "quaternia/util/parallel.h"
#include "server/explore_server.h"

namespace quaternia {
namespace {

std::atomic<bool> gStopRequested{false};

extern "C" void onStopSignal(int) {
    gStopRequested = true;
}

}  // namespace

int serveExplorer(const ExploreCommandOptions& options) {
    ExploreServerOptions serverOptions;
    serverOptions.bind = options.bind;
    serverOptions.port = options.port;
    serverOptions.renderThreads = options.threads;
    serverOptions.connections = options.connections;
    // Resolved here, in the server's own process: `auto` is what this process can still take.
    serverOptions.memory = parseMemoryBudget(options.memoryBudget, "--memory-budget",
                                             resolveThreadCount(options.threads));
    serverOptions.startScene =
        options.scenePath.empty() ? defaultScene() : loadScene(options.scenePath);
    if (!options.preset.empty()) applyPreset(serverOptions.startScene, options.preset);
    validateScene(serverOptions.startScene);

    ExploreServer server(serverOptions);
    int port = server.bind();
    std::string host =
        options.bind.find(':') != std::string::npos ? "[" + options.bind + "]" : options.bind;
    std::printf("quaternia explore: serving http://%s:%d/ (Ctrl-C stops)\n", host.c_str(), port);
    std::fflush(stdout);

    // Ctrl-C and SIGTERM stop the server from a watcher thread: httplib's stop() is not
    // async-signal-safe, so the handler only sets a flag.
    gStopRequested = false;
    auto previousInt = std::signal(SIGINT, onStopSignal);
    auto previousTerm = std::signal(SIGTERM, onStopSignal);
    std::atomic<bool> finished{false};
    std::thread watcher([&] {
        while (!gStopRequested && !finished)
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        server.stop();
    });
    server.run();
    finished = true;
    watcher.join();
    std::signal(SIGINT, previousInt);
    std::signal(SIGTERM, previousTerm);
    return 0;
}

}  // namespace quaternia

int main(int argc, char** argv) {
    using namespace quaternia;
    CLI::App app("Quaternia's live explorer, started by `quaternia explore`.", "quaternia explore");
    ExploreCommandOptions options;
    addExploreOptions(app, options);
    if (auto code = parseCommandLine(app, argc, argv, "quaternia explore")) return *code;
    return runAtBoundary([&] { return serveExplorer(options); });
}
