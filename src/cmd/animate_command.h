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

#include <CLI/CLI.hpp>

#include "cmd/scene_command.h"

namespace quaternia {

struct AnimateCommandOptions : SceneCommandOptions {
    AnimateCommandOptions() { output = "frames"; }
    std::string frames;  // "A-B" or "N", 1-based and inclusive; empty: the whole film
    std::string video;   // empty: frames only
    bool overwrite = false;
    std::optional<int64_t> printFrame;
};

void addAnimateCommand(CLI::App& app, AnimateCommandOptions& options);
// Renders and writes the frames (and the video); returns the process exit code. Throws
// UserError on bad input.
int runAnimateCommand(const AnimateCommandOptions& options);

// The frames of --frames `text` for a film of `count` frames: [first, last]. Throws UserError
// ("--frames") for a malformed range or one outside [1, count].
std::pair<int64_t, int64_t> parseFrameRange(const std::string& text, int64_t count);

// "frame_000042.png": six digits, more where the film has more frames.
std::string frameFileName(int64_t frame, int64_t count);

}  // namespace quaternia
