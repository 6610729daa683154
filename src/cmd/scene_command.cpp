#include "cmd/scene_command.h"

#include <cstdio>

#include "quaternia/scene/parameters.h"
#include "quaternia/scene/presets.h"
#include "quaternia/scene/scene_file.h"
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
           "\n" + presetHelp();
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

}  // namespace quaternia
