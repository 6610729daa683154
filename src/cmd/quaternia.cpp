// quaternia: the command line. This is the boundary where user errors become one line on
// standard error and exit code 2; the library below never prints and never exits.
#include <cstdio>
#include <exception>

#include <CLI/CLI.hpp>

#include "cycles_command.h"
#include "explore_command.h"
#include "mesh_command.h"
#include "orbit_command.h"
#include "plane_command.h"
#include "quaternia/parameters.h"
#include "quaternia/util/error.h"
#include "render_command.h"

int main(int argc, char** argv) {
    using namespace quaternia;
    CLI::App app(
        "Quaternia: quaternion Julia sets, sliced from 4D into 3D, ray marched with "
        "distance estimation, shaded and exported.",
        "quaternia");
    app.require_subcommand(1);
    app.set_version_flag("--version", "quaternia 0.1.0");
    app.footer(
        "Run `quaternia COMMAND --help` for a command's options (render, plane, mesh, orbit, "
        "cycles, explore).\n\nScene "
        "keys (scene file "
        "sections, or --set section.key=value):\n" +
        parameterHelp());
    RenderCommandOptions renderOptions;
    addRenderCommand(app, renderOptions);
    OrbitCommandOptions orbitOptions;
    addOrbitCommand(app, orbitOptions);
    CyclesCommandOptions cyclesOptions;
    addCyclesCommand(app, cyclesOptions);
    PlaneCommandOptions planeOptions;
    addPlaneCommand(app, planeOptions);
    MeshCommandOptions meshOptions;
    addMeshCommand(app, meshOptions);
    ExploreCommandOptions exploreOptions;
    addExploreCommand(app, exploreOptions);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "quaternia: error: %s (see quaternia --help)\n", e.what());
        return 2;
    }
    try {
        if (app.got_subcommand("render")) return runRenderCommand(renderOptions);
        if (app.got_subcommand("orbit")) return runOrbitCommand(orbitOptions);
        if (app.got_subcommand("cycles")) return runCyclesCommand(cyclesOptions);
        if (app.got_subcommand("plane")) return runPlaneCommand(planeOptions);
        if (app.got_subcommand("mesh")) return runMeshCommand(meshOptions);
        if (app.got_subcommand("explore")) return runExploreCommand(exploreOptions);
    } catch (const UserError& e) {
        std::fprintf(stderr, "quaternia: error: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "quaternia: internal error: %s\n", e.what());
        return 1;
    }
    return 0;
}
