// What the commands that read a scene share: the options [SCENE.toml] --preset --set -o --width
// --height --threads --json, building the scene from them, and Ctrl-C handling.
#pragma once

#include <atomic>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

#include "cmd/progress_bar.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene.h"
#include "quaternia/util/memory_budget.h"
#include "quaternia/util/parallel.h"

namespace quaternia {

struct SceneCommandOptions {
    std::string scenePath;  // empty: the embedded default scene
    std::string preset;     // empty: none (presets.h)
    std::string output;
    std::optional<int64_t> width, height;  // unset: from the scene
    std::vector<std::string> overrides;    // section.key=value
    int threads = 0;
    bool json = false;
    std::string memoryBudget = "auto";  // --memory-budget (memory_budget.h)
};

// Adds what every command that reads a scene takes: [SCENE.toml], --preset and --set.
void addSceneInputOptions(CLI::App& command, SceneCommandOptions& options);

// Adds the scene input and the shared options to `command`; `outputHelp` describes -o. --width
// and --height only where the command makes an image.
void addSceneOptions(CLI::App& command, SceneCommandOptions& options, const std::string& outputHelp,
                     bool imageSize = true);

// The scene file (or the default scene), then the preset, then each --set, then --width and
// --height. Throws UserError for a bad file, preset, key or value, and for --threads outside
// [0, 1024].
Scene sceneFromOptions(const SceneCommandOptions& options);

// The budget --memory-budget asks for (auto: what the process can still take).
MemoryBudget memoryBudgetFromOptions(const SceneCommandOptions& options);

// Throws UserError naming render.width when `bytes` (an estimate for the scene's image size) do
// not fit in the budget of --memory-budget; `what` says what is made ("a render", "a film's
// frames in flight").
void requireImageMemory(const Scene& scene, uint64_t bytes, const SceneCommandOptions& options,
                        const std::string& what);

// Reads the scene's environment map (environment.map) within the budget of --memory-budget,
// before the work: a missing, unreadable or non-HDR file, one that is not 2:1 or too large is a
// UserError naming environment.map. The renders then take it from environmentOf's cache.
// With it, the fractal's tables (requireFractalMemory: the bicomplex functions' escape maps).
void requireSceneTables(const Scene& scene, const SceneCommandOptions& options);

// Where a command's summary goes: standard output, unless one of `outputs` is standard output
// itself (-o /dev/stdout, or a path to the file or pipe that fd 1 is), where the summary would be
// written into the image; then standard error.
std::FILE* summaryStream(std::initializer_list<std::string_view> outputs);

// Sets the table key `key` from the short flag `flag` (e.g. --period for cycles.period), naming
// the flag in an error: "--period: cycles.period = 11 is out of range [1, 10]".
void setFromFlag(Scene& scene, const std::string& flag, const std::string& key,
                 const ParameterValue& value);

// The end of a scene-reading command's --help: every scene key, then every preset, then the
// costs (costHelp).
std::string sceneHelpFooter();

// What the memory budget bounds, and the accepted inputs that would run for hours.
std::string costHelp();

// While alive, Ctrl-C (SIGINT) and SIGTERM (a job's end, as mpirun sends it when a rank fails)
// set flag() instead of ending the process (the work stops early, nothing is written and no
// temporary is left); the previous handlers return on destruction.
class InterruptScope {
  public:
    InterruptScope();
    ~InterruptScope();
    InterruptScope(const InterruptScope&) = delete;
    InterruptScope& operator=(const InterruptScope&) = delete;

    const std::atomic<bool>* flag() const;

  private:
    void (*previous_)(int);
    void (*previousTerminate_)(int);
};

// Runs work(WorkOptions) with the command's --threads, Ctrl-C caught (InterruptScope) as the
// cancel flag and a progress bar labelled `label` on a terminal (none with --json), and returns
// what it returns.
template <typename Work>
auto runInterruptibly(const char* label, const SceneCommandOptions& options, Work work) {
    InterruptScope interrupt;
    ProgressBar bar(label, !options.json && ProgressBar::stderrIsTerminal());
    WorkOptions workOptions;
    workOptions.threads = options.threads;
    workOptions.cancel = interrupt.flag();
    workOptions.progress = [&](double fraction) { bar.update(fraction); };
    auto result = work(workOptions);
    bar.finish();
    return result;
}

// Says on stderr that the work was interrupted and nothing written; returns exit code 130.
int reportInterrupted();

}  // namespace quaternia
