#include <chrono>
#include <cstdio>
#include <optional>
#include <set>
#include <string>

#include "cmd/mpi_boundary.h"
#include "cmd/mpi_commands.h"
#include "cmd/mpi_report.h"
#include "cmd/render_command.h"
#include "quaternia/distribute/work_scheduler.h"
#include "quaternia/film/poster.h"
#include "quaternia/fractal/fractal.h"
#include "quaternia/scene/json.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/util/atomic_file.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

// A unit's result message: its number, its work (and the engine that did it: ranks may run on
// machines of different SIMD targets), its samples.
std::vector<uint8_t> unitMessage(const PosterUnit& unit) {
    MessageWriter message;
    const std::string engine = unit.stats.engine;
    message.putBytes(std::vector<uint8_t>(engine.begin(), engine.end()));
    const RenderStats& s = unit.stats;
    message.put(unit.unit).put(s.rays).put(s.hits).put(s.marchSteps).put(s.iterations);
    message.put(s.shadingEstimates).put(s.laneIterations).put(s.laneSlots);
    message.putBytes(unit.colour).putBytes(unit.depth);
    return message.bytes();
}

PosterUnit unitFromMessage(const std::vector<uint8_t>& bytes, std::string& engine) {
    MessageReader message(bytes);
    PosterUnit unit;
    RenderStats& s = unit.stats;
    const std::vector<uint8_t> engineName = message.getBytes();
    engine.assign(engineName.begin(), engineName.end());
    unit.unit = message.get<int64_t>();
    s.rays = message.get<int64_t>();
    s.hits = message.get<int64_t>();
    s.marchSteps = message.get<int64_t>();
    s.iterations = message.get<int64_t>();
    s.shadingEstimates = message.get<int64_t>();
    s.laneIterations = message.get<int64_t>();
    s.laneSlots = message.get<int64_t>();
    unit.colour = message.getBytes();
    unit.depth = message.getBytes();
    return unit;
}

// The rows of band buffers rank 0 holds: enough that every rank has units to work on while the
// oldest band waits for its last unit (two units per rank ahead), and at least two bands.
int64_t windowBandsFor(const PosterLayout& layout, int ranks) {
    return std::max<int64_t>(
        2, (2 * int64_t(ranks) + layout.unitsAcross - 1) / layout.unitsAcross + 1);
}

// Rank 0's memory beyond a fixed amount: its window of bands, once as samples and once more as
// the PNG stream's pieces, and the units in flight (its own render's float image and depth,
// and a unit received while it renders).
uint64_t posterMemoryBytes(const PosterLayout& layout, const PosterFormat& format, int ranks) {
    const uint64_t bandBytes =
        uint64_t(layout.width) * kUnitRows * (format.colourPixelBytes() + (format.depth ? 2 : 0));
    const uint64_t unitBytes = uint64_t(kUnitRows) * kUnitColumns * (sizeof(Rgba) + sizeof(float));
    return 2 * uint64_t(windowBandsFor(layout, ranks)) * bandBytes + 2 * unitBytes;
}

// quaternia render's summary, with the ranks' shares and rank 0's window of bands.
void printSummary(const RenderCommandOptions& options, const Scene& scene, const RenderStats& stats,
                  const std::vector<RankShare>& shares, const std::vector<int64_t>& pixels,
                  size_t windowBytes) {
    Json extra;
    extra["ranks"] = shares.size();
    extra["band_window_bytes"] = windowBytes;
    extra["per_rank"] = rankSharesJson(shares, "units");
    for (size_t rank = 0; rank < shares.size(); ++rank)
        extra["per_rank"][rank]["pixels"] = pixels[rank];
    printRenderSummary(options, scene, stats, extra);
    if (!options.json) printRankShares(shares, "units");
}

}  // namespace

