// The explorer's timeline routes: keys in a query come back in /api/scene, each frame of
// /api/frame is the library's render of sceneAtFrame byte for byte, /api/film tells the frame
// count, and bad keys or frames are 400 naming the key.
#include <cstdio>

#include "quaternia/image/png_io.h"
#include "quaternia/render/render.h"
#include "quaternia/scene/animation.h"
#include "quaternia/scene/json.h"
#include "quaternia/scene/scene_file.h"
#include "server/explore_test_client.h"

namespace quaternia::testing {
namespace {

class ExploreFilm : public ExploreServerFixture {};

// Every byte but letters and digits as %XX, as a query value.
std::string urlEncode(const std::string& text) {
    std::string out;
    for (unsigned char ch : text) {
        bool plain =
            (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9');
        if (plain) {
            out += char(ch);
        } else {
            char hex[4];
            std::snprintf(hex, sizeof hex, "%%%02X", ch);
            out += hex;
        }
    }
    return out;
}

// Two keys one second apart that move c; the second eases.
const std::string kKeys =
    "[{time = 0, \"fractal.c\" = [-0.2, 0.8, 0, 0]}, "
    "{time = 1, interpolation = \"ease\", \"fractal.c\" = [-0.5, 0.5, 0.1, 0]}]";

std::string keysQuery(const std::string& keys = kKeys) {
    return "animation.fps=8&animation.keys=" + urlEncode(keys);
}

void expectBadKey(const httplib::Result& result, const std::string& key) {
    ASSERT_TRUE(result) << "no answer";
    EXPECT_EQ(result->status, 400) << result->body;
    Json body = Json::parse(result->body);
    EXPECT_EQ(body["key"], key) << result->body;
}

TEST_F(ExploreFilm, KeysComeBackInTheSceneFile) {
    startServer(options());
    auto r = get("/api/scene?" + keysQuery());
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200) << r->body;
    EXPECT_NE(r->body.find("[animation]\n"), std::string::npos);
    EXPECT_NE(r->body.find("[[animation.keys]]"), std::string::npos) << r->body;
    Scene scene = parseScene(r->body);
    EXPECT_EQ(scene.animation.fps, 8);
    ASSERT_EQ(scene.animation.keys.size(), 2u);
    EXPECT_EQ(scene.animation.keys[1].time, 1);
    EXPECT_EQ(scene.animation.keys[1].interpolation, Interpolation::Ease);
    Scene expected = defaultScene();
    applyOverride(expected, "animation.fps=8");
    applyOverride(expected, "animation.keys=" + kKeys);
    EXPECT_EQ(r->body, sceneToToml(expected));
}

TEST_F(ExploreFilm, FramesAreTheLibrarysRenderOfSceneAtFrame) {
    startServer(options());
    Scene film = defaultScene();
    applyOverride(film, "render.width=40");
    applyOverride(film, "render.height=30");
    applyOverride(film, "render.samples=1");
    applyOverride(film, "animation.fps=8");
    applyOverride(film, "animation.keys=" + kKeys);
    ASSERT_EQ(filmFrameCount(film), 9);
    std::string frames[2];
    for (int64_t frame : {1, 5}) {
        auto r = get("/api/frame?client=t&frame=" + std::to_string(frame) +
                     "&render.width=40&render.height=30&render.samples=1&" + keysQuery());
        ASSERT_TRUE(r);
        ASSERT_EQ(r->status, 200) << r->body;
        EXPECT_EQ(r->get_header_value("Content-Type"), "image/png");
        auto expected = encodePng(render(sceneAtFrame(film, frame)).image, 8);
        EXPECT_EQ(r->body, std::string(expected.begin(), expected.end())) << "frame " << frame;
        frames[frame == 1 ? 0 : 1] = r->body;
    }
    EXPECT_NE(frames[0], frames[1]);  // c moved
}

TEST_F(ExploreFilm, FilmTellsFramesFpsAndKeys) {
    startServer(options());
    auto none = get("/api/film");
    ASSERT_EQ(none->status, 200) << none->body;
    EXPECT_EQ(Json::parse(none->body)["frames"], 0);
    auto r = get("/api/film?" + keysQuery());
    ASSERT_EQ(r->status, 200) << r->body;
    Json film = Json::parse(r->body);
    EXPECT_EQ(film["frames"], 9);  // 0 s to 1 s at 8 fps, both ends
    EXPECT_EQ(film["fps"], 8.0);
    ASSERT_EQ(film["keys"].size(), 2u);
    EXPECT_EQ(film["keys"][0]["interpolation"], nullptr);
    EXPECT_EQ(film["keys"][1]["interpolation"], "ease");
    EXPECT_EQ(film["keys"][1]["values"]["fractal.c"], Json::array({-0.5, 0.5, 0.1, 0.0}));
    auto longer = get("/api/film?animation.duration=2&" + keysQuery());
    EXPECT_EQ(Json::parse(longer->body)["frames"], 16);
}

TEST_F(ExploreFilm, BadKeysAndFramesAre400NamingTheKey) {
    startServer(options());
    expectBadKey(get("/api/scene?animation.keys=" + urlEncode("[{time = 0, \"fractal.cc\" = 1}]")),
                 "fractal.cc");
    expectBadKey(
        get("/api/film?animation.keys=" +
            urlEncode("[{time = 1, \"camera.fov\" = 30}, {time = 1, \"camera.fov\" = 40}]")),
        "animation.keys");
    expectBadKey(
        get("/api/scene?animation.keys=" + urlEncode("[{time = 0, \"animation.fps\" = 3}]")),
        "animation.fps");
    expectBadKey(get("/api/render?animation.keys=" + urlEncode("{time = 0}")), "animation.keys");
    std::string many = "[";
    for (int i = 0; i < 65; ++i)
        many += (i ? ", " : "") + std::string("{time = ") + std::to_string(i) +
                ", \"camera.fov\" = 30}";
    many += "]";
    expectBadKey(get("/api/scene?animation.keys=" + urlEncode(many)), "animation.keys");
    expectBadKey(get("/api/frame?" + keysQuery()), "frame");
    expectBadKey(get("/api/frame?frame=0&" + keysQuery()), "frame");
    expectBadKey(get("/api/frame?frame=2x&" + keysQuery()), "frame");
    expectBadKey(get("/api/frame?frame=10&" + keysQuery()), "frame");  // 9 frames
    expectBadKey(get("/api/frame?frame=1"), "animation");              // no film
    // A frame is bounded as a view is, whatever the keys move.
    expectBadKey(get("/api/frame?frame=1&animation.keys=" +
                     urlEncode("[{time = 0, \"render.width\" = 4000, \"render.height\" = 4000}]")),
                 "render.width");
    expectBadKey(get("/api/frame?frame=1&animation.keys=" +
                     urlEncode("[{time = 0, \"fractal.max_iterations\" = 100000}]")),
                 "fractal.max_iterations");
}

}  // namespace
}  // namespace quaternia::testing
