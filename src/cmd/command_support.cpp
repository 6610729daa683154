#include "command_support.h"

#include <csignal>
#include <cstdio>

#include "quaternia/parameters.h"
#include "quaternia/scene_file.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

std::atomic<bool> gInterrupted{false};
void (*gPreviousHandler)(int) = SIG_DFL;

extern "C" void onInterrupt(int) {
    gInterrupted = true;
}

}  // namespace

Scene loadSceneWithOverrides(const std::string& scenePath,
                             const std::vector<std::string>& overrides) {
    Scene scene = scenePath.empty() ? defaultScene() : loadScene(scenePath);
    for (const std::string& assignment : overrides)
        applyOverride(scene, assignment);
    return scene;
}

void checkThreadCount(int threads) {
    if (threads < 0 || threads > 1024)
        throw UserError("--threads",
                        "--threads must be in [0, 1024], got " + std::to_string(threads));
}

std::string jsonString(const std::string& s) {
    std::string out = "\"";
    for (char ch : s) {
        if (ch == '"' || ch == '\\') {
            out += '\\';
            out += ch;
        } else if (static_cast<unsigned char>(ch) < 0x20) {
            char buffer[8];
            std::snprintf(buffer, sizeof buffer, "\\u%04x", ch);
            out += buffer;
        } else {
            out += ch;
        }
    }
    return out + "\"";
}

InterruptFlag::InterruptFlag() {
    gInterrupted = false;
    gPreviousHandler = std::signal(SIGINT, onInterrupt);
}

InterruptFlag::~InterruptFlag() {
    std::signal(SIGINT, gPreviousHandler);
}

const std::atomic<bool>* InterruptFlag::flag() const {
    return &gInterrupted;
}

}  // namespace quaternia
