// Scene files and command-line overrides, in TOML, driven by the parameter table
// (parameters.h): one [section] per table section, one `key = value` per parameter, e.g.
//
//   [fractal]
//   formula = "z^3 + c"
//   c = [-0.2, 0.6, 0.2, 0.2]
//   [render]
//   width = 640
//
// Keys left out keep their defaults. slice.axes may also be written as three arrays of 8 (or 4)
// numbers, [[a0 .. a7], [b0 .. b7], [c0 .. c7]], here and in --set; sceneToToml writes it so.
// Every error is a UserError that names the file, line and column and the key, and for an
// unknown section or key suggests the nearest valid one.
#pragma once

#include <string>
#include <string_view>

#include "quaternia/scene/scene.h"

namespace quaternia {

// defaultScene() with every key of `tomlText` applied; `sourceName` (usually the path) starts
// each message: "scene.toml:3:7: render.width = 0 is out of range [1, 16384]". Numbers in
// arrays may mix integers and floats; an integer is accepted for a real. A TOML syntax error
// throws UserError(sourceName, ...), a bad key or value UserError("section.key", ...).
// Does not call validateScene, so that overrides can still fix a cross-field problem.
Scene parseScene(std::string_view tomlText, const std::string& sourceName = "scene");

// Reads `path` and parses it; UserError(path, "cannot read scene file '<path>': <reason>") if
// the file cannot be read.
Scene loadScene(const std::string& path);

// Applies one "section.key=value" from the command line (--set). The value is read as TOML
// ("640", "[0, 1, 0, 0]", "\"z^3 + c\""); if it is not valid TOML, or it is not a string where
// the parameter wants text or a choice, the trimmed raw text is taken as a string, so that
// `--set fractal.formula=z^3+c` and `--set render.method=fixed-step` work unquoted.
// Throws UserError("--set", ...) without '=', and setParameter's UserErrors otherwise.
void applyOverride(Scene& scene, std::string_view assignment);

// Every parameter, grouped by [section] in table order, each preceded by its help and allowed
// values as a comment. Reals are written with full precision, so parseScene(sceneToToml(s))
// reproduces s exactly.
std::string sceneToToml(const Scene& scene);

}  // namespace quaternia
