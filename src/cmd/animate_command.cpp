#include "cmd/animate_command.h"

#include <chrono>
#include <cstdio>
#include <memory>
#include <vector>

#include "quaternia/film/video_encoder.h"
#include "quaternia/scene/animation.h"
#include "quaternia/scene/json.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_file.h"
#include "quaternia/util/atomic_file.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

// The whole range on this process (renderFilmFrames), with Ctrl-C, the progress bar and the
// summary; the video is finished only when every frame is in it.
int renderFilm(const AnimateCommandOptions& options, const Scene& film, int64_t count,
               FrameRange range, std::unique_ptr<VideoEncoder> encoder) {
    const auto start = std::chrono::steady_clock::now();
    const FrameDirectory directory{options.output, count};
    const std::vector<int64_t> toRender = framesToRender(directory, range, options.overwrite);
    InterruptScope interrupt;
    ProgressBar bar("animating", !options.json && ProgressBar::stderrIsTerminal());
    WorkOptions work;
    work.threads = options.threads;
    work.cancel = interrupt.flag();
    work.progress = [&bar](double fraction) { bar.update(fraction); };
    FilmRun run = renderFilmFrames(film, directory, range, toRender, encoder.get(), work);
    bar.finish();
    FilmStats& stats = run.stats;
    if (run.interrupted) {
        std::fprintf(stderr,
                     "quaternia: interrupted with %lld frame%s written; run the same command "
                     "again to finish the film\n",
                     (long long)stats.rendered, stats.rendered == 1 ? "" : "s");
        return 130;
    }
    if (encoder) encoder->finish();
    stats.threads = resolveThreadCount(options.threads);
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    printFilmSummary(options, film, count, range, stats);
    return 0;
}

}  // namespace

void requireFilmMemory(const Scene& film, FrameRange range, bool video, int framesInFlight,
                       const AnimateCommandOptions& options) {
    const FilmMemory memory = filmMemory(film, range, video, framesInFlight);
    requireImageMemory(memory.largestFrame, memory.bytes, options, "the film (frames in flight)");
    requireSceneTables(film, options);
}

void printFilmSummary(const AnimateCommandOptions& options, const Scene& film, int64_t count,
                      FrameRange range, const FilmStats& stats, const Json& extra) {
    std::FILE* stream = summaryStream({options.video});
    double framesPerSecond = stats.seconds > 0 ? double(stats.rendered) / stats.seconds : 0;
    if (!options.json) {
        std::fprintf(
            stream,
            "quaternia: %lld frame%s rendered, %lld skipped (frames %lld-%lld of %lld, %dx%d) "
            "into %s in %.2f s, %.3g frames/s%s%s\n",
            (long long)stats.rendered, stats.rendered == 1 ? "" : "s", (long long)stats.skipped,
            (long long)range.first, (long long)range.second, (long long)count, film.render.width,
            film.render.height, options.output.c_str(), stats.seconds, framesPerSecond,
            options.video.empty() ? "" : ", video ", options.video.c_str());
        return;
    }
    Json json;
    json["command"] = "animate";
    json["output"] = options.output;
    json["video"] = options.video.empty() ? Json() : Json(options.video);
    json["film_frames"] = count;
    json["first_frame"] = range.first;
    json["last_frame"] = range.second;
    json["frames_rendered"] = stats.rendered;
    json["frames_skipped"] = stats.skipped;
    json["seconds"] = stats.seconds;
    json["frames_per_second"] = framesPerSecond;
    json["render_seconds"] = stats.renderSeconds;
    json["fps"] = film.animation.fps;
    json["width"] = film.render.width;
    json["height"] = film.render.height;
    json["samples"] = film.render.samples;
    json["threads"] = stats.threads;
    json.update(extra);
    std::fprintf(stream, "%s\n", jsonText(json).c_str());
}

void addAnimateCommand(CLI::App& app, AnimateCommandOptions& options) {
    CLI::App* animate = app.add_subcommand(
        "animate", "Render a scene's [animation] to numbered PNG frames, and optionally a video");
    addSceneOptions(*animate, options,
                    "Directory of the frames: frame_000001.png, ... (made if missing)");
    animate->add_option("--frames", options.frames,
                        "Frames to render, FIRST-LAST or N (from 1, inclusive); default all. "
                        "Frames already in the directory are skipped");
    animate->add_option("--video", options.video,
                        "Also encode the range's frames with ffmpeg: OUT.mp4 (H.264), OUT.webm "
                        "(VP9) or OUT.gif");
    animate->add_flag("--overwrite", options.overwrite,
                      "Render frames whose files exist too, replacing them");
    animate->add_option("--print-frame", options.printFrame,
                        "Print frame N's scene as TOML (render it with `quaternia render`) and "
                        "render nothing");
    animate->footer(sceneHelpFooter());
}

int runAnimateCommand(const AnimateCommandOptions& options) {
    const Scene film = sceneFromOptions(options);
    validateAnimation(film);
    const int64_t count = filmFrameCount(film);
    if (options.printFrame) {
        int64_t frame = *options.printFrame;
        if (frame < 1 || frame > count)
            throw UserError("--print-frame", "--print-frame " + std::to_string(frame) +
                                                 ": the film has frames 1-" +
                                                 std::to_string(count));
        std::printf("%s", sceneToToml(sceneAtFrame(film, frame)).c_str());
        return 0;
    }
    const auto range = parseFrameRange(options.frames, count);
    std::optional<VideoFormat> format;
    std::string ffmpeg;
    if (!options.video.empty()) {
        format = videoFormatOf(options.video);
        ffmpeg = findFfmpeg();
    }
    if (options.output.empty()) throw UserError("-o", "-o: the frame directory is empty");
    checkFrames(film, range, format.has_value());
    // One frame rendering, one queued for the writer, one being encoded.
    requireFilmMemory(film, range, format.has_value(), 3, options);
    prepareDirectory(FrameDirectory{options.output, count}, range);
    std::unique_ptr<VideoEncoder> encoder;
    if (format) {
        const Scene first = sceneAtFrame(film, range.first);
        encoder = std::make_unique<VideoEncoder>(ffmpeg, AtomicFile(options.video), *format,
                                                 first.render.width, first.render.height,
                                                 film.animation.fps);
    }
    return renderFilm(options, film, count, range, std::move(encoder));
}

}  // namespace quaternia
