// `quaternia animate`: a scene's film ([animation], animation.h) rendered to numbered PNG
// frames in a directory, `DIR/frame_000001.png` on, and optionally encoded to a video.
//
// Frames are written whole (renamed into place), and a frame whose file exists is skipped, so
// that a killed run started again finishes the film, and disjoint --frames ranges can render a
// film on many machines into one directory. Frame n is byte for byte `quaternia render` of
// the scene `--print-frame n` prints.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "cmd/scene_command.h"
#include "quaternia/scene/json.h"

namespace quaternia {

struct AnimateCommandOptions : SceneCommandOptions {
    AnimateCommandOptions() { output = "frames"; }
    std::string frames;  // "A-B" or "N", 1-based and inclusive; empty: the whole film
    std::string video;   // empty: frames only
    bool overwrite = false;
    std::optional<int64_t> printFrame;
};

void addAnimateCommand(CLI::App& app, AnimateCommandOptions& options);

// Throws UserError naming render.width when the largest frame of `range`, `framesInFlight`
// times over with its PNG (and for a video that frame decoded and as ffmpeg's RGBA), does not
// fit in the budget of --memory-budget.
void requireFilmMemory(const Scene& film, std::pair<int64_t, int64_t> range, bool video,
                       int framesInFlight, const AnimateCommandOptions& options);
// Renders and writes the frames (and the video); returns the process exit code. Throws
// UserError on bad input.
int runAnimateCommand(const AnimateCommandOptions& options);

// The frames of --frames `text` for a film of `count` frames: [first, last]. Throws UserError
// ("--frames") for a malformed range or one outside [1, count].
std::pair<int64_t, int64_t> parseFrameRange(const std::string& text, int64_t count);

// Every frame's scene of [first, last] is checked before any work: each is valid, its formula
// parses, and for a video all have the first one's size. Throws UserError.
void checkFrames(const Scene& film, int64_t first, int64_t last, bool video);

// Creates the directory, removes the temporaries a killed run left for the frames of [first,
// last] (only those: another run may be writing other frames into the same directory), and
// checks that a frame can be written there. Throws UserError.
void prepareDirectory(const std::string& directory, int64_t first, int64_t last, int64_t count);

// The frames of the range that are to be rendered: those without a file, or all with
// --overwrite. A file there is complete, since frames are renamed into place.
std::vector<int64_t> framesToRender(const AnimateCommandOptions& options, int64_t count,
                                    std::pair<int64_t, int64_t> range);

// What a film's run did, for the summary.
struct FilmStats {
    int64_t rendered = 0, skipped = 0;
    double seconds = 0, renderSeconds = 0;
    int threads = 0;
};

// The summary of a film's run on stdout: one line, or with --json an object, `extra`'s fields
// added.
void printFilmSummary(const AnimateCommandOptions& options, const Scene& film, int64_t count,
                      std::pair<int64_t, int64_t> range, const FilmStats& stats,
                      const Json& extra = Json::object());

// "frame_000042.png": six digits, more where the film has more frames.
std::string frameFileName(int64_t frame, int64_t count);

}  // namespace quaternia
