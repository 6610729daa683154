// Scene files and --set overrides (scene_file.h), then validation, as the CLI applies them
// (sceneFromOptions, then validateScene). The input is a TOML scene file, optionally followed
// by a line "---" and one --set assignment per line. A UserError is a clean rejection; any other
// exception, a crash or a scene that breaks the table's ranges is a bug, as is a valid scene
// that sceneToToml does not write back exactly (scene_file.h promises it does).
#include <cmath>
#include <string>

#include "fuzz/fuzz_check.h"
#include "fuzz/scene_check.h"
#include "fuzz/toml_unicode_bug.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/scene_file.h"
#include "quaternia/util/error.h"

using namespace quaternia;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view input = fuzzText(data, size);
    if (hitsTomlUnicodeBug(input)) return 0;
    const size_t separator = input.find("\n---\n");
    const std::string_view toml = input.substr(0, separator);
    Scene scene;
    try {
        scene = parseScene(toml, "fuzz.toml");
        if (separator != std::string_view::npos) {
            std::string_view rest = input.substr(separator + 5);
            while (!rest.empty()) {
                const size_t end = rest.find('\n');
                applyOverride(scene, rest.substr(0, end));
                rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
            }
        }
    } catch (const UserError&) {
        return 0;
    }
    checkSceneInRange(scene);
    try {
        validateScene(scene);
    } catch (const UserError&) {
        return 0;
    }
    const std::string text = sceneToToml(scene);
    Scene back;
    try {
        back = parseScene(text, "written.toml");
    } catch (const UserError& e) {
        std::fprintf(stderr, "sceneToToml's text does not read back: %s\n%s\n", e.what(),
                     text.c_str());
        FUZZ_CHECK(false);
    }
    FUZZ_CHECK(sameScene(scene, back, true));
    return 0;
}
