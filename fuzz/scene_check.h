// Invariants of scenes that the scene and explorer fuzz targets share.
#pragma once

#include "fuzz/fuzz_check.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/util/error.h"

namespace quaternia {

// A Scene built only through the table is always in range (parameters.h): every value, read
// back, passes the table's own check, and so does every animation key's.
inline void checkSceneInRange(const Scene& scene) {
    for (const Parameter& p : parameterTable()) {
        try {
            checkedValue(p, p.read(scene));
        } catch (const UserError& e) {
            std::fprintf(stderr, "out of range after parsing: %s\n", e.what());
            FUZZ_CHECK(false);
        }
    }
    for (const AnimationKey& key : scene.animation.keys) {
        FUZZ_CHECK(std::isfinite(key.time));
        for (const auto& [name, value] : key.values) {
            const Parameter* p = findParameter(name);
            FUZZ_CHECK(p != nullptr);
            try {
                FUZZ_CHECK(checkedValue(*p, value) == value);
            } catch (const UserError& e) {
                std::fprintf(stderr, "animation key out of range: %s\n", e.what());
                FUZZ_CHECK(false);
            }
        }
    }
}

inline bool sameKeys(const std::vector<AnimationKey>& a, const std::vector<AnimationKey>& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i) {
        if (a[i].time != b[i].time || a[i].interpolation != b[i].interpolation ||
            a[i].shortest != b[i].shortest || a[i].values != b[i].values)
            return false;
    }
    return true;
}

// Whether every table value of the two scenes is equal (and the animation keys, if asked).
inline bool sameScene(const Scene& a, const Scene& b, bool withAnimation) {
    for (const Parameter& p : parameterTable()) {
        if (!withAnimation && p.section == "animation") continue;
        if (p.read(a) != p.read(b)) {
            std::fprintf(stderr, "%s differs: %s against %s\n", p.name().c_str(),
                         formatValue(p.read(a)).c_str(), formatValue(p.read(b)).c_str());
            return false;
        }
    }
    return !withAnimation || sameKeys(a.animation.keys, b.animation.keys);
}

}  // namespace quaternia
