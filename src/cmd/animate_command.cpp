#include "cmd/animate_command.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <vector>

#include "cmd/frame_writer.h"
#include "cmd/video_encoder.h"
#include "quaternia/fractal/fractal.h"
#include "quaternia/image/png_io.h"
#include "quaternia/render/render_png.h"
#include "quaternia/scene/animation.h"
#include "quaternia/scene/json.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_file.h"
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

// One process for the whole range: the parallel-for's workers stay between frames, and the
// writer thread encodes and writes frame n (and hands it to ffmpeg) while frame n + 1 renders.
int renderFilm(const AnimateCommandOptions& options, const Scene& film, int64_t count,
               std::pair<int64_t, int64_t> range, std::unique_ptr<VideoEncoder> encoder) {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<int64_t> toRender = framesToRender(options, count, range);
    auto framePath = [&](int64_t frame) {
        return (fs::path(options.output) / frameFileName(frame, count)).string();
    };
    FilmStats stats;
    stats.threads = resolveThreadCount(options.threads);
    FrameWriter writer(
        [&](FrameWork& work) {
            const std::string path = framePath(work.frame);
            if (work.rendered) {
                std::vector<uint8_t> png = encodeRenderPng(*work.rendered, work.bitDepth);
                work.rendered.reset();
                writeFileAtomically(path, png);
                if (encoder) encoder->addFrame(decodePng(png));
            } else if (encoder) {
                encoder->addFrame(readPng(path));
            }
        },
        1);
    RenderWorkspace workspace;  // the threads' lane renderers, kept from frame to frame
    InterruptScope interrupt;
    ProgressBar bar("animating", !options.json && ProgressBar::stderrIsTerminal());
    bool interrupted = false;
    std::size_t next = 0;  // the next of toRender
    for (int64_t frame = range.first; frame <= range.second && !interrupted; ++frame) {
        if (next == toRender.size() || toRender[next] != frame) {
            ++stats.skipped;
            if (encoder) writer.push({frame, std::nullopt, 0});
            continue;
        }
        const Scene scene = sceneAtFrame(film, frame);
        RenderOptions renderOptions;
        renderOptions.threads = options.threads;
        renderOptions.cancel = interrupt.flag();
        renderOptions.workspace = &workspace;
        const double done = double(next), total = double(toRender.size());
        renderOptions.progress = [&bar, done, total](double fraction) {
            bar.update((done + fraction) / total);
        };
        RenderResult result = renderForPng(scene, renderOptions);
        interrupted = !result.completed || interrupt.flag()->load();
        if (!result.completed) break;
        stats.renderSeconds += result.stats.seconds;
        ++stats.rendered;
        ++next;
        writer.push({frame, std::move(result), scene.render.bitDepth});
    }
    writer.finish();
    bar.finish();
    if (interrupted) {
        std::fprintf(stderr,
                     "quaternia: interrupted with %lld frame%s written; run the same command "
                     "again to finish the film\n",
                     (long long)stats.rendered, stats.rendered == 1 ? "" : "s");
        return 130;
    }
    if (encoder) encoder->finish();
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    printFilmSummary(options, film, count, range, stats);
    return 0;
}

}  // namespace

void requireFilmMemory(const Scene& film, std::pair<int64_t, int64_t> range, bool video,
                       int framesInFlight, const AnimateCommandOptions& options) {
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
    requireImageMemory(
        largestScene,
        uint64_t(framesInFlight) * largest + (video ? pixels * (sizeof(Rgba) + 4) : 0), options,
        "the film (frames in flight)");
}

void checkFrames(const Scene& film, int64_t first, int64_t last, bool video) {
    std::map<std::string, bool> formulas;  // formulas checked already
    int width = 0, height = 0;
    for (int64_t frame = first; frame <= last; ++frame) {
        Scene scene = sceneAtFrame(film, frame);
        validateScene(scene);
        if (formulas.emplace(scene.fractal.formula, true).second) Fractal::fromScene(scene);
        if (frame == first) {
            width = scene.render.width;
            height = scene.render.height;
        } else if (video && (scene.render.width != width || scene.render.height != height)) {
            throw UserError("--video", "--video: frame " + std::to_string(frame) + " is " +
                                           std::to_string(scene.render.width) + "x" +
                                           std::to_string(scene.render.height) + ", frame " +
                                           std::to_string(first) + " " + std::to_string(width) +
                                           "x" + std::to_string(height) +
                                           ": a video's frames have one size");
        }
    }
}

void prepareDirectory(const std::string& directory, int64_t first, int64_t last, int64_t count) {
    std::error_code error;
    fs::create_directories(directory, error);
    if (error || !fs::is_directory(directory))
        throw UserError("-o", "cannot create the frame directory '" + directory +
                                  "': " + (error ? error.message() : "not a directory"));
    for (const fs::directory_entry& entry : fs::directory_iterator(directory, error)) {
        auto frame = staleFrameTemporary(entry.path().filename().string());
        if (frame && *frame >= first && *frame <= last) fs::remove(entry.path(), error);
    }
    AtomicFile probe((fs::path(directory) / frameFileName(first, count)).string());
}

std::vector<int64_t> framesToRender(const AnimateCommandOptions& options, int64_t count,
                                    std::pair<int64_t, int64_t> range) {
    std::vector<int64_t> frames;
    for (int64_t frame = range.first; frame <= range.second; ++frame)
        if (options.overwrite ||
            !fs::exists(fs::path(options.output) / frameFileName(frame, count)))
            frames.push_back(frame);
    return frames;
}

void printFilmSummary(const AnimateCommandOptions& options, const Scene& film, int64_t count,
                      std::pair<int64_t, int64_t> range, const FilmStats& stats,
                      const Json& extra) {
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

std::string frameFileName(int64_t frame, int64_t count) {
    int digits = std::max<int>(6, int(std::to_string(count).size()));
    std::string number = std::to_string(frame);
    return "frame_" + std::string(std::size_t(std::max<int>(0, digits - int(number.size()))), '0') +
           number + ".png";
}

std::pair<int64_t, int64_t> parseFrameRange(const std::string& text, int64_t count) {
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
    checkFrames(film, range.first, range.second, format.has_value());
    // One frame rendering, one queued for the writer, one being encoded.
    requireFilmMemory(film, range, format.has_value(), 3, options);
    prepareDirectory(options.output, range.first, range.second, count);
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
