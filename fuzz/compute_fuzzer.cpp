// What computes (issue 41): the input becomes a random valid scene, built as a user would build
// it with --set (algebra, a formula from a grammar of polynomials and, for the bicomplex
// algebra, functions, c, z0, slice, camera, look, small limits), and one of the library paths
// behind the commands runs on it: orbit (with connectedness), cycles, a plane image of every
// kind (basins included), a render of a few pixels on either engine, a coarse mesh, or a frame of
// a film. A UserError is a clean refusal; a crash, a sanitizer report, any other exception or a
// hang is a finding. The seed corpus (corpus/compute) holds the reproductions of the issue.
#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "fuzz/fuzz_check.h"
#include "fuzz/toml_unicode_bug.h"
#include "quaternia/algebra/complex_polynomial.h"
#include "quaternia/algebra/formula.h"
#include "quaternia/dynamics/connectedness.h"
#include "quaternia/dynamics/orbit.h"
#include "quaternia/dynamics/periodic_points.h"
#include "quaternia/fractal/fractal.h"
#include "quaternia/fractal/hypercomplex_julia.h"
#include "quaternia/mesh/mesher.h"
#include "quaternia/plane/plane_render.h"
#include "quaternia/render/render.h"
#include "quaternia/scene/animation.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_file.h"
#include "quaternia/scene/scene_fractal.h"
#include "quaternia/util/error.h"

using namespace quaternia;

