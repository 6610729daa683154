// quaternia_derivative_bound_study: how many sphere-tracing steps a tighter derivative would
// spare the general polynomials (issue 42, "programs nearer z^2 + c").
//   quaternia_derivative_bound_study [--width W] [--height H] [FORMULA ...]
// The default scene with each formula (the ten of bench/run.sh's polynomial rows by default)
// is sphere traced by the scalar reference (render/march.h, sphereTrace) through one ray per
// pixel centre, three times, with the escape-time estimate d = 0.5 |z_n| ln|z_n| / rho_n
// (distance.h) and three choices of rho_n, the running derivative:
//  - bound:    rho <- P'(|z|) rho, what both engines carry (P(r) the coefficient-norm products
//              times r^degree; distance.h);
//  - iterate:  rho <- ||Dp(z)|| rho, the exact operator norm of each iterate's Jacobian;
//  - jacobian: rho_n = ||D(p^n)(z_0)||, the exact operator norm of the whole orbit's Jacobian
//              (its four columns carried through the chain rule).
// Each is at most the one before, so each estimate is at least the one before. The last is the
// tightest any rho of this kind can be. It reports, per formula and rho, the steps per ray, the
// polynomial evaluations per ray (the Jacobians' own work not counted), the hits, and how the
// silhouette agrees with Algorithm 2's (fixed steps of render.step, each sample's orbit tested:
// the set the rays meet): the IoU, and the hits with no Algorithm 2 hit within one pixel. Only
// the step counts and the silhouettes mean anything: carrying the Jacobian costs four
// derivative evaluations per iterate, which this scalar loop does not weigh as the lanes would.
// (docs/methods.md, "Distance estimate": why the general polynomials' halo.)
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include "quaternia/fractal/distance.h"
#include "quaternia/fractal/distance_estimate.h"
#include "quaternia/fractal/escape_time.h"
#include "quaternia/fractal/fractal.h"
#include "quaternia/render/camera.h"
#include "quaternia/render/march.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_fractal.h"

namespace {

using namespace quaternia;

enum class Rho { kBound, kIterate, kJacobian };
const char* const kRhoNames[] = {"bound", "iterate", "jacobian"};

// sqrt of the largest eigenvalue of the Gram matrix of four columns: the operator norm of the
// matrix whose columns they are (power iteration; the Gram matrix is symmetric, positive).
double operatorNorm(const std::array<Quaternion, 4>& columns) {
    double gram[4][4];
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            gram[i][j] = dot(columns[i], columns[j]);
    double v[4] = {1, 0.7, 0.5, 0.3}, eigenvalue = 0;
    for (int iteration = 0; iteration < 100; ++iteration) {
        double w[4] = {0, 0, 0, 0};
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
                w[i] += gram[i][j] * v[j];
        double norm = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2] + w[3] * w[3]);
        if (!(norm > 0)) return 0;
        eigenvalue = norm;
        for (int i = 0; i < 4; ++i)
            v[i] = w[i] / norm;
    }
    return std::sqrt(eigenvalue);
}

