// A film's frames rendered into their directory (frame_plan.h), and optionally into a video.
// Frame n is byte for byte the PNG render of the scene sceneAtFrame(film, n), however the frames
// are spread: one process for the whole range (renderFilmFrames) or one frame at a time on many
// (renderFrameFile, then encodeFrameFiles).
#pragma once

#include <cstdint>
#include <vector>

#include "quaternia/film/frame_plan.h"
#include "quaternia/film/video_encoder.h"
#include "quaternia/render/render.h"
#include "quaternia/scene/scene.h"
#include "quaternia/util/parallel.h"

namespace quaternia {

// What a film's run did, for the summary.
struct FilmStats {
    int64_t rendered = 0, skipped = 0;
    double seconds = 0, renderSeconds = 0;
    int threads = 0;
};

struct FilmRun {
    FilmStats stats;  // rendered, skipped and renderSeconds (the caller times the whole run)
    bool interrupted = false;  // the cancel flag stopped it; the frames written are whole
};

// Renders the frames `toRender` of the range, in order (the others are skipped: their files
// exist), on one process: the render's threads stay from frame to frame, and a writer thread
// writes frame n (and hands it to the encoder) while frame n + 1 renders. The encoder, where
// there is one, gets every frame of the range in order and is left unfinished. `options`'
// progress is the fraction of toRender done. Throws what rendering or writing throws.
FilmRun renderFilmFrames(const Scene& film, const FrameDirectory& directory, FrameRange range,
                         const std::vector<int64_t>& toRender, VideoEncoder* encoder,
                         const WorkOptions& options);

// Renders frame `frame` alone and writes its file (each rank of quaternia-mpi, for the frames it
// is handed). False, and nothing written, when the options' cancel flag stopped the render.
bool renderFrameFile(const Scene& film, const FrameDirectory& directory, int64_t frame,
                     const RenderOptions& options);

// Hands the range's frame files to the encoder in order (after many processes wrote them).
void encodeFrameFiles(VideoEncoder& encoder, const FrameDirectory& directory, FrameRange range);

}  // namespace quaternia