int runMpiRender(const MpiSession& mpi, const RenderCommandOptions& options) {
    Scene scene;
    std::optional<AtomicFile> output, depthOutput;
    const int setUp = setUpOnEveryRank(mpi, [&] {
        scene = sceneFromOptions(options);
        validateScene(scene);
        fractalFromScene(scene);
        // The bands travel and are assembled as PNG rows; EXR's passes are quaternia render's.
        if (isExrPath(options.output))
            throw UserError("-o", "-o: quaternia-mpi writes PNG; write " + options.output +
                                      " with quaternia render");
        requireImageMemory(
            scene,
            posterMemoryBytes(PosterLayout(scene.render.width, scene.render.height),
                              PosterFormat::of(scene, !options.depthOutput.empty()), mpi.size()),
            options, "rank 0's window of bands");
        requireSceneTables(scene, options);
        if (mpi.rank() != 0) return;
        output.emplace(options.output);
        if (!options.depthOutput.empty()) depthOutput.emplace(options.depthOutput);
    });
    if (setUp != 0) return setUp;

    return runOrAbort(mpi, [&] {
        // The work owns the outputs: whatever ends it early (an error, an interruption, the job
        // ending because a rank died: SIGTERM) removes their temporaries before MPI_Abort.
        std::optional<AtomicFile> colourFile = std::move(output),
                                  depthFile = std::move(depthOutput);
        const PosterLayout layout(scene.render.width, scene.render.height);
        const PosterFormat format = PosterFormat::of(scene, !options.depthOutput.empty());
        InterruptScope interrupt;
        RenderWorkspace workspace;  // rank 0's local thread or a worker's one loop: one user
        WorkItems items;
        items.count = layout.units();
        items.run = [&](int64_t unit) {
            RenderOptions renderOptions;
            renderOptions.threads = options.threads;
            renderOptions.cancel = interrupt.flag();
            renderOptions.workspace = &workspace;
            std::optional<PosterUnit> rendered =
                renderPosterUnit(scene, layout, format, unit, renderOptions);
            if (!rendered) return std::vector<uint8_t>();
            return unitMessage(*rendered);
        };
        MpiChannel channel(mpi);
        if (mpi.rank() != 0) return workOnItems(channel, items, interrupt.flag()) ? 0 : 130;

        PosterAssembler assembler(layout, format, *colourFile, depthFile ? &*depthFile : nullptr,
                                  windowBandsFor(layout, mpi.size()), options.threads);
        RenderStats stats;
        std::vector<int64_t> pixels(size_t(mpi.size()));
        std::set<std::string> engines;  // the SIMD targets of the ranks, e.g. {"AVX2", "AVX3"}
        items.mayStart = [&](int64_t unit) { return assembler.mayStart(unit); };
        items.take = [&](int source, const std::vector<uint8_t>& bytes) {
            std::string engine;
            const PosterUnit unit = unitFromMessage(bytes, engine);
            engines.insert(engine);
            assembler.add(unit);
            stats += unit.stats;
            const Tile window = layout.window(unit.unit);
            pixels[size_t(source)] += int64_t(window.x1 - window.x0) * (window.y1 - window.y0);
        };
        ProgressBar bar("rendering", !options.json && ProgressBar::stderrIsTerminal());
        items.progress = progressOn(bar, "tiles");
        const auto start = std::chrono::steady_clock::now();
        const std::vector<RankShare> shares = handOutWork(channel, items, interrupt.flag());
        bar.finish();
        if (shares.empty()) return reportInterrupted();
        std::optional<AtomicFile> rgb = assembler.finish();
        (rgb ? *rgb : *colourFile).commit();
        if (depthFile) depthFile->commit();
        stats.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::string engineNames;
        for (const std::string& engine : engines)
            engineNames += (engineNames.empty() ? "" : "+") + engine;
        stats.engine = engineNames.c_str();
        stats.threads = resolveThreadCount(options.threads);
        printSummary(options, scene, stats, shares, pixels, assembler.windowBytes());
        return 0;
    });
}

}  // namespace quaternia
