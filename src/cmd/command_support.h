// What the subcommands share: the scene from a file (or the default) with --set overrides,
// the --threads check, JSON strings for --json summaries, and Ctrl-C as a cancel flag.
#pragma once

#include <atomic>
#include <string>
#include <vector>

#include "quaternia/scene.h"

namespace quaternia {

// The scene file at `scenePath` (the embedded default scene when empty) with each
// "section.key=value" of `overrides` applied in order. Throws UserError.
Scene loadSceneWithOverrides(const std::string& scenePath,
                             const std::vector<std::string>& overrides);

// Throws UserError("--threads", ...) outside [0, 1024].
void checkThreadCount(int threads);

// `s` quoted and escaped for JSON.
std::string jsonString(const std::string& s);

// While alive, Ctrl-C sets flag() instead of killing the process, so that the work stops and
// nothing is written; the previous handler comes back on destruction.
class InterruptFlag {
  public:
    InterruptFlag();
    ~InterruptFlag();
    InterruptFlag(const InterruptFlag&) = delete;
    InterruptFlag& operator=(const InterruptFlag&) = delete;
    const std::atomic<bool>* flag() const;
};

}  // namespace quaternia
