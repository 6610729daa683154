// The explorer's query-to-scene layer (explore_request.h): a URL query string, decoded as
// cpp-httplib decodes it (pairs split at '&' and the first '=', %XX and '+' decoded, sorted by
// name as its multimap keeps them), turned into a scene by sceneFromQuery and checked by the
// routes' limits. A UserError is a clean rejection (its JSON answer is made as the server
// would). An accepted scene must be valid, within the explorer's limits, and the CLI command
// the page shows for it must rebuild it.
#include <map>
#include <string>

#include "fuzz/fuzz_check.h"
#include "fuzz/scene_check.h"
#include "fuzz/toml_unicode_bug.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_file.h"
#include "quaternia/util/error.h"
#include "server/explore_request.h"

using namespace quaternia;

namespace {

int hexValue(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

std::string decode(std::string_view text) {
    std::string out;
    for (size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '+') {
            out += ' ';
        } else if (text[i] == '%' && i + 2 < text.size() && hexValue(text[i + 1]) >= 0 &&
                   hexValue(text[i + 2]) >= 0) {
            out += char(hexValue(text[i + 1]) * 16 + hexValue(text[i + 2]));
            i += 2;
        } else {
            out += text[i];
        }
    }
    return out;
}

QueryParameters parseQuery(std::string_view query) {
    std::multimap<std::string, std::string> sorted;
    while (!query.empty()) {
        const size_t end = query.find('&');
        const std::string_view pair = query.substr(0, end);
        const size_t equals = pair.find('=');
        const std::string name = decode(pair.substr(0, equals));
        const std::string value =
            equals == std::string_view::npos ? "" : decode(pair.substr(equals + 1));
        if (!name.empty()) sorted.emplace(name, value);
        query = end == std::string_view::npos ? std::string_view() : query.substr(end + 1);
    }
    return {sorted.begin(), sorted.end()};
}

// The page's CLI command: `--set name=value` for every key that differs from the default.
void checkRenderCommand(const Scene& scene) {
    const std::string command = renderCommandForScene(scene);
    FUZZ_CHECK(command.starts_with("quaternia render") && command.ends_with(" -o quaternia.png"));
    const Scene defaults = defaultScene();
    Scene rebuilt = defaults;
    for (const Parameter& p : parameterTable()) {
        const ParameterValue value = p.read(scene);
        if (p.section == "animation" || value == p.read(defaults)) continue;
        applyOverride(rebuilt, p.name() + "=" + formatValue(value));
    }
    FUZZ_CHECK(sameScene(scene, rebuilt, false));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const Scene base = defaultScene();
    static const ExploreLimits limits;
    const QueryParameters query = parseQuery(fuzzText(data, size));
    for (const auto& [name, value] : query)
        if (hitsTomlUnicodeBug(name) || hitsTomlUnicodeBug(value)) return 0;
    try {
        (void)clientIdFromQuery(query);
    } catch (const UserError& e) {
        FUZZ_CHECK(!errorJson(e.key(), e.what()).empty());
    }
    Scene scene;
    try {
        scene = sceneFromQuery(base, query, limits);
    } catch (const UserError& e) {
        FUZZ_CHECK(!errorJson(e.key(), e.what()).empty());
        return 0;
    }
    checkSceneInRange(scene);
    FUZZ_CHECK(scene.fractal.maxIterations <= limits.maxIterations);
    FUZZ_CHECK(scene.render.maxSteps <= limits.maxSteps);
    FUZZ_CHECK(scene.animation.keys.size() <= limits.maxAnimationKeys);
    for (auto check : {checkInteractiveImage, checkDownloadImage, checkMeshRequest}) {
        try {
            check(scene, limits);
        } catch (const UserError&) {
        }
    }
    checkRenderCommand(scene);
    FUZZ_CHECK(!parameterTableJson(scene).empty());
    return 0;
}
