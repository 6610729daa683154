// quaternia.Scene: a scene as a mapping from the parameter table's keys to their values, every
// value set through the table's validation (parameters.h), as scene files and --set are.
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "python/python_module.h"
#include "quaternia/scene/animation.h"
#include "quaternia/scene/presets.h"
#include "quaternia/scene/scene_file.h"
#include "quaternia/util/error.h"

namespace quaternia::python {
namespace {

std::vector<std::string> keysOf() {
    std::vector<std::string> keys;
    for (const Parameter& parameter : parameterTable())
        keys.push_back(parameter.name());
    return keys;
}

Scene sceneFromFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) raiseOSError("cannot read scene file '" + path + "': " + std::strerror(errno));
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) raiseOSError("cannot read scene file '" + path + "': " + std::strerror(errno));
    return parseScene(text.str(), path);
}

}  // namespace

void bindScene(py::module_& module) {
    py::class_<Scene>(module, "Scene", R"(A scene: every key of Quaternia's parameter table.

Scene() is the default scene (what `quaternia render` draws without a scene file).
Keys are "section.key" strings, as in scene files and --set:

    scene = quaternia.Scene.preset("rabbit")
    scene["fractal.c"] = [-0.2, 0.6, 0.2, 0.2]
    scene["render.width"] = 640

Every value is checked as a scene file's is: a bad value raises ValueError naming the key,
an unknown key UnknownKeyError (a KeyError and a ValueError) with the nearest valid name.)")
        .def(py::init(&defaultScene), "The default scene.")
        .def_static("from_file", &sceneFromFile, py::arg("path"),
                    "The scene file at `path` (TOML) over the defaults. OSError if it cannot be "
                    "read, ValueError (with file, line and key) for a bad key or value.")
        .def_static(
            "from_toml", [](const std::string& text) { return parseScene(text, "scene"); },
            py::arg("text"), "A scene from the text of a scene file (TOML) over the defaults.")
        .def_static(
            "preset",
            [](const std::string& name) {
                Scene scene = defaultScene();
                applyPreset(scene, name);
                return scene;
            },
            py::arg("name"),
            ("The default scene with the preset `name` applied, one of: " + presetNames()).c_str())
        .def(
            "apply_preset", [](Scene& scene, const std::string& name) { applyPreset(scene, name); },
            py::arg("name"), "Sets the keys of the preset `name` (the others stay).")
        .def(
            "__getitem__",
            [](const Scene& scene, const std::string& key) {
                const Parameter& parameter = parameterNamed(key);
                return pythonValueOf(parameter, parameter.read(scene));
            },
            py::arg("key"), "The value of `key` (\"section.key\").")
        .def(
            "__setitem__",
            [](Scene& scene, const std::string& key, py::handle value) {
                const Parameter& parameter = parameterNamed(key);
                setParameter(scene, key, parameterValueOf(parameter, value));
            },
            py::arg("key"), py::arg("value"),
            "Sets `key` after checking `value` against the table (type, range, choices).")
        .def("__contains__",
             [](const Scene&, const std::string& key) { return findParameter(key) != nullptr; })
        .def("__iter__", [](const Scene&) { return py::iter(py::cast(keysOf())); })
        .def("__len__", [](const Scene&) { return parameterTable().size(); })
        .def(
            "keys", [](const Scene&) { return keysOf(); },
            "Every key, in the table's order (fractal, slice, camera, render, ...).")
        .def(
            "help",
            [](const Scene&, const std::string& key) {
                const Parameter& parameter = parameterNamed(key);
                return parameter.help + " (" + describeType(parameter) + ", " +
                       describeRange(parameter) + ", default " +
                       formatParameterValue(parameter, parameter.defaultValue) + ")";
            },
            py::arg("key"), "One line on `key`: what it does, its type, range and default.")
        .def("to_toml", &sceneToToml,
             "The scene as a scene file: every key, with its help as a comment. "
             "Scene.from_toml(scene.to_toml()) gives the same scene.")
        .def(
            "copy", [](const Scene& scene) { return Scene(scene); }, "An independent copy.")
        .def("__copy__", [](const Scene& scene) { return Scene(scene); })
        .def("__deepcopy__", [](const Scene& scene, py::dict) { return Scene(scene); })
        .def(
            "__eq__",
            [](const Scene& a, const Scene& b) { return sceneToToml(a) == sceneToToml(b); },
            py::is_operator())  // another type: NotImplemented, so `scene == 3` is False
        .def("validate", &validateScene,
             "Checks the conditions between keys (as render does before any work); "
             "ValueError naming the key to change.")
        .def(
            "frame_count", [](const Scene& scene) { return filmFrameCount(scene); },
            "The number of frames of the scene's film ([animation]); ValueError if it has none.")
        .def("__repr__", [](const Scene& scene) {
            return "<quaternia.Scene " + formatValue(ParameterValue(scene.fractal.formula)) +
                   " c=" +
                   formatParameterValue(*findParameter("fractal.c"),
                                        findParameter("fractal.c")->read(scene)) +
                   ">";
        });
    module.def(
        "presets",
        [] {
            std::vector<std::pair<std::string, std::string>> list;
            for (const Preset& preset : scenePresets())
                list.emplace_back(preset.name, preset.description);
            return list;
        },
        "The presets as (name, description) pairs.");
    module.def(
        "frame",
        [](const Scene& film, int64_t n) {
            const int64_t frames = filmFrameCount(film);
            if (n < 1 || n > frames)
                throw UserError("frame", "frame " + std::to_string(n) + " is outside the film's " +
                                             std::to_string(frames) + " frames (1 to " +
                                             std::to_string(frames) + ")");
            return sceneAtFrame(film, n);
        },
        py::arg("scene"), py::arg("n"),
        "The scene of frame n (1 to scene.frame_count()) of the scene's film: its [animation] "
        "keys and shortcuts applied at that frame's time, the animation itself removed, so that "
        "render(frame(scene, n)) is frame n of `quaternia animate`.");
}

}  // namespace quaternia::python
