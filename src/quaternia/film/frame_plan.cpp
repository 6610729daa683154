#include "quaternia/film/frame_plan.h"

#include <algorithm>
#include <filesystem>
#include <optional>
#include <set>

#include "quaternia/fractal/fractal.h"
#include "quaternia/image/image.h"
#include "quaternia/render/render_png.h"
#include "quaternia/scene/animation.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/util/atomic_file.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

namespace fs = std::filesystem;

std::optional<int64_t> parseFrameNumber(const std::string& text) {
    if (text.empty() || text.size() > 18 ||
        text.find_first_not_of("0123456789") != std::string::npos)
        return std::nullopt;
    return std::stoll(text);
}

// The frame number of a temporary that a killed run left for a frame ("frame_N.png.tmp-XXX").
std::optional<int64_t> staleFrameTemporary(const std::string& name) {
    const std::string prefix = "frame_", middle = ".png.tmp-";
    std::size_t at = name.find(middle);
    if (!name.starts_with(prefix) || at == std::string::npos) return std::nullopt;
    return parseFrameNumber(name.substr(prefix.size(), at - prefix.size()));
}

}  // namespace

FrameRange parseFrameRange(const std::string& text, int64_t count) {
    if (text.empty()) return {1, count};
    std::size_t dash = text.find('-');
    auto first = parseFrameNumber(text.substr(0, dash));
    auto last = dash == std::string::npos ? first : parseFrameNumber(text.substr(dash + 1));
    if (!first || !last)
        throw UserError("--frames",
                        "--frames '" + text + "': expected FIRST-LAST or N (frame numbers from 1)");
    if (*first > *last)
        throw UserError("--frames", "--frames " + text + ": the last frame comes before the first");
    if (*first < 1 || *last > count)
        throw UserError("--frames", "--frames " + text + " is outside the film's frames 1-" +
                                        std::to_string(count));
    return {*first, *last};
}

std::string frameFileName(int64_t frame, int64_t count) {
    int digits = std::max<int>(6, int(std::to_string(count).size()));
    std::string number = std::to_string(frame);
    return "frame_" + std::string(std::size_t(std::max<int>(0, digits - int(number.size()))), '0') +
           number + ".png";
}

std::string FrameDirectory::framePath(int64_t frame) const {
    return (fs::path(path) / frameFileName(frame, filmFrames)).string();
}

void checkFrames(const Scene& film, FrameRange range, bool video) {
    std::set<std::string> formulas;  // formulas checked already
    int width = 0, height = 0;
    for (int64_t frame = range.first; frame <= range.second; ++frame) {
        Scene scene = sceneAtFrame(film, frame);
        validateScene(scene);
        if (formulas.insert(scene.fractal.formula).second) fractalFromScene(scene);
        if (frame == range.first) {
            width = scene.render.width;
            height = scene.render.height;
        } else if (video && (scene.render.width != width || scene.render.height != height)) {
            throw UserError("--video", "--video: frame " + std::to_string(frame) + " is " +
                                           std::to_string(scene.render.width) + "x" +
                                           std::to_string(scene.render.height) + ", frame " +
                                           std::to_string(range.first) + " " +
                                           std::to_string(width) + "x" + std::to_string(height) +
                                           ": a video's frames have one size");
        }
    }
}

void prepareDirectory(const FrameDirectory& directory, FrameRange range) {
    std::error_code error;
    fs::create_directories(directory.path, error);
    if (error || !fs::is_directory(directory.path))
        throw UserError("-o", "cannot create the frame directory '" + directory.path +
                                  "': " + (error ? error.message() : "not a directory"));
    for (const fs::directory_entry& entry : fs::directory_iterator(directory.path, error)) {
        auto frame = staleFrameTemporary(entry.path().filename().string());
        if (frame && *frame >= range.first && *frame <= range.second)
            fs::remove(entry.path(), error);
    }
    AtomicFile probe(directory.framePath(range.first));
}

std::vector<int64_t> framesToRender(const FrameDirectory& directory, FrameRange range,
                                    bool overwrite) {
    std::vector<int64_t> frames;
    for (int64_t frame = range.first; frame <= range.second; ++frame)
        if (overwrite || !fs::exists(directory.framePath(frame))) frames.push_back(frame);
    return frames;
}

FilmMemory filmMemory(const Scene& film, FrameRange range, bool video, int framesInFlight) {
    uint64_t largest = 0;
    Scene largestScene = film;
    for (int64_t frame = range.first; frame <= range.second; ++frame) {
        Scene scene = sceneAtFrame(film, frame);
        const uint64_t bytes = renderPngMemoryBytes(scene, false);
        if (bytes > largest) {
            largest = bytes;
            largestScene = std::move(scene);
        }
    }
    const uint64_t pixels =
        uint64_t(largestScene.render.width) * uint64_t(largestScene.render.height);
    const uint64_t bytes =
        uint64_t(framesInFlight) * largest + (video ? pixels * (sizeof(Rgba) + 4) : 0);
    return FilmMemory{std::move(largestScene), bytes};
}

}  // namespace quaternia
