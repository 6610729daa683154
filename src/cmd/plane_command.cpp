#include "cmd/plane_command.h"

#include <cstdio>

#include "cmd/dynamics_input.h"
#include "quaternia/dynamics/connectedness.h"
#include "quaternia/image/png_io.h"
#include "quaternia/plane/plane_render.h"
#include "quaternia/scene/json.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/util/atomic_file.h"

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

void printSummary(const PlaneCommandOptions& options, const Scene& scene, const PlaneImage& image,
                  const std::string& note) {
    std::FILE* stream = summaryStream({options.output});
    const std::string kind = std::get<std::string>(findParameter("plane.kind")->read(scene));
    if (!options.json) {
        std::fprintf(
            stream,
            "quaternia: wrote %s (%s, %dx%d, %d sample%s per pixel) in %.2f s, %d thread%s\n",
            options.output.c_str(), kind.c_str(), scene.render.width, scene.render.height,
            scene.render.samples, scene.render.samples == 1 ? "" : "s", image.seconds,
            image.threads, image.threads == 1 ? "" : "s");
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
    std::fprintf(stream, "%s\n", jsonText(json).c_str());
}

}  // namespace

void addPlaneCommand(CLI::App& app, PlaneCommandOptions& options) {
    CLI::App* plane = app.add_subcommand(
        "plane",
        "Draw a 2D image: a Julia set, its boundary, the Mandelbrot set, basins of "
        "attraction or a plane through a Julia set in any algebra (plane.kind)");
    addSceneOptions(*plane, options, "Output PNG (RGB: plane images are opaque)");
    plane->footer(sceneHelpFooter());
}

int runPlaneCommand(const PlaneCommandOptions& options) {
    Scene scene = sceneFromOptions(options);
    // Every check that can fail runs before the work, the output path included.
    validatePlaneScene(scene);
    const std::string note = connectednessNote(scene);
    requireImageMemory(scene, planeMemoryBytes(scene), options, "the image");
    AtomicFile output(options.output);

    PlaneImage image = runInterruptibly(
        "drawing", options, [&](const WorkOptions& work) { return renderPlane(scene, work); });
    if (!image.completed) return reportInterrupted();
    output.write(encodePng(image.image, scene.render.bitDepth));
    output.commit();
    printSummary(options, scene, image, note);
    return 0;
}

}  // namespace quaternia
