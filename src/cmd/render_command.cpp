#include "render_command.h"

#include <cstdio>
#include <sstream>

#include "command_support.h"
#include "progress_bar.h"
#include "quaternia/fractal.h"
#include "quaternia/parameters.h"
#include "quaternia/png_io.h"
#include "quaternia/render.h"
#include "quaternia/util/atomic_file.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

Scene sceneFromOptions(const RenderCommandOptions& options) {
    Scene scene = loadSceneWithOverrides(options.scenePath, options.overrides);
    if (options.width) setParameter(scene, "render.width", *options.width);
    if (options.height) setParameter(scene, "render.height", *options.height);
    return scene;
}

void printSummary(const RenderCommandOptions& options, const Scene& scene,
                  const RenderStats& stats) {
    double raysPerSecond = stats.seconds > 0 ? stats.rays / stats.seconds : 0;
    if (!options.json) {
        std::printf(
            "quaternia: wrote %s (%dx%d, %d sample%s per pixel) in %.2f s, %.3g rays/s, "
            "%d thread%s\n",
            options.output.c_str(), scene.render.width, scene.render.height, scene.render.samples,
            scene.render.samples == 1 ? "" : "s", stats.seconds, raysPerSecond, stats.threads,
            stats.threads == 1 ? "" : "s");
        return;
    }
    std::ostringstream json;
    json.precision(6);
    json << "{\"command\": \"render\", \"output\": " << jsonString(options.output)
         << ", \"depth_output\": "
         << (options.depthOutput.empty() ? "null" : jsonString(options.depthOutput))
         << ", \"width\": " << scene.render.width << ", \"height\": " << scene.render.height
         << ", \"samples\": " << scene.render.samples
         << ", \"formula\": " << jsonString(scene.fractal.formula) << ", \"c\": ["
         << scene.fractal.c.w << ", " << scene.fractal.c.x << ", " << scene.fractal.c.y << ", "
         << scene.fractal.c.z << "], \"threads\": " << stats.threads
         << ", \"seconds\": " << stats.seconds << ", \"rays\": " << stats.rays
         << ", \"rays_per_second\": " << raysPerSecond << ", \"hits\": " << stats.hits
         << ", \"march_steps\": " << stats.marchSteps << ", \"iterations\": " << stats.iterations
         << ", \"shading_estimates\": " << stats.shadingEstimates << "}";
    std::printf("%s\n", json.str().c_str());
}

}  // namespace

void addRenderCommand(CLI::App& app, RenderCommandOptions& options) {
    CLI::App* render = app.add_subcommand("render", "Render a quaternion Julia set to a PNG");
    render->add_option("scene", options.scenePath,
                       "Scene file (TOML); without one the embedded default scene renders");
    render->add_option("-o,--output", options.output, "Output PNG (RGBA, alpha = coverage)")
        ->capture_default_str();
    render->add_option("--width", options.width, "Image width in pixels (render.width)");
    render->add_option("--height", options.height, "Image height in pixels (render.height)");
    render->add_option("--set", options.overrides,
                       "Override a scene key: section.key=value, value in TOML syntax "
                       "(a bare word is a string); repeatable");
    render->add_option("--threads", options.threads, "Worker threads (0 = every core)")
        ->capture_default_str();
    render->add_option("--depth", options.depthOutput,
                       "Also write a 16-bit grey depth pass to this PNG");
    render->add_flag("--json", options.json, "Print a machine-readable JSON summary");
    render->footer("Scene keys (scene file sections, or --set section.key=value):\n" +
                   parameterHelp());
}

int runRenderCommand(const RenderCommandOptions& options) {
    checkThreadCount(options.threads);
    Scene scene = sceneFromOptions(options);
    // Every check that can fail runs before the work: the scene, the formula, and whether the
    // outputs can be written (a temporary file beside each, renamed over it at the end).
    validateScene(scene);
    Fractal::fromScene(scene);
    AtomicFile output(options.output);
    std::optional<AtomicFile> depthOutput;
    if (!options.depthOutput.empty()) depthOutput.emplace(options.depthOutput);

    InterruptFlag interrupt;
    ProgressBar bar("rendering", !options.json && ProgressBar::stderrIsTerminal());
    RenderOptions renderOptions;
    renderOptions.threads = options.threads;
    renderOptions.cancel = interrupt.flag();
    renderOptions.progress = [&](double fraction) { bar.update(fraction); };
    renderOptions.depth = depthOutput.has_value();
    RenderResult result = render(scene, renderOptions);
    bar.finish();
    if (!result.completed) {
        std::fprintf(stderr, "quaternia: interrupted, nothing written\n");
        return 130;
    }

    auto png = encodePng(result.image, scene.render.bitDepth);
    output.write(png.data(), png.size());
    output.commit();
    if (depthOutput) {
        auto depthPng = encodeGrayPng16(result.depth);
        depthOutput->write(depthPng.data(), depthPng.size());
        depthOutput->commit();
    }
    printSummary(options, scene, result.stats);
    return 0;
}

}  // namespace quaternia
