#include "cmd/mesh_command.h"

#include <chrono>
#include <cstdio>

#include "cmd/scene_command.h"
#include "quaternia/fractal/fractal.h"
#include "quaternia/mesh/mesh_check.h"
#include "quaternia/mesh/mesh_io.h"
#include "quaternia/mesh/mesher.h"
#include "quaternia/scene/json.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/util/atomic_file.h"

namespace quaternia {
namespace {

Scene meshSceneFromOptions(const MeshCommandOptions& options) {
    Scene scene = sceneFromOptions(options);
    if (options.resolution) setParameter(scene, "mesh.resolution", *options.resolution);
    if (options.iso) setParameter(scene, "mesh.iso", *options.iso);
    if (options.minComponent) setParameter(scene, "mesh.min_component", *options.minComponent);
    return scene;
}

void printSummary(const MeshCommandOptions& options, const Scene& scene, MeshFormat format,
                  const MeshStats& stats, const MeshCheck& check, double seconds) {
    std::FILE* stream = summaryStream({options.output});
    if (!options.json) {
        std::fprintf(
            stream,
            "quaternia: wrote %s (%s, %lld triangles, %lld vertices, %lld component%s, %s) in "
            "%.2f s; volume %.6g, area %.6g; resolution %d (cell %.4g), %lld of %lld blocks, "
            "%d thread%s\n",
            options.output.c_str(), meshFormatName(format), (long long)check.triangles,
            (long long)check.vertices, (long long)check.components,
            check.components == 1 ? "" : "s",
            check.triangles == 0 ? "empty"
            : check.watertight() ? "closed"
                                 : "NOT closed",
            seconds, check.volume, check.area, scene.mesh.resolution, stats.grid.cellSize,
            (long long)stats.blocks, (long long)stats.latticeBlocks, stats.threads,
            stats.threads == 1 ? "" : "s");
        return;
    }
    Json json;
    json["command"] = "mesh";
    json["output"] = options.output;
    json["format"] = meshFormatName(format);
    json["formula"] = scene.fractal.formula;
    json["c"] = scene.fractal.c;
    json["resolution"] = scene.mesh.resolution;
    json["iso"] = scene.mesh.iso;
    json["min_component"] = scene.mesh.minComponent;
    json["cell_size"] = stats.grid.cellSize;
    json["grid"] = {stats.grid.cells[0], stats.grid.cells[1], stats.grid.cells[2]};
    json["triangles"] = check.triangles;
    json["vertices"] = check.vertices;
    json["components"] = check.components;
    json["dropped_components"] = stats.droppedComponents;
    json["volume"] = check.volume;
    json["area"] = check.area;
    json["watertight"] = check.watertight();
    json["boundary_edges"] = check.boundaryEdges;
    json["non_manifold_edges"] = check.nonManifoldEdges;
    json["misoriented_edges"] = check.misorientedEdges;
    json["non_manifold_vertices"] = check.nonManifoldVertices;
    json["degenerate_triangles"] = check.degenerateTriangles;
    json["lattice_blocks"] = stats.latticeBlocks;
    json["near_blocks"] = stats.nearBlocks;
    json["blocks"] = stats.blocks;
    json["closure_blocks"] = stats.closureBlocks;
    json["estimates"] = stats.estimates;
    json["threads"] = stats.threads;
    json["mesh_seconds"] = stats.seconds;
    json["seconds"] = seconds;
    std::fprintf(stream, "%s\n", jsonText(json).c_str());
}

}  // namespace

void addMeshCommand(CLI::App& app, MeshCommandOptions& options) {
    CLI::App* mesh = app.add_subcommand(
        "mesh", "Mesh a quaternion Julia set (closed, manifold) to STL, PLY or OBJ");
    addSceneOptions(*mesh, options,
                    "Output mesh; the extension picks the format: .stl (binary), .ply (binary, "
                    "with normals and colours) or .obj",
                    false);
    mesh->add_option("--resolution", options.resolution,
                     "Cells along the longest side of the set's bounding box (mesh.resolution)");
    mesh->add_option("--iso", options.iso,
                     "Move the surface outward by this many cells, for printing (mesh.iso)");
    mesh->add_option("--min-component", options.minComponent,
                     "Drop pieces of smaller volume, in world units cubed (mesh.min_component)");
    mesh->footer(sceneHelpFooter());
}

int runMeshCommand(const MeshCommandOptions& options) {
    auto start = std::chrono::steady_clock::now();
    Scene scene = meshSceneFromOptions(options);
    // Every check that can fail runs before the work: the scene, the formula, the format, and
    // whether the output can be written (a temporary beside it, renamed over it at the end).
    validateScene(scene);
    fractalFromScene(scene);
    MeshFormat format = meshFormatFromPath(options.output);
    AtomicFile output(options.output);

    MeshResult result = runInterruptibly("meshing", options, [&](const WorkOptions& work) {
        MeshOptions meshOptions{work};
        meshOptions.memory = memoryBudgetFromOptions(options);
        return meshScene(scene, meshOptions);
    });
    if (!result.completed) return reportInterrupted();
    MeshCheck check = checkMesh(result.mesh, options.threads);
    writeMesh(result.mesh, format, output);
    output.commit();
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    printSummary(options, scene, format, result.stats, check, seconds);
    return 0;
}

}  // namespace quaternia
