#include "cmd/certify_command.h"

#include <cstdio>

#include "quaternia/cellmap/certify_set.h"
#include "quaternia/image/png_writer.h"
#include "quaternia/plane/plane_cells.h"
#include "quaternia/scene/json.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/util/atomic_file.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

bool endsWith(const std::string& text, const std::string& tail) {
    return text.size() >= tail.size() &&
           text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}

Json levelsJson(const CellMappingReport& report) {
    Json levels = Json::array();
    for (const CellMappingLevel& l : report.levels) {
        Json level;
        level["level"] = l.level;
        level["cells"] = l.cells;
        level["outside"] = l.outside;
        level["inside"] = l.inside;
        level["undecided"] = l.undecided;
        level["inside_sweeps"] = l.insideSweeps;
        level["seconds"] = l.seconds;
        levels.push_back(level);
    }
    return levels;
}

int certifyPlane(const CertifyCommandOptions& options, const Scene& scene) {
    validatePlaneCells(scene);
    const MemoryBudget budget = memoryBudgetFromOptions(options);
    const uint64_t pixels = uint64_t(scene.render.width) * uint64_t(scene.render.height);
    const PngFormat format{scene.render.width, scene.render.height, 8, PngColorType::Gray};
    requireImageMemory(scene, 3 * pixels + pngBytesBound(format), options, "the classes image");
    AtomicFile output(options.output);
    const PlaneCells cells = runInterruptibly("certifying", options, [&](const WorkOptions& work) {
        return certifyPlaneCells(scene, work, budget.bytes ? budget.bytes : UINT64_MAX);
    });
    if (!cells.completed) return reportInterrupted();
    output.write(writePngBytes(format, cells.classes, options.threads));
    output.commit();
    std::FILE* stream = summaryStream({options.output});
    const double total = double(pixels);
    if (!options.json) {
        std::fprintf(
            stream,
            "quaternia: certified %s (%dx%d) in %.2f s: %lld outside, %lld inside, %lld "
            "undecided (%.3f%%); undecided band %d px wide (median), %d (99%%), %d (max)\n",
            options.output.c_str(), cells.width, cells.height, cells.report.seconds,
            (long long)cells.outside, (long long)cells.inside, (long long)cells.undecided,
            100 * double(cells.undecided) / total, cells.band.median, cells.band.p99,
            cells.band.max);
        return 0;
    }
    Json json;
    json["command"] = "certify";
    json["space"] = "plane";
    json["output"] = options.output;
    json["width"] = cells.width;
    json["height"] = cells.height;
    json["formula"] = scene.fractal.formula;
    json["c"] = cComponents(scene);
    json["escape_radius"] = cells.escapeRadius;
    Json counts;
    counts["outside"] = cells.outside;
    counts["inside"] = cells.inside;
    counts["undecided"] = cells.undecided;
    counts["undecided_fraction"] = double(cells.undecided) / total;
    json["pixels"] = counts;
    Json areas;
    areas["outside"] = double(cells.outside) * cells.pixelArea;
    areas["inside"] = double(cells.inside) * cells.pixelArea;
    areas["undecided"] = double(cells.undecided) * cells.pixelArea;
    json["areas"] = areas;
    Json band;
    band["median"] = cells.band.median;
    band["p99"] = cells.band.p99;
    band["max"] = cells.band.max;
    json["undecided_band_pixels"] = band;
    json["levels"] = levelsJson(cells.report);
    json["peak_memory_bytes"] = cells.report.peakMemoryBytes;
    json["threads"] = resolveThreadCount(options.threads);
    json["seconds"] = cells.report.seconds;
    std::fprintf(stream, "%s\n", jsonText(json).c_str());
    return 0;
}

Json censusJson(const CellGrid::Census& census) {
    Json json;
    json["outside"] = census.outside;
    json["inside"] = census.inside;
    json["undecided"] = census.undecided;
    json["outside_volume"] = census.outsideVolume;
    json["inside_volume"] = census.insideVolume;
    json["undecided_volume"] = census.undecidedVolume;
    return json;
}

