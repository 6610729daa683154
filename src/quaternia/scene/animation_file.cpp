#include "quaternia/scene/animation_file.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "quaternia/scene/animation.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/toml_values.h"
#include "quaternia/util/error.h"

namespace quaternia {
namespace {

// Reads one key's table; `at` starts every message ("scene.toml:12:1: animation key 3: ").
class KeyReader {
  public:
    KeyReader(std::string at, Interpolation defaultInterpolation)
        : at_(std::move(at)), defaultInterpolation_(defaultInterpolation) {}

    AnimationKey read(const toml::table& table) {
        const toml::node* time = table.get("time");
        if (time == nullptr || (!time->is_integer() && !time->is_floating_point()))
            fail("animation.keys", "needs a time in seconds, e.g. time = 1.5");
        key_.time = time->is_integer() ? double(time->as_integer()->get())
                                       : time->as_floating_point()->get();
        if (!std::isfinite(key_.time)) fail("animation.keys", "time must be a finite number");
        if (const toml::node* interpolation = table.get("interpolation"))
            key_.interpolation = readInterpolation(*interpolation);
        if (const toml::node* shortest = table.get("shortest")) {
            if (!shortest->is_boolean()) fail("animation.keys", "shortest must be true or false");
            key_.shortest = shortest->as_boolean()->get();
        }
        for (const auto& [name, node] : table) {
            std::string key(name.str());
            if (key != "time" && key != "interpolation" && key != "shortest") readValue(key, node);
        }
        // In the table's order, whatever the file's: keys compare and write back alike.
        auto rank = [](const std::pair<std::string, ParameterValue>& entry) {
            return findParameter(entry.first) - parameterTable().data();
        };
        std::sort(key_.values.begin(), key_.values.end(),
                  [&](const auto& a, const auto& b) { return rank(a) < rank(b); });
        for (std::size_t i = 1; i < key_.values.size(); ++i)
            if (key_.values[i].first == key_.values[i - 1].first)
                fail(key_.values[i].first, key_.values[i].first + " is named twice in this key");
        return key_;
    }

  private:
    [[noreturn]] void fail(const std::string& key, const std::string& message) const {
        throw UserError(key, at_ + message);
    }

    Interpolation readInterpolation(const toml::node& node) const {
        if (const auto* text = node.as_string())
            if (auto interpolation = interpolationNamed(text->get())) return *interpolation;
        fail("animation.keys",
             "interpolation must be \"smooth\", \"linear\", \"ease\" or "
             "\"step\", got " +
                 describeNode(node));
    }

    // A parameter by its full name, or a table of them (a dotted key: fractal.c = ...).
    void readValue(const std::string& name, const toml::node& node) {
        if (const auto* inner = node.as_table();
            inner != nullptr && findParameter(name) == nullptr) {
            for (const auto& [innerName, innerNode] : *inner)
                readValue(name + "." + std::string(innerName.str()), innerNode);
            return;
        }
        if (std::string problem = animatableProblem(name); !problem.empty()) fail(name, problem);
        const Parameter& p = *findParameter(name);
        auto value = toParameterValue(node, &p);
        if (!value)
            fail(name, name + " must be " + describeType(p) + ", got " + describeNode(node));
        try {
            key_.values.emplace_back(name, checkedValue(p, *value));
        } catch (const UserError& error) {
            fail(error.key(), error.what());
        }
        bool numeric = p.type != ParameterType::Text && p.type != ParameterType::Choice &&
                       p.type != ParameterType::Boolean;
        if (!numeric && key_.interpolation.value_or(defaultInterpolation_) != Interpolation::Step)
            fail(name, name + " is " + describeType(p) +
                           " and can change only at a key: give this key interpolation = \"step\"");
    }

    std::string at_;
    Interpolation defaultInterpolation_;
    AnimationKey key_;
};

std::string keyBody(const AnimationKey& key, const char* separator) {
    std::string out = "time = " + formatValue(key.time);
    if (key.interpolation)
        out += separator + std::string("interpolation = \"") +
               interpolationName(*key.interpolation) + "\"";
    if (key.shortest) out += separator + std::string("shortest = true");
    for (const auto& [name, value] : key.values)
        out += separator + ("\"" + name + "\" = ") + formatValue(value);
    return out;
}

}  // namespace

std::vector<AnimationKey> parseAnimationKeys(const toml::node& node, const std::string& sourceName,
                                             Interpolation defaultInterpolation) {
    const auto* array = node.as_array();
    if (array == nullptr)
        throw UserError("animation.keys", location(sourceName, node.source().begin) +
                                              "animation.keys must be an array of tables: write "
                                              "each key as [[animation.keys]]");
    std::vector<AnimationKey> keys;
    for (std::size_t i = 0; i < array->size(); ++i) {
        const toml::node& element = *array->get(i);
        std::string at = location(sourceName, element.source().begin) + "animation key " +
                         std::to_string(i + 1) + ": ";
        const auto* table = element.as_table();
        if (table == nullptr)
            throw UserError("animation.keys", at + "must be a table, got " + describeNode(element));
        AnimationKey key = KeyReader(at, defaultInterpolation).read(*table);
        if (key.time < 0)
            throw UserError("animation.keys",
                            at + "time must be >= 0, got " + formatValue(key.time));
        if (!keys.empty() && !(key.time > keys.back().time))
            throw UserError("animation.keys",
                            at +
                                "keys must be in increasing time order with different times: "
                                "time " +
                                formatValue(key.time) + " follows time " +
                                formatValue(keys.back().time));
        if (key.values.empty())
            throw UserError("animation.keys", at + "names no parameter to animate");
        keys.push_back(std::move(key));
    }
    return keys;
}

std::vector<AnimationKey> parseAnimationKeysText(const std::string& text,
                                                 Interpolation defaultInterpolation) {
    toml::table table;
    try {
        table = toml::parse(std::string_view("keys = " + text + "\n"),
                            std::string_view("animation.keys"));
    } catch (const toml::parse_error& error) {
        throw UserError("animation.keys",
                        "animation.keys must be an inline TOML array of key "
                        "tables, e.g. [{time = 0, \"fractal.c\" = [0, 1, 0, 0]}]: " +
                            std::string(error.description()));
    }
    return parseAnimationKeys(*table.get("keys"), "animation.keys", defaultInterpolation);
}

std::string animationKeysToToml(const std::vector<AnimationKey>& keys) {
    std::string out;
    for (const AnimationKey& key : keys)
        out += "\n[[animation.keys]]\n" + keyBody(key, "\n") + "\n";
    return out;
}

std::string animationKeysToInlineToml(const std::vector<AnimationKey>& keys) {
    std::string out = "[";
    for (std::size_t i = 0; i < keys.size(); ++i)
        out += (i ? ", {" : "{") + keyBody(keys[i], ", ") + "}";
    return out + "]";
}

}  // namespace quaternia