// The map for estimateWith (escape_time.h) with the columns of a Jacobian carried along: of the
// whole orbit (kJacobian), or of the latest iterate alone, whose norm joins the running product
// (kIterate). gainSquared is 1: rho is applied after the loop.
struct JacobianMap {
    const Polynomial* p;
    Rho rho;
    std::array<Quaternion, 4>* columns;
    double* iterateProduct;
    Quaternion operator()(const Quaternion& z) const {
        if (rho == Rho::kIterate)
            *columns = {Quaternion{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
        for (Quaternion& column : *columns)
            column = p->derivative(z, column);
        if (rho == Rho::kIterate) *iterateProduct *= operatorNorm(*columns);
        return p->evaluate(z);
    }
    double gainSquared(double) const { return 1; }
};

// The scene's set with estimate() taking rho as chosen; everything else is the set's own.
class StudiedSet final : public JuliaSet {
  public:
    StudiedSet(std::shared_ptr<const JuliaSet> inner, Rho rho)
        : inner_(std::move(inner)),
          set_(dynamic_cast<const QuaternionJuliaSet&>(*inner_)),
          rho_(rho) {}

    Algebra algebra() const override { return inner_->algebra(); }
    DistanceKind distanceKind() const override { return inner_->distanceKind(); }
    DistanceEstimate estimate(const Hypercomplex& z0) const override {
        if (rho_ == Rho::kBound) return inner_->estimate(z0);
        const double bailout = set_.bailout(), escape = set_.escapeRadius();
        const int degree = set_.polynomial().degree();
        IterationLimits limits{set_.maxIterations(), bailout * bailout, escape * escape, degree,
                               continuationRadiusSquared<double>(degree)};
        std::array<Quaternion, 4> columns{
            Quaternion{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
        double iterateProduct = 1;
        JacobianMap map{&set_.polynomial(), rho_, &columns, &iterateProduct};
        DistanceEstimate e = estimateWith(map, limits, Quaternion{z0[0], z0[1], z0[2], z0[3]});
        const double rho = rho_ == Rho::kIterate ? iterateProduct : operatorNorm(columns);
        // With gainSquared 1 the loop's distance has rho = 1; both of its forms scale as 1 / rho.
        if (!e.inside) e.distance = rho > 0 ? e.distance / rho : 0;
        return e;
    }
    bool contains(const Hypercomplex& z0) const override { return inner_->contains(z0); }
    double logRadiusAfter(const Hypercomplex& z0, int iterations) const override {
        return inner_->logRadiusAfter(z0, iterations);
    }
    int gradientIterations(const Hypercomplex& z0) const override {
        return inner_->gradientIterations(z0);
    }
    std::array<double, 3> potentialGradient(
        const Hypercomplex& z0, const std::array<Hypercomplex, 3>& tangents) const override {
        return inner_->potentialGradient(z0, tangents);
    }
    const FormulaProgram& program() const override { return inner_->program(); }
    bool hasIntervalExtension() const override { return inner_->hasIntervalExtension(); }
    int maxIterations() const override { return inner_->maxIterations(); }
    double bailout() const override { return inner_->bailout(); }
    double escapeRadius() const override { return inner_->escapeRadius(); }

  private:
    std::shared_ptr<const JuliaSet> inner_;
    const QuaternionJuliaSet& set_;
    Rho rho_;
};

// Which pixel centres' rays meet the set, row by row.
struct Mask {
    int width = 0, height = 0;
    std::vector<char> hit;
    bool at(int x, int y) const {
        return x >= 0 && y >= 0 && x < width && y < height &&
               hit[std::size_t(y) * std::size_t(width) + std::size_t(x)];
    }
};

template <class Trace>
Mask maskOf(const Camera& camera, int width, int height, Trace trace) {
    Mask mask{width, height, std::vector<char>(std::size_t(width) * std::size_t(height))};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            mask.hit[std::size_t(y) * std::size_t(width) + std::size_t(x)] =
                trace(camera.generateRay(x + 0.5, y + 0.5));
    return mask;
}

struct Agreement {
    long hits = 0;
    double iou = 1;
    long farFromReference = 0;  // hits with no reference hit within one pixel (8-neighbours)
};

Agreement agreement(const Mask& traced, const Mask& reference) {
    Agreement a;
    long both = 0, either = 0;
    for (int y = 0; y < traced.height; ++y) {
        for (int x = 0; x < traced.width; ++x) {
            const bool t = traced.at(x, y), r = reference.at(x, y);
            a.hits += t;
            both += t && r;
            either += t || r;
            if (!t) continue;
            bool near = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    near = near || reference.at(x + dx, y + dy);
            a.farFromReference += !near;
        }
    }
    a.iou = either ? double(both) / double(either) : 1.0;
    return a;
}

int run(int argc, char** argv) {
    int width = 320, height = 180;
    std::vector<std::string> formulas;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--width") && i + 1 < argc) {
            width = std::atoi(argv[++i]);
        } else if (!std::strcmp(argv[i], "--height") && i + 1 < argc) {
            height = std::atoi(argv[++i]);
        } else {
            formulas.push_back(argv[i]);
        }
    }
    if (width < 1 || height < 1 || width > 4096 || height > 4096) {
        std::fprintf(stderr,
                     "quaternia_derivative_bound_study: --width and --height in [1, 4096]\n");
        return 2;
    }
    if (formulas.empty()) {  // bench/run.sh's polynomial rows, in order
        formulas = {"z^2 + 0.1*z + c",
                    "i z^2 j + c",
                    "(1+0.2i) z (1-0.1k) z + 0.1j z + c",
                    "z^3 + c",
                    "z^3 + 0.2j z^2 + c",
                    "(1+0.1j) z^3 - 0.3i z + c",
                    "z^4 + c",
                    "z^4 - 0.2 z^2 + 0.1k z + c",
                    "z^5 + c",
                    "z j z^4 + 0.1 z^2 + c"};
    }
    std::printf("%dx%d, one ray per pixel centre, sphere tracing (scalar reference)\n\n", width,
                height);
    std::printf(
        "| formula | rho | steps/ray | evaluations/ray | hits | IoU with Algorithm 2 | "
        "more than a pixel from Algorithm 2's set |\n");
    std::printf("|---|---|---:|---:|---:|---:|---:|\n");
    for (const std::string& formula : formulas) {
        Scene scene = defaultScene();
        setParameter(scene, "fractal.formula", formula);
        setParameter(scene, "render.width", int64_t(width));
        setParameter(scene, "render.height", int64_t(height));
        const Fractal reference = fractalFromScene(scene);
        if (!reference.setAs<QuaternionJuliaSet>()) {
            std::fprintf(stderr, "%s: not a quaternion polynomial\n", formula.c_str());
            return 2;
        }
        const Camera camera(scene.camera, width, height);
        MarchSettings march;
        march.method = MarchMethod::SphereTracing;
        march.step = scene.render.step;
        march.epsilon = scene.render.epsilon;
        march.pixelAngle = camera.pixelFootprint(1.0);
        march.maxSteps = scene.render.maxSteps;
        march.relaxation = scene.render.relaxation;
        // Algorithm 2 (every sample at render.step tested by its orbit): the set each pixel
        // centre's ray meets, which sphere tracing should draw.
        MarchSettings fixedSteps = march;
        fixedSteps.method = MarchMethod::FixedStep;
        fixedSteps.maxSteps = 100000000;
        const Mask algorithm2 = maskOf(camera, width, height, [&](const Ray& ray) {
            return fixedStepMarch(reference, ray, fixedSteps).hit.has_value();
        });
        for (Rho rho : {Rho::kBound, Rho::kIterate, Rho::kJacobian}) {
            const Fractal fractal(std::make_shared<const StudiedSet>(reference.sharedSet(), rho),
                                  reference.slice());
            double steps = 0, iterations = 0;
            const Mask traced = maskOf(camera, width, height, [&](const Ray& ray) {
                const MarchResult r = sphereTrace(fractal, ray, march);
                steps += r.steps;
                iterations += double(r.iterations);
                return r.hit.has_value();
            });
            const double rays = double(width) * double(height);
            const Agreement a = agreement(traced, algorithm2);
            std::printf("| `%s` | %s | %.2f | %.1f | %ld | %.4f | %ld |\n", formula.c_str(),
                        kRhoNames[int(rho)], steps / rays, iterations / rays, a.hits, a.iou,
                        a.farFromReference);
            std::fflush(stdout);
        }
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "quaternia_derivative_bound_study: %s\n", e.what());
        return 1;
    }
}
