#include "cmd/render_command.h"

#include <cctype>
#include <cstdio>

#include "quaternia/fractal/fractal.h"
#include "quaternia/image/png_io.h"
#include "quaternia/render/pixel_certificate.h"
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
    std::FILE* stream = summaryStream({options.output, options.depthOutput, options.certifyOutput});
    double raysPerSecond = stats.seconds > 0 ? stats.rays / stats.seconds : 0;
    if (!options.json) {
        std::fprintf(stream,
                     "quaternia: wrote %s (%dx%d, %d sample%s per pixel) in %.2f s, %.3g rays/s, "
                     "%d thread%s\n",
                     options.output.c_str(), scene.render.width, scene.render.height,
                     scene.render.samples, scene.render.samples == 1 ? "" : "s", stats.seconds,
                     raysPerSecond, stats.threads, stats.threads == 1 ? "" : "s");
        if (extra.contains("certificate")) {
            const Json& c = extra["certificate"];
            std::fprintf(
                stream,
                "quaternia: certified %s against %s in %.2f s: %lld missed, %lld hit, %lld "
                "undecided (%.2f%%)\n",
                c["output"].is_null() ? "the picture" : c["output"].get<std::string>().c_str(),
                c["set"].get<std::string>().c_str(), c["seconds"].get<double>(),
                (long long)c["missed"].get<int64_t>(), (long long)c["hit"].get<int64_t>(),
                (long long)c["undecided"].get<int64_t>(),
                100 * c["undecided_fraction"].get<double>());
        }
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

// The certificate where --certify or --tint-undecided asks for one.
std::optional<PixelCertificate> certificateFor(const RenderCommandOptions& options,
                                               const Scene& scene) {
    std::optional<PixelCertificate> certificate;
    const bool completed = runInterruptibly("certifying", options, [&](const WorkOptions& work) {
        certificate = certifyPixels(scene, work);
        return certificate->completed;
    });
    if (!completed) return std::nullopt;
    return certificate;
}

Json certificateJson(const RenderCommandOptions& options, const Scene& scene,
                     const PixelCertificate& c) {
    Json json;
    json["output"] = options.certifyOutput.empty() ? Json() : Json(options.certifyOutput);
    // What the classes are proven against: K_N, or K itself from render.certified's cells.
    json["set"] = scene.render.certified.empty() ? "K_N" : "K";
    json["missed"] = c.counts.missed;
    json["hit"] = c.counts.hit;
    json["undecided"] = c.counts.undecided;
    json["undecided_fraction"] = c.counts.undecidedFraction();
    json["proofs"] = c.proofs;
    json["seconds"] = c.seconds;
    return json;
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
    render->add_option("--certify", options.certifyOutput,
                       "Also prove what each pixel's ray meets, in interval arithmetic, and write "
                       "the classes to this 8-bit grey PNG: 0 certainly missed, 255 certainly "
                       "hit, 128 undecided (counts in --json; with an .exr output the depth "
                       "interval of certain hits as channels certified.near and certified.far)");
    render->add_flag("--tint-undecided", options.tintUndecided,
                     "Tint the pixels the certificate leaves undecided magenta over the picture");
    render->footer(sceneHelpFooter());
}

int runRenderCommand(const RenderCommandOptions& options) {
    Scene scene = sceneFromOptions(options);
    // Every check that can fail runs before the work: the scene, the formula, whether a
    // certificate can be made, and whether the outputs can be written (a temporary file beside
    // each, renamed over it at the end).
    validateScene(scene);
    fractalFromScene(scene);
    const bool certify = !options.certifyOutput.empty() || options.tintUndecided;
    if (certify) validateCertificate(scene);
    const bool exr = isExrPath(options.output);
    const uint64_t pixels = uint64_t(scene.render.width) * uint64_t(scene.render.height);
    requireImageMemory(scene,
                       (exr ? renderExrMemoryBytes(scene) : 0) +
                           renderPngMemoryBytes(scene, !options.depthOutput.empty()) +
                           (certify ? pixels * (1 + 2 * sizeof(float) + 8 + sizeof(Rgba)) : 0),
                       options, "the render");
    requireSceneTables(scene, options);
    AtomicFile output(options.output);
    std::optional<AtomicFile> depthOutput, certifyOutput;
    if (!options.depthOutput.empty()) depthOutput.emplace(options.depthOutput);
    if (!options.certifyOutput.empty()) certifyOutput.emplace(options.certifyOutput);

    std::optional<RenderResult> result;
    const bool completed = runInterruptibly("rendering", options, [&](const WorkOptions& work) {
        RenderOptions renderOptions;
        static_cast<WorkOptions&>(renderOptions) = work;
        renderOptions.depth = depthOutput.has_value();
        renderOptions.passes = exr;
        result = exr || options.tintUndecided ? render(scene, renderOptions)
                                              : renderForPng(scene, renderOptions);
        return result->completed;
    });
    if (!completed) return reportInterrupted();
    std::optional<PixelCertificate> certificate;
    if (certify) {
        certificate = certificateFor(options, scene);
        if (!certificate) return reportInterrupted();
    }
    if (exr) {
        output.write(encodeRenderExr(result->passes, certificate ? &*certificate : nullptr));
    } else {
        if (options.tintUndecided) tintUndecided(result->image, *certificate);
        output.write(encodeRenderPng(*result, scene.render.bitDepth));
    }
    output.commit();
    if (depthOutput) {
        depthOutput->write(encodeGrayPng16(result->depth));
        depthOutput->commit();
    }
    if (certifyOutput) {
        certifyOutput->write(encodeCertificatePng(*certificate));
        certifyOutput->commit();
    }
    Json extra = Json::object();
    if (certificate) extra["certificate"] = certificateJson(options, scene, *certificate);
    printRenderSummary(options, scene, result->stats, extra);
    return 0;
}

}  // namespace quaternia
