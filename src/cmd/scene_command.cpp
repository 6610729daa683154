#include "cmd/scene_command.h"

#include <cstdio>

#include <sys/stat.h>

#include "quaternia/render/environment.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/presets.h"
#include "quaternia/scene/scene_file.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

std::atomic<bool> gInterrupted{false};

extern "C" void onInterrupt(int) {
    gInterrupted = true;
}

}  // namespace

void addSceneInputOptions(CLI::App& command, SceneCommandOptions& options) {
    command.add_option("scene", options.scenePath,
                       "Scene file (TOML); without one the embedded default scene is used");
    command.add_option("--preset", options.preset,
                       "Start from a preset, applied after the scene file and before --set: " +
                           presetNames() + " (described below)");
    command.add_option("--set", options.overrides,
                       "Override a scene key: section.key=value, value in TOML syntax "
                       "(a bare word is a string); repeatable");
}

void addSceneOptions(CLI::App& command, SceneCommandOptions& options, const std::string& outputHelp,
                     bool imageSize) {
    addSceneInputOptions(command, options);
    command.add_option("-o,--output", options.output, outputHelp)->capture_default_str();
    if (imageSize) {
        command.add_option("--width", options.width, "Image width in pixels (render.width)");
        command.add_option("--height", options.height, "Image height in pixels (render.height)");
    }
    command.add_option("--threads", options.threads, "Worker threads (0 = every core)")
        ->capture_default_str();
    command.add_flag("--json", options.json, "Print a machine-readable JSON summary");
    command
        .add_option("--memory-budget", options.memoryBudget,
                    "Memory the command may use: a size (512M, 8G, 1.5GiB), auto (the least of "
                    "the address-space and data limits, the cgroup's limit and the available "
                    "memory) or unlimited. A request estimated to need more is refused before "
                    "any work")
        ->capture_default_str();
}

MemoryBudget memoryBudgetFromOptions(const SceneCommandOptions& options) {
    return parseMemoryBudget(options.memoryBudget, "--memory-budget",
                             resolveThreadCount(options.threads));
}

void requireImageMemory(const Scene& scene, uint64_t bytes, const SceneCommandOptions& options,
                        const std::string& what) {
    requireMemory(bytes, memoryBudgetFromOptions(options), "render.width",
                  "render.width x render.height = " + std::to_string(scene.render.width) + " x " +
                      std::to_string(scene.render.height) + ": " + what,
                  "lower render.width and render.height, or set --memory-budget");
}

void requireSceneTables(const Scene& scene, const SceneCommandOptions& options) {
    const MemoryBudget budget = memoryBudgetFromOptions(options);
    environmentOf(scene, budget);
    requireFractalMemory(scene, budget);
}

Scene sceneFromOptions(const SceneCommandOptions& options) {
    if (options.threads < 0 || options.threads > 1024) {
        throw UserError("--threads",
                        "--threads must be in [0, 1024], got " + std::to_string(options.threads));
    }
    Scene scene = options.scenePath.empty() ? defaultScene() : loadScene(options.scenePath);
    if (!options.preset.empty()) applyPreset(scene, options.preset);
    for (const std::string& assignment : options.overrides)
        applyOverride(scene, assignment);
    if (options.width) setParameter(scene, "render.width", *options.width);
    if (options.height) setParameter(scene, "render.height", *options.height);
    return scene;
}

void setFromFlag(Scene& scene, const std::string& flag, const std::string& key,
                 const ParameterValue& value) {
    try {
        setParameter(scene, key, value);
    } catch (const UserError& e) {
        throw UserError(flag, flag + ": " + e.what());
    }
}

std::string sceneHelpFooter() {
    return "Scene keys (scene file sections, or --set section.key=value):\n" + parameterHelp() +
           "\n" + presetHelp() + "\n" + costHelp();
}

std::string costHelp() {
    return "Costs: memory is estimated before any work and a request that does not fit "
           "--memory-budget is refused; time is not bounded, and some accepted inputs run for "
           "hours or days on a desktop: a render's time grows with render.width x "
           "render.height x render.samples and with fractal.max_iterations (at the limits, "
           "16384 x 16384 with 1024 samples, about 3 hours on 2 cores at the default 12 "
           "iterations, and many times that at 100000); plane images with plane.max_iterations up "
           "to 1000000 and render.samples "
           "likewise; a mesh's time and memory grow with mesh.resolution squared or faster "
           "(2048: minutes and about 10 GiB); cycles with a high --period solves degree^period "
           "equations. Ctrl-C stops any command and writes nothing.\n";
}

InterruptScope::InterruptScope() {
    gInterrupted = false;
    previous_ = std::signal(SIGINT, onInterrupt);
    previousTerminate_ = std::signal(SIGTERM, onInterrupt);
}

InterruptScope::~InterruptScope() {
    std::signal(SIGINT, previous_);
    std::signal(SIGTERM, previousTerminate_);
}

const std::atomic<bool>* InterruptScope::flag() const {
    return &gInterrupted;
}

int reportInterrupted() {
    std::fprintf(stderr, "quaternia: interrupted, nothing written\n");
    return 130;
}

std::FILE* summaryStream(std::initializer_list<std::string_view> outputs) {
    struct stat out {};
    if (fstat(fileno(stdout), &out) != 0) return stdout;
    for (std::string_view output : outputs) {
        struct stat file {};
        if (!output.empty() && stat(std::string(output).c_str(), &file) == 0 &&
            file.st_dev == out.st_dev && file.st_ino == out.st_ino)
            return stderr;
    }
    return stdout;
}

}  // namespace quaternia
