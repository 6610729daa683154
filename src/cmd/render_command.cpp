#include "cmd/render_command.h"

#include <cctype>
#include <cstdio>

#include "quaternia/fractal/fractal.h"
#include "quaternia/image/png_io.h"
#include "quaternia/render/render_exr.h"
#include "quaternia/render/render_png.h"
#include "quaternia/scene/json.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/util/atomic_file.h"
#include "quaternia/util/error.h"

namespace quaternia {

void printRenderSummary(const RenderCommandOptions& options, const Scene& scene,
                        const RenderStats& stats, const Json& extra) {
    std::FILE* stream = summaryStream({options.output, options.depthOutput});
    double raysPerSecond = stats.seconds > 0 ? stats.rays / stats.seconds : 0;
    if (!options.json) {
        std::fprintf(stream,
                     "quaternia: wrote %s (%dx%d, %d sample%s per pixel) in %.2f s, %.3g rays/s, "
                     "%d thread%s\n",
                     options.output.c_str(), scene.render.width, scene.render.height,
                     scene.render.samples, scene.render.samples == 1 ? "" : "s", stats.seconds,
                     raysPerSecond, stats.threads, stats.threads == 1 ? "" : "s");
        return;
    }
    Json json;
    json["command"] = "render";
    json["output"] = options.output;
    json["depth_output"] = options.depthOutput.empty() ? Json() : Json(options.depthOutput);
    json["width"] = scene.render.width;
    json["height"] = scene.render.height;
    json["samples"] = scene.render.samples;
    json["formula"] = scene.fractal.formula;
    json["c"] = scene.fractal.c;
    json["threads"] = stats.threads;
    json["seconds"] = stats.seconds;
    json["rays"] = stats.rays;
    json["rays_per_second"] = raysPerSecond;
    json["hits"] = stats.hits;
    json["march_steps"] = stats.marchSteps;
    json["iterations"] = stats.iterations;
    json["shading_estimates"] = stats.shadingEstimates;
    json["lane_utilisation"] =
        stats.laneSlots > 0 ? double(stats.laneIterations) / double(stats.laneSlots) : 0.0;
    json["engine"] = stats.engine;
    json.update(extra);
    std::fprintf(stream, "%s\n", jsonText(json).c_str());
}

bool isExrPath(const std::string& path) {
    if (path.size() < 4) return false;
    std::string suffix = path.substr(path.size() - 4);
    for (char& ch : suffix)
        ch = char(std::tolower(static_cast<unsigned char>(ch)));
    return suffix == ".exr";
}

namespace {

// The render as OpenEXR, and the depth pass as a PNG where --depth asks for one too.
int renderExr(const RenderCommandOptions& options, const Scene& scene) {
    AtomicFile output(options.output);
    std::optional<AtomicFile> depthOutput;
    if (!options.depthOutput.empty()) depthOutput.emplace(options.depthOutput);
    std::optional<RenderResult> result;
    const bool completed = runInterruptibly("rendering", options, [&](const WorkOptions& work) {
        RenderOptions renderOptions;
        static_cast<WorkOptions&>(renderOptions) = work;
        renderOptions.depth = depthOutput.has_value();
        renderOptions.passes = true;
        result = render(scene, renderOptions);
        return result->completed;
    });
    if (!completed) return reportInterrupted();
    output.write(encodeRenderExr(result->passes));
    output.commit();
    if (depthOutput) {
        depthOutput->write(encodeGrayPng16(result->depth));
        depthOutput->commit();
    }
    printRenderSummary(options, scene, result->stats);
    return 0;
}

}  // namespace

void addRenderCommand(CLI::App& app, RenderCommandOptions& options) {
    CLI::App* render = app.add_subcommand("render", "Render a quaternion Julia set to a PNG");
    addSceneOptions(
        *render, options,
        "Output PNG (RGBA, alpha = coverage; RGB when every pixel is opaque), or OpenEXR where the "
        "name ends in .exr: linear colour, alpha and passes Z, N, trap, id");
    render->add_option("--depth", options.depthOutput,
                       "Also write a 16-bit grey depth pass to this PNG");
    render->footer(sceneHelpFooter());
}

int runRenderCommand(const RenderCommandOptions& options) {
    Scene scene = sceneFromOptions(options);
    // Every check that can fail runs before the work: the scene, the formula, and whether the
    // outputs can be written (a temporary file beside each, renamed over it at the end).
    validateScene(scene);
    fractalFromScene(scene);
    const bool exr = isExrPath(options.output);
    requireImageMemory(scene,
                       (exr ? renderExrMemoryBytes(scene) : 0) +
                           renderPngMemoryBytes(scene, !options.depthOutput.empty()),
                       options, "the render");
    requireEnvironment(scene, options);
    if (exr) return renderExr(options, scene);
    AtomicFile output(options.output);
    std::optional<AtomicFile> depthOutput;
    if (!options.depthOutput.empty()) depthOutput.emplace(options.depthOutput);

    PngRender result = runInterruptibly("rendering", options, [&](const WorkOptions& work) {
        RenderOptions renderOptions;
        static_cast<WorkOptions&>(renderOptions) = work;
        renderOptions.depth = depthOutput.has_value();
        return renderPng(scene, renderOptions);
    });
    if (!result.completed) return reportInterrupted();

    output.write(result.png);
    output.commit();
    if (depthOutput) {
        depthOutput->write(result.depthPng);
        depthOutput->commit();
    }
    printRenderSummary(options, scene, result.stats);
    return 0;
}

}  // namespace quaternia
