#include "quaternia/film/film_render.h"

#include <optional>
#include <utility>

#include "quaternia/film/frame_writer.h"
#include "quaternia/image/png_io.h"
#include "quaternia/render/render_png.h"
#include "quaternia/scene/animation.h"
#include "quaternia/util/atomic_file.h"

namespace quaternia {

FilmRun renderFilmFrames(const Scene& film, const FrameDirectory& directory, FrameRange range,
                         const std::vector<int64_t>& toRender, VideoEncoder* encoder,
                         const WorkOptions& options) {
    FilmRun run;
    // One frame queued while the next renders: the queue bounds the frames in memory.
    FrameWriter writer(frameFileHandler(directory, encoder), 1);
    RenderWorkspace workspace;  // the threads' lane renderers, kept from frame to frame
    std::size_t next = 0;       // the next of toRender
    for (int64_t frame = range.first; frame <= range.second && !run.interrupted; ++frame) {
        if (next == toRender.size() || toRender[next] != frame) {
            ++run.stats.skipped;
            if (encoder != nullptr) writer.push({frame, std::nullopt, 0});
            continue;
        }
        const Scene scene = sceneAtFrame(film, frame);
        RenderOptions renderOptions;
        renderOptions.threads = options.threads;
        renderOptions.cancel = options.cancel;
        renderOptions.workspace = &workspace;
        if (options.progress) {
            const double done = double(next), total = double(toRender.size());
            renderOptions.progress = [&options, done, total](double fraction) {
                options.progress((done + fraction) / total);
            };
        }
        RenderResult result = renderForPng(scene, renderOptions);
        // A frame that completed as the flag was set is still written: it is whole.
        run.interrupted =
            !result.completed || (options.cancel != nullptr && options.cancel->load());
        if (!result.completed) break;
        run.stats.renderSeconds += result.stats.seconds;
        ++run.stats.rendered;
        ++next;
        writer.push({frame, std::move(result), scene.render.bitDepth});
    }
    writer.finish();
    return run;
}

bool renderFrameFile(const Scene& film, const FrameDirectory& directory, int64_t frame,
                     const RenderOptions& options) {
    const Scene scene = sceneAtFrame(film, frame);
    RenderResult result = renderForPng(scene, options);
    if (!result.completed) return false;
    writeFileAtomically(directory.framePath(frame), encodeRenderPng(result, scene.render.bitDepth));
    return true;
}

void encodeFrameFiles(VideoEncoder& encoder, const FrameDirectory& directory, FrameRange range) {
    for (int64_t frame = range.first; frame <= range.second; ++frame)
        encoder.addFrame(readPng(directory.framePath(frame)));
}

}  // namespace quaternia
