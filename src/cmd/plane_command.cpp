#include "cmd/plane_command.h"

#include <cstdio>
#include <filesystem>
#include <optional>

#include "cmd/dynamics_input.h"
#include "quaternia/dynamics/connectedness.h"
#include "quaternia/image/png_io.h"
#include "quaternia/image/png_writer.h"
#include "quaternia/plane/plane_certificate.h"
#include "quaternia/plane/plane_render.h"
#include "quaternia/scene/json.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/util/atomic_file.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

// For the kinds that draw one complex polynomial: whether its K is connected, from the
// critical orbits (connectedness.h); empty for the others.
std::string connectednessNote(const Scene& scene) {
    PlaneKind kind = scene.plane.kind;
    if (kind != PlaneKind::Julia && kind != PlaneKind::JuliaBoundary && kind != PlaneKind::Basins)
        return {};
    ComplexPolynomial p = complexRestrictionOfScene(scene).polynomial;
    if (p.degree() < 2) return {};
    Connectedness k = connectedness(p, scene.plane.maxIterations);
    std::string hedge = k.certain ? "" : " (within plane.max_iterations)";
    if (k.cantor)
        return "K is a Cantor set: every critical orbit escapes (for z^2 + c, c is not in M)";
    if (!k.connected) return "K is disconnected: some critical orbits escape, others stay bounded";
    return "K is connected: every critical orbit stays bounded" + hedge +
           " (for z^2 + c, c is in M)";
}

// The classes as an 8-bit grey PNG: 0 certainly missed, 255 certainly hit, 128 undecided.
std::vector<uint8_t> certificatePng(const PlaneCertificate& certificate, int threads) {
    const PngFormat format{certificate.width, certificate.height, 8, PngColorType::Gray};
    return writePngBytes(format, certificate.classes, threads);
}

void printSummary(const PlaneCommandOptions& options, const Scene& scene, const PlaneImage& image,
                  const PlaneCertificate* certificate, const std::string& note) {
    std::FILE* stream = summaryStream({options.output, options.certify});
    const std::string kind = std::get<std::string>(findParameter("plane.kind")->read(scene));
    if (!options.json) {
        std::fprintf(
            stream,
            "quaternia: wrote %s (%s, %dx%d, %d sample%s per pixel) in %.2f s, %d thread%s\n",
            options.output.c_str(), kind.c_str(), scene.render.width, scene.render.height,
            scene.render.samples, scene.render.samples == 1 ? "" : "s", image.seconds,
            image.threads, image.threads == 1 ? "" : "s");
        if (certificate)
            std::fprintf(stream,
                         "quaternia: certified %s in %.2f s: %lld missed, %lld hit, %lld "
                         "undecided (%.2f%%)\n",
                         options.certify.c_str(), certificate->seconds,
                         (long long)certificate->counts.missed, (long long)certificate->counts.hit,
                         (long long)certificate->counts.undecided,
                         100 * certificate->counts.undecidedFraction());
        if (!note.empty()) std::fprintf(stream, "note: %s\n", note.c_str());
        return;
    }
    Json json;
    json["command"] = "plane";
    json["kind"] = kind;
    json["output"] = options.output;
    json["width"] = scene.render.width;
    json["height"] = scene.render.height;
    json["samples"] = scene.render.samples;
    json["formula"] = scene.fractal.formula;
    if (scene.fractal.algebra != Algebra::kQuaternion)
        json["algebra"] = std::string(algebraName(scene.fractal.algebra));
    json["c"] = cComponents(scene);
    json["threads"] = image.threads;
    json["seconds"] = image.seconds;
    json["note"] = note.empty() ? Json() : Json(note);
    if (certificate) {
        Json classes;
        classes["missed"] = certificate->counts.missed;
        classes["hit"] = certificate->counts.hit;
        classes["undecided"] = certificate->counts.undecided;
        classes["undecided_fraction"] = certificate->counts.undecidedFraction();
        classes["seconds"] = certificate->seconds;
        classes["output"] = options.certify;
        json["certificate"] = classes;
    }
    std::fprintf(stream, "%s\n", jsonText(json).c_str());
}

}  // namespace

void addPlaneCommand(CLI::App& app, PlaneCommandOptions& options) {
    CLI::App* plane = app.add_subcommand(
        "plane",
        "Draw a 2D image: a Julia set, its boundary, the Mandelbrot set, basins of "
        "attraction or a plane through a Julia set in any algebra (plane.kind)");
    addSceneOptions(*plane, options, "Output PNG (RGB: plane images are opaque)");
    plane->add_option("--certify", options.certify,
                      "Also write each pixel's proven class as a grey PNG: 0 where interval "
                      "arithmetic proves no point of the pixel in K_N, 255 where the pixel's "
                      "centre is proven in K_N, 128 undecided (not for plane.kind = basins)");
    plane->footer(sceneHelpFooter());
}

int runPlaneCommand(const PlaneCommandOptions& options) {
    Scene scene = sceneFromOptions(options);
    // Every check that can fail runs before the work, the output path included.
    validatePlaneScene(scene);
    const bool certify = !options.certify.empty();
    if (certify) {
        validatePlaneCertificate(scene);
        auto normal = [](const std::string& path) {
            return std::filesystem::absolute(path).lexically_normal();
        };
        if (normal(options.certify) == normal(options.output))
            throw UserError("--certify", "--certify names the image's own file " + options.output +
                                             "; give the classes another one");
    }
    const std::string note = connectednessNote(scene);
    const uint64_t pixels = uint64_t(scene.render.width) * uint64_t(scene.render.height);
    const PngFormat classesFormat{scene.render.width, scene.render.height, 8, PngColorType::Gray};
    requireImageMemory(
        scene, planeMemoryBytes(scene) + (certify ? pixels + pngBytesBound(classesFormat) : 0),
        options, "the image");
    requireFractalMemory(scene, memoryBudgetFromOptions(options));
    AtomicFile output(options.output);
    std::optional<AtomicFile> classesOutput;
    if (certify) classesOutput.emplace(options.certify);

    PlaneImage image = runInterruptibly(
        "drawing", options, [&](const WorkOptions& work) { return renderPlane(scene, work); });
    if (!image.completed) return reportInterrupted();
    std::optional<PlaneCertificate> certificate;
    if (certify) {
        certificate = runInterruptibly("certifying", options, [&](const WorkOptions& work) {
            return certifyPlane(scene, work);
        });
        if (!certificate->completed) return reportInterrupted();
    }
    output.write(encodePng(image.image, scene.render.bitDepth));
    if (certificate) classesOutput->write(certificatePng(*certificate, options.threads));
    output.commit();
    if (classesOutput) classesOutput->commit();
    printSummary(options, scene, image, certificate ? &*certificate : nullptr, note);
    return 0;
}

}  // namespace quaternia
