// The scene around the set, one for both engines: paths of rays that reflect off the set and the
// ground, refract into the set and out of it, and see the ground, the background, the fog and the
// glow, followed wave by wave (breadth first). What becomes of a ray at a surface (the
// materials: Schlick's and the dielectric's reflectance, Snell's refraction, Beer-Lambert
// absorption, glossy lobes, fog, the glow's layer, the shadow catcher, where a path ends) is
// decided here, once; each wave's rays are marched and its surfaces lit by an engine
// (WaveEngine): the SIMD lanes (lane_tile_renderer.h) or the double-precision reference
// (scalar_waves.h). So the two engines draw the same scene by construction and differ only in
// how a batch is computed.
//
// The rays outside the set are marched as camera rays are; the rays inside march by fixed steps
// (no distance estimate bounds a step inside the set, docs/rendering.md) and find where they
// leave it by bisection.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "quaternia/render/adaptive_driver.h"
#include "quaternia/render/adaptive_sampling.h"
#include "quaternia/render/camera.h"
#include "quaternia/render/camera_rays.h"
#include "quaternia/render/lanes/march_lanes.h"
#include "quaternia/render/shade.h"
#include "quaternia/util/parallel.h"

namespace quaternia {

// A point of the ground to light: where, the direction of the ray that met it, and the cone
// block of a camera ray's pixel (-1 for other rays).
struct GroundPoint {
    Point3d x;
    Vector3d direction;
    int block;
    // The side of the plane the ray came from.
    Vector3d normal() const { return Vector3d(0, direction.y < 0 ? 1 : -1, 0); }
};

// A ray of a batch that ended on the set: whose ray it was (the caller's index: a pixel of the
// tile, or a path), the cone block of its pixel (-1 where none), the length of the whole path to
// it (its footprint's), its unit direction, and the last point known outside the set (where the
// potential is defined and normals are taken).
struct WaveHit {
    int owner, block;
    double t;
    Vector3d direction;
    Point3d outside;
};

// The batches a wave of paths needs, computed by one engine. Each call answers for every ray or
// point of its batch, in order.
class WaveEngine {
  public:
    virtual ~WaveEngine() = default;
    // How the hits of a wave are shaded: those of the camera rays (firstWave) or of later rays
    // (lit without ambient occlusion: a reflection's creases cost as much as the camera's and
    // show far less); `lit` false where the surface shows none of its own light (a mirror,
    // clear glass: normals only, colours black); `traps` where the orbit traps are wanted.
    struct HitShading {
        bool firstWave = true;
        bool lit = true;
        bool traps = false;
    };
    // The rays marched from their tNear to their tFar (their origins may lie behind where their
    // path has come to, so that the marching tolerance is the camera's footprint there), each
    // ray's end into `traced`; `closest` records each ray's least estimate (the glow).
    virtual void marchWave(const RayBatch& rays, bool closest,
                           std::vector<TraceResult>& traced) = 0;
    // The hits' unit normals, facing the rays, and what they asked for: normals(), colour(h),
    // trap(h) are the answers until the next call.
    virtual void shadeWave(const std::vector<WaveHit>& hits, const HitShading& how) = 0;
    virtual const std::vector<Vector3d>& normals() const = 0;
    virtual Color colour(size_t hit) const = 0;
    virtual double trap(size_t hit) const = 0;
    // At each point, whether it lies outside the set: a distance > 0 there, 0 inside.
    virtual void outsideDistances(const PointBatch& points, std::vector<double>& distances) = 0;
    // The unit outward normal of the set at each point (just outside it).
    virtual void outwardNormals(const PointBatch& points, std::vector<Vector3d>& normals) = 0;
    // The ground's own light at the points (every light, with shadows), and the key light's
    // visibility (1 where the key light is behind the plane: no shadow to catch there).
    // firstWave: the points of camera rays.
    virtual void lightGround(const std::vector<GroundPoint>& points, bool firstWave) = 0;
    virtual const std::vector<Color>& groundColour() const = 0;
    virtual const std::vector<double>& groundKeyVisibility() const = 0;
};

class PathWaves {
  public:
    // The frame: its shader, camera and set's bounding radius, the set's material and the
    // ground.
    void bind(const Shader& shader, const Camera& camera, double boundingRadius,
              const MaterialSettings& material, const GroundSettings& ground);
    // Whether the pixels also sum their hits' normals and orbit traps (RenderOptions::passes).
    void setPasses(bool passes) { passes_ = passes; }
    // Whether the frame has anything about the set (reflection, refraction, the ground, the
    // glow): otherwise camera rays that hit the set end there, and no paths are needed.
    bool active() const { return active_; }
    static bool neededFor(const MaterialSettings& material, const GroundSettings& ground,
                          double glowIntensity) {
        return material.reflectivity > 0 || material.transparency > 0 || ground.enabled ||
               glowIntensity > 0;
    }
    // Whether camera rays that skip the set (their cone or the bounding sphere missed) still
    // count: the ground or the glow may see them (CameraRayBatch::bypass).
    bool bypassing() const { return bypassing_; }
    const GroundSettings& ground() const { return ground_; }
    // Whether camera rays that see only a ground that reflects nothing end there without the
    // waves (shadeCameraGround), which changes no pixel; false only to check that.
    void setGroundShortcut(bool shortcut) { groundShortcut_ = shortcut; }

