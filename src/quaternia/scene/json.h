// JSON for the commands' summaries and the explorer's answers: nlohmann::ordered_json (keys in
// the order written), whose dump() writes each double in the shortest form that reads back
// exactly and NaN and infinities as null, which JSON lacks. Quaternions convert to [w, x, y, z]
// and complex numbers to [re, im].
#pragma once

#include <complex>
#include <string>

#include <nlohmann/json.hpp>

#include "quaternia/algebra/quaternion.h"

namespace quaternia {

using Json = nlohmann::ordered_json;

// One line of JSON. Strings come from users (paths, formulas, query keys) and need not be UTF-8:
// invalid bytes become U+FFFD instead of dump()'s exception.
inline std::string jsonText(const Json& json) {
    return json.dump(-1, ' ', false, Json::error_handler_t::replace);
}

// Found by argument-dependent lookup when a Quaternion is assigned to a Json.
template <typename BasicJson>
void to_json(BasicJson& json, const Quaternion& q) {
    json = BasicJson::array({q.w, q.x, q.y, q.z});
}

}  // namespace quaternia

// std::complex lives in std, where a to_json of ours may not go: nlohmann's serializer hook.
NLOHMANN_JSON_NAMESPACE_BEGIN
template <typename T>
struct adl_serializer<std::complex<T>> {
    template <typename BasicJson>
    static void to_json(BasicJson& out, const std::complex<T>& z) {
        out = BasicJson::array({z.real(), z.imag()});
    }
};
NLOHMANN_JSON_NAMESPACE_END
