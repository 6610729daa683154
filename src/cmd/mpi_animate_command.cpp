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

}  // namespace

int runMpiAnimate(const MpiSession& mpi, const AnimateCommandOptions& options) {
    Scene film;
    int64_t count = 0;
    std::pair<int64_t, int64_t> range;
    std::optional<VideoFormat> format;
    std::string ffmpeg;
    std::vector<int64_t> frames;
    const int setUp = setUpOnEveryRank(mpi, [&] {
        film = sceneFromOptions(options);
        validateAnimation(film);
        count = filmFrameCount(film);
        range = parseFrameRange(options.frames, count);
        if (options.printFrame) {
            if (*options.printFrame < 1 || *options.printFrame > count)
                throw UserError("--print-frame",
                                "--print-frame " + std::to_string(*options.printFrame) +
                                    ": the film has frames 1-" + std::to_string(count));
            return;
        }
        if (options.output.empty()) throw UserError("-o", "-o: the frame directory is empty");
        if (mpi.rank() != 0) return;
        if (!options.video.empty()) {
            format = videoFormatOf(options.video);
            ffmpeg = findFfmpeg();
        }
        checkFrames(film, range.first, range.second, format.has_value());
        // Each rank renders one frame at a time (rank 0 on its local worker thread).
        requireFilmMemory(film, range, format.has_value() && mpi.rank() == 0, 1, options);
        prepareDirectory(options.output, range.first, range.second, count);
        frames = framesToRender(options, count, range);
    });
    if (setUp != 0) return setUp;
    if (options.printFrame) {
        // The film was checked on every rank; rank 0 prints, as `quaternia animate` does.
        return mpi.rank() == 0 ? runOrAbort(mpi, [&] { return runAnimateCommand(options); }) : 0;
    }
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
        items.progress = progressOn(bar, "frames");
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
        FilmStats stats;
        stats.rendered = rendered;
        stats.skipped = range.second - range.first + 1 - rendered;
        stats.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        for (const RankShare& share : shares)
            stats.renderSeconds += share.busySeconds;
        stats.threads = resolveThreadCount(options.threads);
        Json extra;
        extra["ranks"] = shares.size();
        extra["per_rank"] = rankSharesJson(shares, "frames");
        printFilmSummary(options, film, count, range, stats, extra);
        if (!options.json) printRankShares(shares, "frames");
        return 0;
    });
}

}  // namespace quaternia
