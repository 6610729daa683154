// `quaternia animate`: a scene's film ([animation], animation.h) rendered to numbered PNG
// frames in a directory, `DIR/frame_000001.png` on, and optionally encoded to a video.
//
// Frames are written whole (renamed into place), and a frame whose file exists is skipped, so
// that a killed run started again finishes the film, and disjoint --frames ranges can render a
// film on many machines into one directory. Frame n is byte for byte `quaternia render` of
// the scene `--print-frame n` prints. The frames' plan, files and rendering are the library's
// (quaternia/film/); here are the options, the checks against them and what is printed.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "cmd/scene_command.h"
#include "quaternia/film/film_render.h"
#include "quaternia/film/frame_plan.h"
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
void requireFilmMemory(const Scene& film, FrameRange range, bool video, int framesInFlight,
                       const AnimateCommandOptions& options);
// Renders and writes the frames (and the video); returns the process exit code. Throws
// UserError on bad input.
int runAnimateCommand(const AnimateCommandOptions& options);

// The summary of a film's run on stdout: one line, or with --json an object, `extra`'s fields
// added.
void printFilmSummary(const AnimateCommandOptions& options, const Scene& film, int64_t count,
                      FrameRange range, const FilmStats& stats, const Json& extra = Json::object());
}  // namespace quaternia
