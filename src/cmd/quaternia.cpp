// quaternia: the command line. Its boundary (cli_boundary.h) is where user errors become one
// line on standard error and exit code 2; the library below never prints and never exits.
#include <cstdio>
#include <exception>
#include <string>

#include <CLI/CLI.hpp>

#include "cmd/animate_command.h"
#include "cmd/cli_boundary.h"
#include "cmd/cycles_command.h"
#include "cmd/explore_command.h"
#include "cmd/highway_runtime.h"
#include "cmd/mesh_command.h"
#include "cmd/orbit_command.h"
#include "cmd/plane_command.h"
#include "cmd/certify_command.h"
#include "cmd/reference_command.h"
#include "cmd/render_command.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/presets.h"
#include "quaternia/util/error.h"

int main(int argc, char** argv) {
    using namespace quaternia;
    CLI::App app(
        "Quaternia: quaternion Julia sets, sliced from 4D into 3D, ray marched with "
        "distance estimation, shaded and exported.",
        "quaternia");
    app.require_subcommand(1);
    app.set_version_flag("--version", "quaternia 0.1.0");
    app.footer(
        "Run `quaternia COMMAND --help` for a command's options (render, animate, plane, mesh, "
        "orbit, cycles, explore).\n\nScene "
        "keys (scene file "
        "sections, or --set section.key=value):\n" +
        parameterHelp() + "\n" + presetHelp() + "\n" + costHelp());
    std::string isa = "best";
    app.add_option("--isa", isa,
                   "Run the SIMD lanes on the best instruction set this CPU has up to this one "
                   "(before the command: `quaternia --isa avx2 render ...` measures an AVX2 "
                   "machine on an AVX-512 one); --json's engine names the one taken")
        ->check(CLI::IsMember(laneTargetNames()))
        ->capture_default_str();
    RenderCommandOptions renderOptions;
    addRenderCommand(app, renderOptions);
    AnimateCommandOptions animateOptions;
    addAnimateCommand(app, animateOptions);
    OrbitCommandOptions orbitOptions;
    addOrbitCommand(app, orbitOptions);
    CyclesCommandOptions cyclesOptions;
    addCyclesCommand(app, cyclesOptions);
    PlaneCommandOptions planeOptions;
    addPlaneCommand(app, planeOptions);
    CertifyCommandOptions certifyOptions;
    addCertifyCommand(app, certifyOptions);
    MeshCommandOptions meshOptions;
    addMeshCommand(app, meshOptions);
    ExploreCommandOptions exploreOptions;
    addExploreCommand(app, exploreOptions);
    ReferenceCommandOptions referenceOptions;
    addReferenceCommand(app, referenceOptions);
    if (auto code = parseCommandLine(app, argc, argv, "quaternia")) return *code;
    limitLaneTargets(isa);
    return runAtBoundary([&] {
        if (app.got_subcommand("render")) return runRenderCommand(renderOptions);
        if (app.got_subcommand("animate")) return runAnimateCommand(animateOptions);
        if (app.got_subcommand("orbit")) return runOrbitCommand(orbitOptions);
        if (app.got_subcommand("cycles")) return runCyclesCommand(cyclesOptions);
        if (app.got_subcommand("plane")) return runPlaneCommand(planeOptions);
        if (app.got_subcommand("certify")) return runCertifyCommand(certifyOptions);
        if (app.got_subcommand("mesh")) return runMeshCommand(meshOptions);
        if (app.got_subcommand("explore")) return runExploreCommand(exploreOptions);
        if (app.got_subcommand("reference")) return runReferenceCommand(app, referenceOptions);
        return 0;
    });
}
