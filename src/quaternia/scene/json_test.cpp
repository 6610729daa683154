// The JSON the commands and the explorer write: doubles that read back exactly, null for NaN and
// infinities, quaternions and complex numbers as arrays, and text that is not UTF-8 still written.
#include "quaternia/scene/json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace quaternia {
namespace {

TEST(Json, DoublesReadBackExactly) {
    for (double value : {-0.12256116687665, 0.74486176661974, 0.0123456789012345, 0.1, 1e-300,
                         std::nextafter(1.0, 2.0), std::numeric_limits<double>::max()}) {
        std::string text = jsonText(Json(value));
        EXPECT_EQ(Json::parse(text).get<double>(), value) << text;
    }
    EXPECT_EQ(jsonText(Json(0.1)), "0.1");  // the shortest form, not 17 digits
}

TEST(Json, NonFiniteNumbersAreNull) {
    Json json;
    json["nan"] = std::nan("");
    json["inf"] = std::numeric_limits<double>::infinity();
    json["-inf"] = -std::numeric_limits<double>::infinity();
    EXPECT_EQ(jsonText(json), R"({"nan":null,"inf":null,"-inf":null})");
}

TEST(Json, QuaternionsAndComplexNumbersAreArrays) {
    Json json;
    json["q"] = Quaternion{-0.12256116687665, 0.74486176661974, 0.0123456789012345, -0.3};
    json["z"] = std::complex<double>(1.5, -2);
    EXPECT_EQ(jsonText(json),
              R"({"q":[-0.12256116687665,0.74486176661974,0.0123456789012345,-0.3],)"
              R"("z":[1.5,-2.0]})");
}

TEST(Json, TextThatIsNotUtf8IsReplacedNotThrown) {
    Json json = std::string("a\xff\"\n");
    EXPECT_EQ(jsonText(json), "\"a\xef\xbf\xbd\\\"\\n\"");  // U+FFFD, then the escapes
}

}  // namespace
}  // namespace quaternia