    // Traces the camera rays of `camera` (each for pixel camera.pixel[i] of `tile`, its sums
    // pixels[pixel]; the rays' tNear where their march may start) and every path they start,
    // and adds each camera sample to its pixel: its colour, alpha, depth (and passes).
    // sampleKey: the sample index of every ray (uniform sampling's pass), or -1 for each
    // pixel's count of samples so far; it seeds the glossy directions. `tracking`, where given,
    // receives each sample's deviation (adaptive sampling). The camera batch's vectors are used
    // as scratch: the caller clears them before the next batch.
    void trace(WaveEngine& engine, const Tile& tile, int sampleKey, const CameraRayBatch& camera,
               std::vector<PixelSamples>& pixels, const DeviationTracking* tracking);

  private:
    // A ray of a path: where it goes, which camera sample it serves (samples_ index) and with
    // what weight, how far the path has come, and how many bounces it took.
    struct PathRay {
        Ray ray;
        double tNear = 0;  // camera rays: their cone's start
        int sample = 0;
        Color weight;
        double travelled = 0;
        int depth = 0;
        bool camera = false;
        int block = -1;
        // The blur of the environment it sees, in radians (a glossy reflection's, Shader::
        // background).
        double spread = 0;
    };
    // A camera sample's result: colour (premultiplied) and alpha, its first hit (depth,
    // normal, trap) and what it hit.
    struct SampleResult {
        int pixel = 0;
        Color color;
        double alpha = 0, depth = 0, trap = 0;
        Vector3d normal;
        uint8_t object = 0;  // 0 nothing, 1 the set, 2 the ground
        int key = 0;         // the pixel's sample index, for glossy directions
        double glow = 0;     // the glow's opacity in front of it
    };
    // Where a ray meets the ground: outside_[path] (groundHits_) or bypass[path]
    // (cameraGround_), at t along it.
    struct GroundHit {
        size_t path;
        double t;
    };

    // One wave of rays outside the set: marched, then shaded where they hit the set or the
    // ground, their children queued. cameraBatch: the first wave, its camera rays still in
    // rays_ as the camera batch left them (without the glow, which marches them from farther
    // out).
    void traceOutsideWave(bool firstWave, bool cameraBatch);
    // The first wave's batch: rays_ kept, cut at the ground (those it hides the set from into
    // groundHits_), marchedPaths_ set; returns how many paths of outside_ it took.
    size_t keepCameraBatch();
    // The rays of traced_ that ended on the set, into hits_.
    void collectHits();
    // The hits_ of an outside wave, shaded by the engine, into their samples, and their
    // reflected and refracted rays queued.
    void shadeSetHits();
    // A hit's glossy reflection: the mirror direction moved by a point of the ball of radius
    // roughness, one per pixel sample.
    Vector3d glossy(const Vector3d& mirror, const Vector3d& n, const SampleResult& sample,
                    int depth) const;
    // One wave of refracted rays inside the set: fixed steps to where they leave it.
    void traceInsideWave();
    // What a ray that hits neither the set nor (usable) ground sees: the background.
    void seeBackground(const PathRay& path);
    // weight times the background along `ray` added to sample `sample`: at once, or, where the
    // environment is seen, at the end of the batch with the others (addEscapes: the map read
    // for many rays together, Environment::radianceBatch).
    void addBackground(int sample, const Color& weight, const Ray& ray, double spread);
    void addEscapes();
    // Queues a child ray of `parent` (or, past the depth or below the weight worth a ray, adds
    // the background along it to its sample).
    void spawn(const PathRay& parent, const Ray& ray, const Color& weight, double travelled,
               bool inside, double spread = 0);
    // The ground: where ray meets the plane (infinity where not ahead).
    double groundDistance(const Ray& ray) const;
    // The ground hits of a wave (groundHits_), into their samples, their reflections queued.
    void shadeGround(bool firstWave);
    // The camera rays of cameraGround_, which see the ground and nothing else, into pixels.
    void shadeCameraGround(const std::vector<BypassRay>& bypass, std::vector<PixelSamples>& pixels);
    // A sample's result added to its pixel's sums (and, while tracking_, its deviation).
    void addSample(std::vector<PixelSamples>& pixels, const SampleResult& sample);
    int blockOfPixel(int pixel) const;  // the cone block of pixel (of tile_)

    const Shader* shader_ = nullptr;
    const Camera* camera_ = nullptr;
    double boundingRadius_ = 0;
    MaterialSettings material_;
    GroundSettings ground_;
    bool passes_ = false;
    bool active_ = false;
    bool bypassing_ = false;
    bool groundShortcut_ = true;

    // The batch being traced.
    WaveEngine* engine_ = nullptr;
    Tile tile_{};
    int sampleKey_ = -1;
    const DeviationTracking* tracking_ = nullptr;

    std::vector<SampleResult> sampleResults_;
    std::vector<PathRay> outside_, inside_, nextOutside_, nextInside_;
    // An outside wave's batch: the rays, each one's path (index in outside_) and cone block.
    RayBatch rays_;
    std::vector<int> rayPath_, rayBlock_;
    std::vector<TraceResult> traced_;
    std::vector<WaveHit> hits_;
    std::vector<GroundHit> groundHits_, cameraGround_;
    std::vector<GroundPoint> groundPoints_;
    std::vector<uint8_t> groundHidden_;
    std::vector<size_t> marchedPaths_;
    // Inside waves: per path, the bracket of the exit, the bisection's points.
    PointBatch insidePoints_;
    std::vector<std::array<double, 2>> insideBracket_;
    std::vector<double> insideFar_, insideDistances_;
    std::vector<size_t> insideActive_;
    std::vector<Vector3d> exitNormals_;
    // The rays that left the scene, their backgrounds to add (addBackground).
    struct Escape {
        int sample;
        Color weight;
    };
    std::vector<Escape> escapes_;
    std::vector<Vector3d> escapeDirections_;
    std::vector<double> escapeSpreads_;
    std::vector<Color> escapeRadiance_;
};

}  // namespace quaternia
