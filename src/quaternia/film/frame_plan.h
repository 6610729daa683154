// Which frames of a film a run renders, and where their files go. A film's frames are numbered
// PNG files in one directory, `DIR/frame_000001.png` on; each is written whole (renamed into
// place), so a file there is a complete frame. That makes a killed run resumable (the frames
// with a file are skipped) and lets disjoint ranges of one film be rendered by many processes
// into one directory (`quaternia animate --frames`, quaternia-mpi's ranks).
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "quaternia/scene/scene.h"

namespace quaternia {

// The frames first..last of a film, 1-based and inclusive.
using FrameRange = std::pair<int64_t, int64_t>;

// The frames of `text` ("FIRST-LAST" or "N", as --frames takes them) for a film of `count`
// frames; the whole film for "". Throws UserError ("--frames") for a malformed range or one
// outside [1, count].
FrameRange parseFrameRange(const std::string& text, int64_t count);

// "frame_000042.png": six digits, more where the film has more frames.
std::string frameFileName(int64_t frame, int64_t count);

// The directory of a film's frames. The film's frame count sets the digits of every name.
struct FrameDirectory {
    std::string path;
    int64_t filmFrames = 0;
    std::string framePath(int64_t frame) const;
};

// Every frame's scene of the range is checked before any work: each is valid, its formula
// parses, and for a video all have the first one's size. Throws UserError.
void checkFrames(const Scene& film, FrameRange range, bool video);

// Creates the directory, removes the temporaries a killed run left for the frames of the range
// (only those: another run may be writing other frames into the same directory), and checks
// that a frame can be written there. Throws UserError ("-o").
void prepareDirectory(const FrameDirectory& directory, FrameRange range);

// The frames of the range that are to be rendered, in order: those without a file, or all of
// them with `overwrite`.
std::vector<int64_t> framesToRender(const FrameDirectory& directory, FrameRange range,
                                    bool overwrite);

// The memory the frames of a range take at most: the largest frame's PNG render,
// `framesInFlight` times over, and for a video that frame decoded and as ffmpeg's RGBA.
struct FilmMemory {
    Scene largestFrame;  // the frame whose render takes the most
    uint64_t bytes = 0;
};
FilmMemory filmMemory(const Scene& film, FrameRange range, bool video, int framesInFlight);

}  // namespace quaternia
