// What the explorer's HTTP API shares between its routes: the scene a request asks for (its
// query parameters are scene keys, validated by the one parameter table), the limits that keep
// hostile requests cheap, and the texts the page copies (scene file, CLI command).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "quaternia/scene/scene.h"

namespace quaternia {

// Bounds on what one request may cost, beyond the parameter table's own ranges.
struct ExploreLimits {
    int64_t interactivePixels = 1920 * 1080;   // /api/render width x height
    int64_t downloadSide = 4096;               // /api/download width and height each
    int64_t downloadRays = 4096LL * 4096 * 4;  // width x height x samples of a download
    int64_t interactiveSamples = 16;
    int64_t maxIterations = 2000;  // fractal.max_iterations
    int64_t maxSteps = 100000;     // render.max_steps
    int64_t meshResolution = 256;  // mesh.resolution of /api/mesh
    int64_t planePixels = 1024 * 1024;
    std::size_t maxParameters = 64;  // query parameters per request
    // Keys of animation.keys. Their text is bounded besides by the request line, which
    // cpp-httplib limits to 8 KiB (CPPHTTPLIB_REQUEST_URI_MAX_LENGTH, 414 beyond).
    std::size_t maxAnimationKeys = 64;
};

// The query parameters of a request in order: (name, value), names and values URL-decoded.
using QueryParameters = std::vector<std::pair<std::string, std::string>>;

// Query parameters that are not scene keys.
inline constexpr const char* kClientParameter = "client";
// /api/render and /api/download: "true" tints the pixels that the picture's certificate
// (render/pixel_certificate.h) leaves undecided; "false" (or none) does not.
inline constexpr const char* kCertifyParameter = "certify";

// `base` (the default scene, or the scene file the server started with) with every query
// parameter applied as `--set name=value` (TOML value syntax; a bare word is a string), then
// validated. Throws UserError naming the key for an unknown key, a repeated one, a bad value or
// a cross-field problem; "client" and "certify" are skipped. animation.keys (the inline TOML array
// of --set) is read, at most limits.maxAnimationKeys of them.
Scene sceneFromQuery(const Scene& base, const QueryParameters& query, const ExploreLimits& limits);

// validateScene, then the explorer's bounds on iterations and steps, then the formula; each
// throws UserError naming the key. sceneFromQuery's checks, for scenes made otherwise (a frame).
void checkSceneCost(const Scene& scene, const ExploreLimits& limits);

// What each route allows on top of sceneFromQuery; each throws UserError naming the key.
void checkInteractiveImage(const Scene& scene, const ExploreLimits& limits);
void checkDownloadImage(const Scene& scene, const ExploreLimits& limits);
void checkMeshRequest(const Scene& scene, const ExploreLimits& limits);

// The client id of a request: letters, digits, '-' and '_', 1 to 64 characters; "" when the
// request names none. Throws UserError("client", ...) for anything else.
std::string clientIdFromQuery(const QueryParameters& query);

// Whether the request asks for the certificate's tint: certify=true or certify=false (also 1
// and 0), false when it names none. Throws UserError("certify", ...) for anything else.
bool certifyFromQuery(const QueryParameters& query);

// `quaternia render --set 'key=value' ... -o quaternia.png`: every key whose value differs from
// the default, each value in exact TOML syntax, so that the command renders the same picture.
// [animation] is left out: it does not change a still.
std::string renderCommandForScene(const Scene& scene);

// The parameter table as JSON: [{"name", "section", "key", "type", "default", "value",
// "minimum", "maximum", "choices", "allowed", "help"}, ...], where "value" is `base`'s.
std::string parameterTableJson(const Scene& base);

// The presets (presets.h) as JSON: [{"name", "description", "values": {"section.key": value}}],
// in display order, each value as in parameterTableJson.
std::string presetsJson();

// {"error": message, "key": key}
std::string errorJson(const std::string& key, const std::string& message);

}  // namespace quaternia
