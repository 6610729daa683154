#include <chrono>
#include <cstdio>
#include <optional>

#include "cmd/mpi_boundary.h"
#include "cmd/mpi_commands.h"
#include "cmd/mpi_report.h"
#include "quaternia/distribute/work_scheduler.h"
#include "quaternia/film/film_render.h"
#include "quaternia/film/frame_plan.h"
#include "quaternia/film/video_encoder.h"
#include "quaternia/scene/animation.h"
#include "quaternia/scene/json.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_file.h"
#include "quaternia/util/atomic_file.h"
#include "quaternia/util/error.h"

namespace quaternia {

int runMpiAnimate(const MpiSession& mpi, const AnimateCommandOptions& options) {
    Scene film;
    int64_t count = 0;
    FrameRange range;
    std::optional<VideoFormat> format;
    std::string ffmpeg;
    FrameDirectory directory;
    std::vector<int64_t> frames;
    const int setUp = setUpOnEveryRank(mpi, [&] {
        film = sceneFromOptions(options);
        validateAnimation(film);
        count = filmFrameCount(film);
        range = parseFrameRange(options.frames, count);
        directory = FrameDirectory{options.output, count};
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
        checkFrames(film, range, format.has_value());
        // Each rank renders one frame at a time (rank 0 on its local worker thread).
        requireFilmMemory(film, range, format.has_value() && mpi.rank() == 0, 1, options);
        prepareDirectory(directory, range);
        frames = framesToRender(directory, range, options.overwrite);
    });
    if (setUp != 0) return setUp;
    if (options.printFrame) {
        // The film was checked on every rank; rank 0 prints, as `quaternia animate` does.
        return mpi.rank() == 0 ? runOrAbort(mpi, [&] { return runAnimateCommand(options); }) : 0;
    }
    mpi.broadcastFromRankZero(frames);  // rank 0's list: the files it saw

    return runOrAbort(mpi, [&] {
        InterruptScope interrupt;
        RenderWorkspace workspace;
        WorkItems items;
        items.count = int64_t(frames.size());
        items.run = [&](int64_t item) {
            const int64_t frame = frames[size_t(item)];
            RenderOptions renderOptions;
            renderOptions.threads = options.threads;
            renderOptions.cancel = interrupt.flag();
            renderOptions.workspace = &workspace;
            if (!renderFrameFile(film, directory, frame, renderOptions))
                return std::vector<uint8_t>();
            return MessageWriter().put(frame).bytes();
        };
        MpiChannel channel(mpi);
        if (mpi.rank() != 0) return workOnItems(channel, items, interrupt.flag()) ? 0 : 130;

        int64_t rendered = 0;
        items.take = [&](int, const std::vector<uint8_t>&) { ++rendered; };
        ProgressBar bar("animating", !options.json && ProgressBar::stderrIsTerminal());
        items.progress = progressOn(bar, "frames");
        const auto start = std::chrono::steady_clock::now();
        const std::vector<RankShare> shares = handOutWork(channel, items, interrupt.flag());
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
            encodeFrameFiles(encoder, directory, range);
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
