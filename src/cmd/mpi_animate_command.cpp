#include <mpi.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "cmd/mpi_boundary.h"
#include "cmd/mpi_commands.h"
#include "cmd/mpi_work.h"
#include "cmd/video_encoder.h"
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

// Rank 0's list of the frames to render, on every rank.
void broadcastFrames(std::vector<int64_t>& frames) {
    uint64_t count = frames.size();
    MPI_Bcast(&count, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
    frames.resize(count);
    if (count > 0) MPI_Bcast(frames.data(), int(count), MPI_INT64_T, 0, MPI_COMM_WORLD);
}

void printSummary(const AnimateCommandOptions& options, const Scene& film, int64_t count,
                  std::pair<int64_t, int64_t> range, int64_t rendered, double seconds,
                  const std::vector<RankShare>& shares) {
    const int64_t skipped = range.second - range.first + 1 - rendered;
    if (!options.json) {
        std::printf(
            "quaternia: %lld frame%s rendered, %lld skipped (frames %lld-%lld of %lld, "
            "%dx%d) into %s in %.2f s on %zu ranks%s%s\n",
            (long long)rendered, rendered == 1 ? "" : "s", (long long)skipped,
            (long long)range.first, (long long)range.second, (long long)count, film.render.width,
            film.render.height, options.output.c_str(), seconds, shares.size(),
            options.video.empty() ? "" : ", video ", options.video.c_str());
        for (size_t rank = 0; rank < shares.size(); ++rank)
            std::printf("  rank %zu: %lld frames, %.2f s rendering, peak %.0f MiB resident\n", rank,
                        (long long)shares[rank].items, shares[rank].busySeconds,
                        double(shares[rank].peakResidentKiB) / 1024);
        return;
    }
    Json json;
    json["command"] = "animate";
    json["output"] = options.output;
    json["video"] = options.video.empty() ? Json() : Json(options.video);
    json["film_frames"] = count;
    json["first_frame"] = range.first;
    json["last_frame"] = range.second;
    json["frames_rendered"] = rendered;
    json["frames_skipped"] = skipped;
    json["seconds"] = seconds;
    json["frames_per_second"] = seconds > 0 ? double(rendered) / seconds : 0.0;
    json["width"] = film.render.width;
    json["height"] = film.render.height;
    json["ranks"] = shares.size();
    json["threads_per_rank"] = resolveThreadCount(options.threads);
    Json ranks = Json::array();
    for (size_t rank = 0; rank < shares.size(); ++rank) {
        Json share;
        share["rank"] = rank;
        share["frames"] = shares[rank].items;
        share["render_seconds"] = shares[rank].busySeconds;
        share["peak_rss_kib"] = shares[rank].peakResidentKiB;
        ranks.push_back(share);
    }
    json["per_rank"] = ranks;
    std::printf("%s\n", jsonText(json).c_str());
}

}  // namespace

int runMpiAnimate(const MpiSession& mpi, const AnimateCommandOptions& options) {
    Scene film;
    int64_t count = 0;
    std::pair<int64_t, int64_t> range;
    std::optional<VideoFormat> format;
    std::string ffmpeg;
    std::vector<int64_t> frames;
    const int setUp = setUpOnEveryRank(mpi, [&] {
        if (options.printFrame)
            throw UserError("--print-frame",
                            "--print-frame: use `quaternia animate` to print a frame");
        film = sceneFromOptions(options);
        validateAnimation(film);
        count = filmFrameCount(film);
        range = parseFrameRange(options.frames, count);
        if (options.output.empty()) throw UserError("-o", "-o: the frame directory is empty");
        if (mpi.rank() != 0) return;
        if (!options.video.empty()) {
            format = videoFormatOf(options.video);
            ffmpeg = findFfmpeg();
        }
        checkFrames(film, range.first, range.second, format.has_value());
        prepareDirectory(options.output, range.first, range.second, count);
        frames = framesToRender(options, count, range);
    });
    if (setUp != 0) return setUp;
    broadcastFrames(frames);

    return runOrAbort(mpi, [&] {
        InterruptScope interrupt;
        RenderWorkspace workspace;
        WorkItems items;
        items.count = int64_t(frames.size());
        items.run = [&](int64_t item) {
            const int64_t frame = frames[size_t(item)];
            const Scene scene = sceneAtFrame(film, frame);
            RenderOptions renderOptions;
            renderOptions.threads = options.threads;
            renderOptions.cancel = interrupt.flag();
            renderOptions.workspace = &workspace;
            RenderResult result = renderForPng(scene, renderOptions);
            if (!result.completed) return std::vector<uint8_t>();
            writeFileAtomically((fs::path(options.output) / frameFileName(frame, count)).string(),
                                encodeRenderPng(result, scene.render.bitDepth));
            return MessageWriter().put(frame).bytes();
        };
        if (mpi.rank() != 0) return workOnItems(items, interrupt.flag()) ? 0 : 130;

        int64_t rendered = 0;
        items.take = [&](int, const std::vector<uint8_t>&) { ++rendered; };
        ProgressBar bar("animating", !options.json && ProgressBar::stderrIsTerminal());
        items.progress = [&](double fraction) { bar.update(fraction); };
        const auto start = std::chrono::steady_clock::now();
        const std::vector<RankShare> shares = handOutWork(mpi, items, interrupt.flag());
        bar.finish();
        if (shares.empty()) {
            std::fprintf(stderr,
                         "quaternia: interrupted with %lld frame%s written; run the same command "
                         "again to finish the film\n",
                         (long long)rendered, rendered == 1 ? "" : "s");
            return 130;
        }
        if (format) {
            const Scene first = sceneAtFrame(film, range.first);
            VideoEncoder encoder(ffmpeg, AtomicFile(options.video), *format, first.render.width,
                                 first.render.height, film.animation.fps);
            for (int64_t frame = range.first; frame <= range.second; ++frame)
                encoder.addFrame(
                    readPng((fs::path(options.output) / frameFileName(frame, count)).string()));
            encoder.finish();
        }
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        printSummary(options, film, count, range, rendered, seconds, shares);
        return 0;
    });
}

}  // namespace quaternia
