#include "explore_command.h"

#include <csignal>
#include <cstdio>
#include <thread>

#include "explore_server.h"
#include "quaternia/parameters.h"
#include "quaternia/scene_file.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

std::atomic<bool> gStopRequested{false};

extern "C" void onStopSignal(int) {
    gStopRequested = true;
}

}  // namespace

void addExploreCommand(CLI::App& app, ExploreCommandOptions& options) {
    CLI::App* explore = app.add_subcommand(
        "explore", "Serve the live explorer: a web page to orbit, tune and export the set");
    explore->add_option("scene", options.scenePath,
                        "Scene file (TOML) the page starts from; without one the default scene");
    explore->add_option("--port", options.port, "TCP port (0: any free port)")
        ->capture_default_str()
        ->check(CLI::Range(0, 65535));
    explore
        ->add_option("--bind", options.bind,
                     "Address to listen on; the default serves this machine only")
        ->capture_default_str();
    explore->add_option("--threads", options.threads, "Worker threads per render (0 = every core)")
        ->capture_default_str()
        ->check(CLI::Range(0, 1024));
}

int runExploreCommand(const ExploreCommandOptions& options) {
    ExploreServerOptions serverOptions;
    serverOptions.bind = options.bind;
    serverOptions.port = options.port;
    serverOptions.renderThreads = options.threads;
    serverOptions.startScene =
        options.scenePath.empty() ? defaultScene() : loadScene(options.scenePath);
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
