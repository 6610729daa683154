// The table's sections of the commands besides render ([plane], [mesh], [orbit], [cycles]) and
// of the film of `quaternia animate` ([animation]) (parameter_sections.h).
#include <string>
#include <utility>
#include <vector>

#include "quaternia/scene/parameter_builders.h"
#include "quaternia/scene/parameter_sections.h"

namespace quaternia::parameter_builders {
namespace {

// The planes of rotation of H in slice.angles' order, for the animation's shortcuts.
std::vector<std::pair<std::string, RotationPlane>> rotationPlanes(bool withNone) {
    std::vector<std::pair<std::string, RotationPlane>> planes = {
        {"1i", RotationPlane::OneI}, {"1j", RotationPlane::OneJ}, {"1k", RotationPlane::OneK},
        {"ij", RotationPlane::IJ},   {"ik", RotationPlane::IK},   {"jk", RotationPlane::JK}};
    if (withNone) planes.insert(planes.begin(), {"none", RotationPlane::None});
    return planes;
}

}  // namespace

// [plane]: the 2D images of `quaternia plane`: which set, where, and how far it iterates.
std::vector<Parameter> planeParameters() {
    using S = Scene;
    using P = PlaneSettings;
    return {
        choiceParameter("plane", "kind", &S::plane, &P::kind, "julia",
                        {{"julia", PlaneKind::Julia},
                         {"julia-boundary", PlaneKind::JuliaBoundary},
                         {"mandelbrot", PlaneKind::Mandelbrot},
                         {"basins", PlaneKind::Basins},
                         {"slice", PlaneKind::Slice}},
                        "`quaternia plane` image: filled Julia set K_c (smooth escape colours), "
                        "its boundary J_c, the Mandelbrot set of z^d + c, basins of attraction, "
                        "or a slice plane.origin + x plane.u + y plane.v through the set (every "
                        "algebra)"),
        vectorParameter("plane", "center", &S::plane, &P::center, {0, 0}, -1e6, 1e6,
                        "The plane point (x, y) at the image centre; for julia, mandelbrot and "
                        "basins the complex number x + y i"),
        realParameter("plane", "width", &S::plane, &P::width, 4, 1e-12, 1e6,
                      "Width of the view in plane units (the height follows the image's aspect)"),
        withMotion(realParameter("plane", "rotation", &S::plane, &P::rotationDegrees, 0, -360, 360,
                                 "Counter-clockwise rotation of the view about its centre, in "
                                 "degrees"),
                   Motion::Angle),
        integerParameter("plane", "max_iterations", &S::plane, &P::maxIterations, 256, 1, 1000000,
                         "Iterations of every plane kind before a point counts as inside (the 3D "
                         "render's fractal.max_iterations is usually far fewer)"),
        vectorParameter("plane", "origin", &S::plane, &P::origin, {0, 0, 0, 0}, -1e6, 1e6,
                        "Slice kind: the point (1, i, j, k) at plane coordinates (0, 0); for the "
                        "8-component algebras a point (x, y, z, 0) of the 3D slice"),
        vectorParameter("plane", "u", &S::plane, &P::u, {1, 0, 0, 0}, -1e6, 1e6,
                        "Slice kind: the direction in H of the image's x axis; one plane unit "
                        "is its length"),
        vectorParameter("plane", "v", &S::plane, &P::v, {0, 1, 0, 0}, -1e6, 1e6,
                        "Slice kind: the direction in H of the image's y axis (up); must not be "
                        "parallel to plane.u"),
        realParameter("plane", "boundary_width", &S::plane, &P::boundaryWidth, 0.75, 0.01, 100,
                      "julia-boundary: J_c is drawn where the distance estimate is below this "
                      "many pixels"),
    };
}

// [mesh]: the grid and surface of `quaternia mesh`.
std::vector<Parameter> meshParameters() {
    using S = Scene;
    using M = MeshSettings;
    return {
        integerParameter(
            "mesh", "resolution", &S::mesh, &M::resolution, 256, 1, 2048,
            "Grid cells of `quaternia mesh` along the longest side of the set's "
            "bounding box; time and memory grow with its square (1024: 1.5 GB, 2048: about 6 GB)"),
        realParameter("mesh", "iso", &S::mesh, &M::iso, 0, 0, 16,
                      "Moves the mesh's surface outward by this many cells, thickening thin "
                      "parts for 3D printing; 0 meshes the set itself"),
        realParameter("mesh", "min_component", &S::mesh, &M::minComponent, 0, 0, 1e6,
                      "Drops connected pieces of the mesh whose volume (world units cubed) is "
                      "below this; 0 keeps every piece"),
    };
}

// [orbit]: the orbit that `quaternia orbit` follows.
std::vector<Parameter> orbitParameters() {
    using S = Scene;
    using O = OrbitSettings;
    return {
        vectorParameter("orbit", "z0", &S::orbit, &O::z0, {0, 0, 0, 0}, -1e6, 1e6,
                        "`quaternia orbit`: the starting point (1, i, j, k) whose orbit under "
                        "fractal.formula with fractal.c is followed"),
        integerParameter("orbit", "max_iterations", &S::orbit, &O::maxIterations, 1000, 1, 1000000,
                         "`quaternia orbit`: iterations before an orbit that neither escapes nor "
                         "settles counts as undecided (far more than fractal.max_iterations)"),
    };
}

// [cycles]: the periodic points that `quaternia cycles` lists.
std::vector<Parameter> cyclesParameters() {
    using S = Scene;
    using Y = CyclesSettings;
    return {
        // degree^period points are solved for, at most 1024 (kMaxPeriodicPoints): period 10
        // for a quadratic, less for higher degrees (checked by the command).
        integerParameter("cycles", "period", &S::cycles, &Y::period, 1, 1, 10,
                         "`quaternia cycles`: the period n whose periodic points are listed; "
                         "degree^n must be at most 1024"),
    };
}

// [animation]: the film's timing and its shortcuts (turns of the slice and the camera, a circle
// of c); its keys are [[animation.keys]] tables (scene_file.h), not table entries.
std::vector<Parameter> animationParameters() {
    using S = Scene;
    using A = AnimationSettings;
    return {
        realParameter("animation", "fps", &S::animation, &A::fps, 30, 0.01, 1000,
                      "Frames per second of `quaternia animate`; frame n is at (n - 1) / fps "
                      "seconds"),
        realParameter("animation", "duration", &S::animation, &A::duration, 0, 0, 86400,
                      "Length of the film in seconds; 0 takes it from animation.frames, or else "
                      "ends the film at the last key"),
        integerParameter("animation", "frames", &S::animation, &A::frames, 0, 0, 1000000,
                         "Number of frames; 0 means duration * fps"),
        choiceParameter("animation", "interpolation", &S::animation, &A::interpolation, "smooth",
                        interpolationChoices(),
                        "How values move from a key to the next, for keys that do not say: smooth "
                        "(through every key, no overshoot), linear, ease (stops at keys) or step"),
        choiceParameter(
            "animation", "turn_plane", &S::animation, &A::turnPlane, "none", rotationPlanes(true),
            "Turns the slice through 4D in this plane over the whole film (slice.angles' "
            "planes; 1k, ik or jk turn the hidden k axis into view)"),
        realParameter("animation", "turns", &S::animation, &A::turns, 1, -100, 100,
                      "Full turns of animation.turn_plane over the film; a quarter turn in 1k "
                      "shows what the slice hid, as the paper's g(qk) view does"),
        realParameter("animation", "orbit_turns", &S::animation, &A::orbitTurns, 0, -100, 100,
                      "Turns of the camera about camera.look_at, around camera.up, over the film"),
        choiceParameter("animation", "c_plane", &S::animation, &A::cPlane, "1i",
                        rotationPlanes(false),
                        "Plane of H in which c travels its circle (animation.c_radius)"),
        realParameter("animation", "c_radius", &S::animation, &A::cRadius, 0, 0, 10,
                      "c travels once around a circle of this radius about fractal.c over the "
                      "film; 0 keeps c still"),
    };
}

}  // namespace quaternia::parameter_builders
