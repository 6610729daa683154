#include "quaternia/scene/scene_file.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <optional>
#include <tuple>
#include <vector>

#include <toml++/toml.h>

#include "quaternia/scene/animation_file.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/toml_values.h"
#include "quaternia/util/error.h"

namespace quaternia {

namespace {

// [[animation.keys]]: the one entry of a section that is not a parameter (animation_file.h).
constexpr std::string_view kAnimationKeys = "animation.keys";

bool isSection(std::string_view name) {
    const auto& sections = parameterSections();
    return std::find(sections.begin(), sections.end(), name) != sections.end();
}

// One `key = value` of the file: "section.key" (or a bare top-level key) with where it was.
struct Entry {
    toml::source_position where;
    std::string name;
    const toml::node* value;
};

// Every entry, in the order of the file (toml++ keeps tables sorted by key), so that the first
// error reported is the first in the file.
std::vector<Entry> entriesInFileOrder(const toml::table& root) {
    std::vector<Entry> entries;
    for (const auto& [key, node] : root) {
        const auto* section = node.as_table();
        if (section != nullptr && isSection(key.str())) {
            for (const auto& [innerKey, innerNode] : *section)
                entries.push_back({innerKey.source().begin,
                                   std::string(key.str()) + "." + std::string(innerKey.str()),
                                   &innerNode});
        } else {
            entries.push_back({key.source().begin, std::string(key.str()), &node});
        }
    }
    std::stable_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
        return std::tie(a.where.line, a.where.column) < std::tie(b.where.line, b.where.column);
    });
    return entries;
}

void applyEntry(Scene& scene, const Entry& entry, const std::string& sourceName) {
    std::string at = location(sourceName, entry.where);
    if (entry.name == kAnimationKeys) {
        scene.animation.keys =
            parseAnimationKeys(*entry.value, sourceName, scene.animation.interpolation);
        return;
    }
    if (isSection(entry.name))
        throw UserError(entry.name, at + "'" + entry.name + "' must be a section: write [" +
                                        entry.name + "] above its keys");
    const Parameter* p = findParameter(entry.name);
    if (p == nullptr && pastTheLights(entry.name))
        throw UserError(entry.name, at + *pastTheLights(entry.name));
    if (p == nullptr && entry.value->is_table() && entry.name.find('.') == std::string::npos)
        throw UserError(entry.name, at + "unknown section [" + entry.name + "] (did you mean [" +
                                        nearestSectionName(entry.name) + "]?)");
    if (p == nullptr)
        throw UserError(entry.name, at + "unknown key '" + entry.name + "' (did you mean '" +
                                        nearestParameterName(entry.name) + "'?)");
    auto value = toParameterValue(*entry.value, p);
    if (!value)
        throw UserError(p->name(), at + p->name() + " must be " + describeType(*p) + ", got " +
                                       describeNode(*entry.value));
    try {
        p->apply(scene, checkedValue(*p, *value));
    } catch (const UserError& error) {
        throw UserError(error.key(), at + error.what());
    }
}

// One line: toml++ descriptions may in principle span lines.
std::string oneLine(std::string_view text) {
    std::string out(text);
    std::replace(out.begin(), out.end(), '\n', ' ');
    return out;
}

std::string trim(std::string_view text) {
    const char* space = " \t\r\n";
    std::size_t first = text.find_first_not_of(space);
    if (first == std::string_view::npos) return {};
    return std::string(text.substr(first, text.find_last_not_of(space) - first + 1));
}

// `text` read as a single TOML value for `parameter` (may be null), or nothing if it is not one.
std::optional<ParameterValue> parseTomlValue(const std::string& text, const Parameter* parameter) {
    try {
        toml::table table = toml::parse("v = " + text + "\n");
        if (table.size() != 1 || !table.contains("v")) return std::nullopt;
        return toParameterValue(*table.get("v"), parameter);
    } catch (const toml::parse_error&) {
        return std::nullopt;
    }
}

}  // namespace

Scene parseScene(std::string_view tomlText, const std::string& sourceName) {
    toml::table root;
    try {
        root = toml::parse(tomlText, sourceName);
    } catch (const toml::parse_error& error) {
        throw UserError(sourceName,
                        location(sourceName, error.source().begin) + oneLine(error.description()));
    }
    Scene scene = defaultScene();
    for (const Entry& entry : entriesInFileOrder(root))
        applyEntry(scene, entry, sourceName);
    return scene;
}

Scene loadScene(const std::string& path) {
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                         &std::fclose);
    auto fail = [&path] {
        return UserError(path, "cannot read scene file '" + path + "': " + std::strerror(errno));
    };
    if (!file) throw fail();
    std::string text;
    char buffer[1 << 14];
    std::size_t count = 0;
    while ((count = std::fread(buffer, 1, sizeof buffer, file.get())) > 0)
        text.append(buffer, count);
    if (std::ferror(file.get())) throw fail();  // e.g. EISDIR: fopen opens a directory
    return parseScene(text, path);
}

void applyOverride(Scene& scene, std::string_view assignment) {
    std::size_t equals = assignment.find('=');
    if (equals == std::string_view::npos)
        throw UserError("--set",
                        "--set expects section.key=value, got '" + std::string(assignment) + "'");
    std::string name = trim(assignment.substr(0, equals));
    std::string raw = trim(assignment.substr(equals + 1));
    if (name == kAnimationKeys) {
        scene.animation.keys = parseAnimationKeysText(raw, scene.animation.interpolation);
        return;
    }

    ParameterValue value = raw;
    const Parameter* p = findParameter(name);
    if (auto parsed = parseTomlValue(raw, p)) {
        // "--set fractal.formula=2" means the text 2, not a type error.
        bool wantsText =
            p != nullptr && (p->type == ParameterType::Text || p->type == ParameterType::Choice);
        if (!wantsText || std::holds_alternative<std::string>(*parsed)) value = std::move(*parsed);
    }
    setParameter(scene, name, value);
}

std::string sceneToToml(const Scene& scene) {
    std::string out =
        "# Quaternia scene. Every key is optional: one left out keeps the default shown by\n"
        "# `quaternia render --help`.\n";
    std::string section;
    for (const Parameter& p : parameterTable()) {
        if (p.section != section) {
            // The keys close the animation section, as the array of tables they are.
            if (section == "animation") out += animationKeysToToml(scene.animation.keys);
            out += "\n[" + (section = p.section) + "]\n";
        }
        out += "# " + p.help + " (" + describeRange(p) + ")\n";
        out += p.key + " = " + formatParameterValue(p, p.read(scene)) + "\n";
    }
    if (section == "animation") out += animationKeysToToml(scene.animation.keys);
    return out;
}

}  // namespace quaternia