namespace {

constexpr const char* kAlgebras[] = {"quaternion", "bicomplex", "coquaternion", "biquaternion",
                                     "octonion"};
constexpr const char* kFunctions[] = {"exp",  "log",   "sin",   "cos",   "tan",
                                      "sinh", "cosh",  "tanh",  "asin",  "acos",
                                      "atan", "asinh", "acosh", "atanh", "reciprocal"};
constexpr const char* kPlaneKinds[] = {"julia", "julia-boundary", "mandelbrot", "basins", "slice"};

template <size_t N>
const char* pick(FuzzedDataProvider& in, const char* const (&names)[N]) {
    return names[in.ConsumeIntegralInRange<size_t>(0, N - 1)];
}

// A number with three decimals in [-scale, scale], as the scripts' scenes have.
std::string number(FuzzedDataProvider& in, double scale) {
    const int steps = int(scale * 1000);
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", in.ConsumeIntegralInRange(-steps, steps) / 1000.0);
    return text;
}

std::string list(FuzzedDataProvider& in, int count, double scale) {
    std::string text = "[";
    for (int n = 0; n < count; ++n)
        text += (n ? ", " : "") + number(in, scale);
    return text + "]";
}

std::string coefficient(FuzzedDataProvider& in) {
    switch (in.ConsumeIntegralInRange(0, 3)) {
        case 0:
            return number(in, 2);
        case 1:
            return std::string(1, "ijk"[in.ConsumeIntegralInRange(0, 2)]);
        default:
            return "(" + number(in, 1) + "+" + number(in, 1) + "i+" + number(in, 1) + "j+" +
                   number(in, 1) + "k)";
    }
}

// sum of terms (z^d, a z^d, or two-sided a z b z ...) plus c; bicomplex functions.
std::string formula(FuzzedDataProvider& in, bool bicomplex) {
    if (bicomplex && in.ConsumeBool())
        return std::string(pick(in, kFunctions)) + "(" + (in.ConsumeBool() ? "z" : "z^2") + ") + c";
    const int top = in.ConsumeIntegralInRange(2, 5);
    std::string text;
    switch (in.ConsumeIntegralInRange(0, 2)) {
        case 0:
            text = "z^" + std::to_string(top);
            break;
        case 1:
            text = coefficient(in) + "*z^" + std::to_string(top);
            break;
        default:
            for (int k = 0; k < top; ++k)
                text += (in.ConsumeBool() ? coefficient(in) + "*" : "") + (k ? "*z" : "z");
            if (in.ConsumeBool()) text += "*" + coefficient(in);
    }
    for (int extra = in.ConsumeIntegralInRange(0, 2); extra > 0; --extra) {
        const int degree = in.ConsumeIntegralInRange(1, top - 1);
        text +=
            (in.ConsumeBool() ? " + " : " - ") + coefficient(in) + "*z^" + std::to_string(degree);
    }
    return text + " + c";
}

void set(Scene& scene, const std::string& assignment) {
    applyOverride(scene, assignment);
}

Scene randomScene(FuzzedDataProvider& in) {
    Scene scene = defaultScene();
    const std::string algebra = pick(in, kAlgebras);
    set(scene, "fractal.algebra=\"" + algebra + "\"");
    const int dimension = algebraDimension(scene.fractal.algebra);
    set(scene, "fractal.formula=\"" + formula(in, algebra == "bicomplex") + "\"");
    set(scene, "fractal.c=" + list(in, dimension, 1.5));
    set(scene, "fractal.max_iterations=" + std::to_string(in.ConsumeIntegralInRange(2, 24)));
    if (in.ConsumeBool())
        set(scene, "fractal.bailout=" + std::to_string(in.ConsumeIntegralInRange(0, 8)));
    set(scene, "orbit.z0=" + list(in, 4, 1.2));
    if (dimension == 4) {
        if (in.ConsumeBool()) {
            const std::string w = std::to_string(in.ConsumeIntegralInRange(100, 1000) / 1000.0);
            std::string normal = list(in, 3, 1);  // x, y, z, then a w that is not 0
            set(scene, "slice.normal=" + normal.insert(normal.size() - 1, ", " + w));
        }
        if (in.ConsumeBool()) set(scene, "slice.angles=" + list(in, 6, 180));
        if (in.ConsumeBool()) set(scene, "slice.distance=" + number(in, 0.5));
    } else if (in.ConsumeBool()) {
        set(scene, "slice.origin=" + list(in, 8, 0.3));
    }
    set(scene, "render.width=" + std::to_string(in.ConsumeIntegralInRange(1, 6)));
    set(scene, "render.height=" + std::to_string(in.ConsumeIntegralInRange(1, 5)));
    set(scene, "render.samples=" + std::to_string(in.ConsumeIntegralInRange(1, 2)));
    return scene;
}

// The look: engine, method, materials and lights, on the lanes where those need them.
void randomLook(FuzzedDataProvider& in, Scene& scene) {
    const bool scalar = in.ConsumeBool();
    set(scene, std::string("render.engine=") + (scalar ? "\"scalar\"" : "\"simd\""));
    set(scene, std::string("render.precision=") + (in.ConsumeBool() ? "\"double\"" : "\"single\""));
    if (in.ConsumeBool()) set(scene, "render.adaptive=true");
    if (in.ConsumeBool()) set(scene, "camera.position=" + list(in, 3, 5));
    if (in.ConsumeBool()) set(scene, "camera.aperture=0.05");
    if (in.ConsumeBool()) set(scene, "shading.light_kind=\"point\"");
    if (in.ConsumeBool()) set(scene, "shading.fog_density=0.2");
    if (scalar) return;
    if (in.ConsumeBool()) set(scene, "material.reflectivity=0.5");
    if (in.ConsumeBool()) set(scene, "material.transparency=0.7");
    if (in.ConsumeBool()) set(scene, "ground.enabled=true");
    if (in.ConsumeBool()) set(scene, "shading.glow_intensity=1");
}

WorkOptions oneThread() {
    WorkOptions work;
    work.threads = 1;
    return work;
}

void runOrbit(const Scene& scene) {
    OrbitOptions options;
    options.maxIterations = scene.orbit.maxIterations;
    const Quaternion& z = scene.orbit.z0;
    if (scene.fractal.algebra == Algebra::kQuaternion) {
        const Polynomial p = compileFormula(scene.fractal.formula, scene.fractal.c);
        analyzeOrbit(p, z, options);
        if (auto restriction = restrictToComplexPlane(p))
            connectedness(restriction->polynomial, options.maxIterations);
        return;
    }
    const auto fractal = hypercomplexFractalFromScene(scene);
    const Hypercomplex z0{z.w, z.x, z.y, z.z, 0, 0, 0, 0};
    const auto& set = *fractal.setAs<HypercomplexJuliaSet>();
    if (set.formula().dimension() == 4)
        analyzeHypercomplexOrbit<4>(set.formula(), set.escapeRadius(), z0, options);
    else
        analyzeHypercomplexOrbit<8>(set.formula(), set.escapeRadius(), z0, options);
}

void runCycles(FuzzedDataProvider& in, const Scene& scene) {
    if (scene.fractal.algebra != Algebra::kQuaternion) return;
    const auto restriction =
        restrictToComplexPlane(compileFormula(scene.fractal.formula, scene.fractal.c));
    if (!restriction) return;
    periodicPoints(restriction->polynomial, in.ConsumeIntegralInRange(1, 3));
}

void runPlane(FuzzedDataProvider& in, Scene& scene, bool random) {
    if (random) {
        set(scene, std::string("plane.kind=\"") + pick(in, kPlaneKinds) + "\"");
        set(scene, "plane.max_iterations=" + std::to_string(in.ConsumeIntegralInRange(4, 64)));
        set(scene, "render.width=" + std::to_string(in.ConsumeIntegralInRange(1, 12)));
        set(scene, "render.height=" + std::to_string(in.ConsumeIntegralInRange(1, 12)));
    }
    validatePlaneScene(scene);
    const PlaneKind kind = scene.plane.kind;
    if (kind == PlaneKind::Julia || kind == PlaneKind::JuliaBoundary || kind == PlaneKind::Basins) {
        const ComplexPolynomial p = complexRestrictionOfScene(scene).polynomial;
        if (p.degree() >= 2) connectedness(p, scene.plane.maxIterations);
    }
    PlaneRenderOptions options;
    static_cast<WorkOptions&>(options) = oneThread();
    renderPlane(scene, options);
}

void runRender(FuzzedDataProvider& in, Scene& scene, bool random) {
    if (random) randomLook(in, scene);
    validateScene(scene);
    RenderOptions options;
    static_cast<WorkOptions&>(options) = oneThread();
    options.depth = in.ConsumeBool();
    options.passes = in.ConsumeBool();
    render(scene, options);
}

void runMesh(FuzzedDataProvider& in, Scene& scene, bool random) {
    if (random) set(scene, "mesh.resolution=" + std::to_string(in.ConsumeIntegralInRange(2, 10)));
    validateScene(scene);
    MeshOptions options;
    static_cast<WorkOptions&>(options) = oneThread();
    meshScene(scene, options);
}

void runFilmFrame(FuzzedDataProvider& in, Scene& scene, bool random) {
    if (random) {
        set(scene, "animation.frames=" + std::to_string(in.ConsumeIntegralInRange(1, 8)));
        set(scene,
            "animation.c_radius=" + std::to_string(in.ConsumeIntegralInRange(0, 300) / 1000.0));
        if (in.ConsumeBool()) set(scene, "animation.turn_plane=\"jk\"");
    }
    validateAnimation(scene);
    const Scene frame =
        sceneAtFrame(scene, in.ConsumeIntegralInRange<int64_t>(1, filmFrameCount(scene)));
    validateScene(frame);
    RenderOptions options;
    static_cast<WorkOptions&>(options) = oneThread();
    render(frame, options);
}

enum class Path { kCycles, kPlane, kRender, kMesh, kFilm, kCount };
constexpr const char* kPathNames[] = {"cycles", "plane", "render", "mesh", "film"};

// The text form of an input, for seeds a person writes: a first line "path=NAME" (cycles,
// plane, render, mesh, film; any other name, such as orbit, runs the orbit alone), then one
// --set assignment per line; the scene starts from the default and nothing else is random.
void readTextScene(std::string_view text, Scene& scene, Path& path) {
    const size_t end = text.find('\n');
    const std::string_view name = text.substr(5, end == std::string_view::npos ? end : end - 5);
    path = Path::kCount;
    for (int n = 0; n < int(Path::kCount); ++n)
        if (name == kPathNames[n]) path = Path(n);
    scene = defaultScene();
    std::string_view rest = end == std::string_view::npos ? "" : text.substr(end + 1);
    while (!rest.empty()) {
        const size_t stop = rest.find('\n');
        if (!rest.substr(0, stop).empty()) applyOverride(scene, rest.substr(0, stop));
        rest = stop == std::string_view::npos ? std::string_view() : rest.substr(stop + 1);
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const bool text = fuzzText(data, size).starts_with("path=");
    // Text scenes pass their values through toml++, whose known bug (toml_unicode_bug.h) is
    // undefined behaviour, as the scene targets do.
    if (text && hitsTomlUnicodeBug(fuzzText(data, size))) return 0;
    FuzzedDataProvider in(data, text ? 0 : size);  // a text scene leaves nothing random
    try {
        Scene scene;
        Path path = Path::kCount;
        if (text) {
            readTextScene(fuzzText(data, size), scene, path);
        } else {
            scene = randomScene(in);
            path = Path(in.ConsumeIntegralInRange(0, int(Path::kCount) - 1));
        }
        // Triage: QUATERNIA_FUZZ_PRINT=1 prints each input's scene and path (the --set options
        // of the same scene reproduce it with the CLI).
        if (std::getenv("QUATERNIA_FUZZ_PRINT"))
            std::fprintf(stderr, "path %d\n%s", int(path), sceneToToml(scene).c_str());
        validateScene(scene);
        runOrbit(scene);
        switch (path) {
            case Path::kCycles:
                runCycles(in, scene);
                break;
            case Path::kPlane:
                runPlane(in, scene, !text);
                break;
            case Path::kRender:
                runRender(in, scene, !text);
                break;
            case Path::kMesh:
                runMesh(in, scene, !text);
                break;
            case Path::kFilm:
                runFilmFrame(in, scene, !text);
                break;
            case Path::kCount:
                break;
        }
    } catch (const UserError&) {
        return 0;  // a clean refusal, as the CLI's exit 2
    }
    return 0;
}
