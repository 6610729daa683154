#include "server/explore_film.h"

#include <algorithm>
#include <charconv>
#include <variant>
#include <vector>

#include "quaternia/scene/animation.h"
#include "quaternia/scene/json.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

// Every parameter the keys name, in the order first named.
std::vector<std::string> keyedNames(const AnimationSettings& animation) {
    std::vector<std::string> names;
    for (const AnimationKey& key : animation.keys)
        for (const auto& [name, value] : key.values)
            if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    return names;
}

}  // namespace

int64_t takeFrameNumber(QueryParameters& query) {
    auto found = std::find_if(query.begin(), query.end(),
                              [](const auto& entry) { return entry.first == kFrameParameter; });
    if (found == query.end())
        throw UserError(kFrameParameter, "frame is missing: the frame number, from 1");
    const std::string text = found->second;
    query.erase(found);
    int64_t frame = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), frame);
    if (error != std::errc() || end != text.data() + text.size() || frame < 1)
        throw UserError(kFrameParameter, "frame must be a whole number from 1, got '" + text + "'");
    return frame;
}

Scene filmFrame(const Scene& film, int64_t frame, const ExploreLimits& limits) {
    validateAnimation(film);
    int64_t count = filmFrameCount(film);
    if (frame > count) {
        throw UserError(kFrameParameter, "frame " + std::to_string(frame) +
                                             " is past the film's last, " + std::to_string(count));
    }
    Scene scene = sceneAtFrame(film, frame);
    checkSceneCost(scene, limits);
    checkInteractiveImage(scene, limits);
    return scene;
}

std::string filmJson(const Scene& film) {
    Json json;
    json["frames"] = 0;
    json["fps"] = film.animation.fps;
    json["seconds"] = 0.0;
    json["keys"] = Json::array();
    if (!isAnimated(film)) return jsonText(json) + "\n";
    validateAnimation(film);
    int64_t frames = filmFrameCount(film);
    json["frames"] = frames;
    json["seconds"] = double(frames) / film.animation.fps;
    // The keys' own motion only: the shortcuts add theirs over the whole film, not at keys.
    Scene keysOnly = film;
    keysOnly.animation.turnPlane = RotationPlane::None;
    keysOnly.animation.orbitTurns = 0;
    keysOnly.animation.cRadius = 0;
    const std::vector<std::string> names = keyedNames(film.animation);
    for (const AnimationKey& key : film.animation.keys) {
        Scene at = sceneAtTime(keysOnly, key.time);
        Json entry;
        entry["time"] = key.time;
        entry["interpolation"] =
            key.interpolation ? Json(interpolationName(*key.interpolation)) : Json(nullptr);
        entry["shortest"] = key.shortest;
        entry["values"] = Json::object();
        for (const std::string& name : names) {
            ParameterValue value = findParameter(name)->read(at);
            entry["values"][name] = std::visit([](const auto& x) { return Json(x); }, value);
        }
        json["keys"].push_back(std::move(entry));
    }
    return jsonText(json) + "\n";
}

}  // namespace quaternia