int certifySetCells(const CertifyCommandOptions& options, const Scene& scene) {
    validateSetCertification(scene);
    const MemoryBudget budget = memoryBudgetFromOptions(options);
    AtomicFile output(options.output);
    const SetCertification result =
        runInterruptibly("certifying", options, [&](const WorkOptions& work) {
            return certifySet(scene, options.resolution, work,
                              budget.bytes ? budget.bytes : UINT64_MAX);
        });
    if (!result.completed) return reportInterrupted();
    const std::vector<uint8_t> bytes = result.set.encode();
    output.write(bytes);
    output.commit();
    double seconds = 0;
    uint64_t peak = 0;
    for (const CellMappingReport& report : result.reports)
        seconds += report.seconds, peak = std::max(peak, report.peakMemoryBytes);
    const bool product = result.set.space == CertifiedSpace::kProduct;
    std::FILE* stream = summaryStream({options.output});
    if (!options.json) {
        std::fprintf(stream, "quaternia: certified %s (%s, %lld cells per axis) in %.2f s:\n",
                     options.output.c_str(),
                     product ? "bicomplex product of two planes" : "reduced space (x, a, r)",
                     (long long)result.cellsPerAxis, seconds);
        for (size_t g = 0; g < result.census.size(); ++g) {
            const CellGrid::Census& c = result.census[g];
            const double total = c.outsideVolume + c.insideVolume + c.undecidedVolume;
            std::fprintf(stream,
                         "  %s: %lld outside, %lld inside, %lld undecided cells (%.3f%% of the "
                         "volume undecided)\n",
                         product ? (g == 0 ? "component 1" : "component 2") : "cells",
                         (long long)c.outside, (long long)c.inside, (long long)c.undecided,
                         100 * c.undecidedVolume / total);
        }
        return 0;
    }
    Json json;
    json["command"] = "certify";
    json["space"] = product ? "product" : "reduced";
    json["output"] = options.output;
    json["bytes"] = bytes.size();
    json["formula"] = scene.fractal.formula;
    json["algebra"] = std::string(algebraName(scene.fractal.algebra));
    json["c"] = cComponents(scene);
    json["escape_radius"] = result.set.escapeRadius;
    json["cells_per_axis"] = result.cellsPerAxis;
    Json grids = Json::array();
    for (size_t g = 0; g < result.census.size(); ++g) {
        Json grid = censusJson(result.census[g]);
        grid["levels"] = levelsJson(result.reports[g]);
        grids.push_back(grid);
    }
    json["grids"] = grids;
    json["peak_memory_bytes"] = peak;
    json["threads"] = resolveThreadCount(options.threads);
    json["seconds"] = seconds;
    std::fprintf(stream, "%s\n", jsonText(json).c_str());
    return 0;
}

}  // namespace

void addCertifyCommand(CLI::App& app, CertifyCommandOptions& options) {
    CLI::App* certify = app.add_subcommand(
        "certify",
        "Prove which points lie in the filled Julia set K itself (not K_N) by cell mapping: a "
        "complex plane image's classes (-o FILE.png: 0 outside, 255 inside, 128 undecided), or "
        "the scene's set as certified cells for render.certified (any other -o)");
    addSceneOptions(*certify, options,
                    "Output: a grey classes PNG of the plane image (plane.kind = julia), or a "
                    "cells file (.qcells) of the scene's set");
    certify
        ->add_option("--resolution", options.resolution,
                     "Finest cells per axis of the set's grid (cells files only)")
        ->check(CLI::Range(16, 4096));
    certify->footer(sceneHelpFooter());
}

int runCertifyCommand(const CertifyCommandOptions& options) {
    const Scene scene = sceneFromOptions(options);
    if (endsWith(options.output, ".png")) return certifyPlane(options, scene);
    return certifySetCells(options, scene);
}

}  // namespace quaternia
