// The explorer's HTTP API, in-process on a loopback port: the page and the table are served,
// views render, every bad parameter is a 400 naming the key, nothing outside the embedded page
// is reachable, image sizes and request rates are bounded, and a client's new request cancels
// its stale render.
#include <algorithm>
#include <atomic>
#include <thread>

#include "quaternia/image/png_io.h"
#include "quaternia/render/pixel_certificate.h"
#include "quaternia/render/render.h"
#include "quaternia/scene/json.h"
#include "quaternia/scene/parameters.h"
#include "quaternia/scene/presets.h"
#include "quaternia/scene/scene_file.h"
#include "server/explore_request.h"
#include "server/explore_test_client.h"

namespace quaternia::testing {
namespace {

class ExploreApi : public ExploreServerFixture {};

// 400 with a JSON body naming `key`.
void expectBadKey(const httplib::Result& result, const std::string& key) {
    ASSERT_TRUE(result) << "no answer";
    EXPECT_EQ(result->status, 400) << result->body;
    EXPECT_EQ(result->get_header_value("Content-Type"), "application/json");
    Json body = Json::parse(result->body);
    EXPECT_EQ(body["key"], key) << result->body;
    EXPECT_TRUE(body["error"].is_string()) << result->body;
}

TEST_F(ExploreApi, ServesThePageAndTheParameterTable) {
    startServer(options());
    for (const char* path :
         {"/", "/index.html", "/explore.js", "/controls.js", "/timeline.js", "/explore.css"}) {
        auto r = get(path);
        ASSERT_TRUE(r);
        EXPECT_EQ(r->status, 200) << path;
        EXPECT_FALSE(r->body.empty()) << path;
    }
    EXPECT_NE(get("/")->body.find("explore.js"), std::string::npos);
    auto table = get("/api/parameters");
    ASSERT_EQ(table->status, 200);
    Json parameters = Json::parse(table->body);
    ASSERT_EQ(parameters.size(), parameterTable().size());
    auto c = std::find_if(parameters.begin(), parameters.end(),
                          [](const Json& p) { return p["name"] == "fractal.c"; });
    ASSERT_NE(c, parameters.end());
    EXPECT_EQ((*c)["type"], "components");
    EXPECT_EQ((*c)["lengths"], Json::array({4, 8}));
    EXPECT_EQ((*c)["value"], Json(defaultScene().fractal.c)) << *c;
    EXPECT_TRUE((*c)["help"].is_string());
}

TEST_F(ExploreApi, ServesThePresetsOfTheLibrary) {
    startServer(options());
    auto r = get("/api/presets");
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200) << r->body;
    EXPECT_EQ(r->get_header_value("Content-Type"), "application/json");
    EXPECT_EQ(r->body, presetsJson());
    // Each preset in order, with its description and the values the table holds for it.
    Json presets = Json::parse(r->body);
    ASSERT_EQ(presets.size(), scenePresets().size());
    for (std::size_t i = 0; i < presets.size(); ++i) {
        const Preset& preset = scenePresets()[i];
        EXPECT_EQ(presets[i]["name"], preset.name);
        EXPECT_EQ(presets[i]["description"], preset.description);
    }
    EXPECT_EQ(presets[0]["values"]["fractal.formula"], "z^2 + c") << r->body;
    EXPECT_EQ(presets[0]["values"]["fractal.c"][0], -0.122561) << r->body;
}

TEST_F(ExploreApi, RendersTheSamePngAsTheLibrary) {
    startServer(options());
    auto r =
        get("/api/render?client=a&render.width=48&render.height=32&render.samples=1"
            "&fractal.c=%5B-0.1%2C%200.7%2C%200%2C%200%5D");
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200) << r->body;
    EXPECT_EQ(r->get_header_value("Content-Type"), "image/png");
    Scene scene = defaultScene();
    applyOverride(scene, "render.width=48");
    applyOverride(scene, "render.height=32");
    applyOverride(scene, "render.samples=1");
    applyOverride(scene, "fractal.c=[-0.1, 0.7, 0, 0]");
    auto expected = encodePng(render(scene).image, 8);
    EXPECT_EQ(r->body, std::string(expected.begin(), expected.end()));
}

Image decodedPng(const std::string& body) {
    return decodePng(std::span(reinterpret_cast<const uint8_t*>(body.data()), body.size()));
}

TEST_F(ExploreApi, CertifyTintsTheUndecidedPixelsAndNothingElse) {
    startServer(options());
    const std::string view = "/api/render?client=a&render.width=64&render.height=36";
    auto plain = get(view);
    auto certified = get(view + "&certify=true");
    ASSERT_TRUE(plain && certified);
    ASSERT_EQ(plain->status, 200) << plain->body;
    ASSERT_EQ(certified->status, 200) << certified->body;
    EXPECT_FALSE(certified->has_header("X-Certify-Error"));
    // The library's picture, certificate and tint, byte for byte.
    Scene scene = defaultScene();
    applyOverride(scene, "render.width=64");
    applyOverride(scene, "render.height=36");
    Image expected = render(scene).image;
    const PixelCertificate certificate = certifyPixels(scene);
    tintUndecided(expected, certificate);
    const auto png = encodePng(expected, 8, scene.render.alpha == AlphaMode::Opaque);
    EXPECT_EQ(certified->body, std::string(png.begin(), png.end()));
    EXPECT_EQ(std::stod(certified->get_header_value("X-Certify-Undecided")),
              std::stod(std::to_string(certificate.counts.undecidedFraction())));
    // Every pixel that differs from the plain picture is undecided and mixed halfway with
    // magenta (to the 8-bit rounding), and every undecided pixel differs.
    const Image a = decodedPng(plain->body), b = decodedPng(certified->body);
    ASSERT_EQ(a.width(), 64);
    int64_t tinted = 0;
    for (int y = 0; y < 36; ++y)
        for (int x = 0; x < 64; ++x) {
            const Rgba p = a.at(x, y), q = b.at(x, y);
            if (p == q) continue;
            ++tinted;
            EXPECT_EQ(certificate.at(x, y), PixelClass::kUndecided) << x << ", " << y;
            EXPECT_NEAR(q.r, 0.5f * (p.r + 1), 1.01f / 255) << x << ", " << y;
            EXPECT_NEAR(q.g, 0.5f * p.g, 1.01f / 255) << x << ", " << y;
            EXPECT_NEAR(q.b, 0.5f * (p.b + 1), 1.01f / 255) << x << ", " << y;
        }
    EXPECT_GT(tinted, 0);
    EXPECT_EQ(tinted, certificate.counts.undecided);
    // certify=false is the plain picture; anything but a boolean is a 400 naming certify.
    EXPECT_EQ(get(view + "&certify=false")->body, plain->body);
    expectBadKey(get(view + "&certify=maybe"), "certify");
}

TEST_F(ExploreApi, CertifyRefusalIsReportedAndThePictureIsUntinted) {
    startServer(options());
    // Bicomplex log has no interval extension: validateCertificate refuses it.
    const std::string view =
        "/api/render?client=a&render.width=32&render.height=24&render.samples=1"
        "&fractal.algebra=bicomplex&fractal.formula=%22log(z)%20%2B%20c%22";
    auto plain = get(view);
    auto certified = get(view + "&certify=true");
    ASSERT_TRUE(plain && certified);
    ASSERT_EQ(certified->status, 200) << certified->body;
    EXPECT_EQ(certified->body, plain->body);
    EXPECT_EQ(certified->get_header_value("X-Certify-Key"), "fractal.formula");
    const std::string message = certified->get_header_value("X-Certify-Error");
    EXPECT_NE(message.find("log"), std::string::npos) << message;
    EXPECT_FALSE(certified->has_header("X-Certify-Undecided"));
}

TEST_F(ExploreApi, BadParametersAre400NamingTheKey) {
    startServer(options());
    expectBadKey(get("/api/render?render.widht=10"), "render.widht");
    expectBadKey(get("/api/render?render.width=0"), "render.width");
    expectBadKey(get("/api/render?fractal.c=nan"), "fractal.c");
    expectBadKey(get("/api/render?fractal.c=%5B1%2C2%5D"), "fractal.c");
    expectBadKey(get("/api/render?fractal.formula=z%5E%5E"), "fractal.formula");
    expectBadKey(get("/api/render?shading.shadows=maybe"), "shading.shadows");
    expectBadKey(get("/api/render?slice.normal=%5B0%2C0%2C0%2C0%5D"), "slice.normal");
    expectBadKey(get("/api/scene?camera.fov=1e999"), "camera.fov");
    expectBadKey(get("/api/command?nonsense"), "nonsense");
    expectBadKey(get("/api/render?client=%3Cscript%3E"), "client");
    expectBadKey(get("/api/render?fractal.max_iterations=100000"), "fractal.max_iterations");
}

TEST_F(ExploreApi, ImageSizesAreLimited) {
    startServer(options());
    expectBadKey(get("/api/render?render.width=4000&render.height=4000"), "render.width");
    expectBadKey(get("/api/render?render.samples=64&render.width=8&render.height=8"),
                 "render.samples");
    expectBadKey(get("/api/download?render.width=5000&render.height=10"), "render.width");
    expectBadKey(get("/api/mesh?mesh.resolution=1024"), "mesh.resolution");
    expectBadKey(get("/api/mandelbrot?render.width=4096&render.height=4096"), "render.width");
}

TEST_F(ExploreApi, OnlyTheEmbeddedFilesAreServed) {
    startServer(options());
    for (const char* path :
         {"/../CMakeLists.txt", "/..%2fCMakeLists.txt", "/%2e%2e/%2e%2e/etc/passwd",
          "/%2E%2E%2F%2E%2E%2Fetc%2Fpasswd", "//etc/passwd", "/etc/passwd", "/web/index.html",
          "/explore.js/..", "/index.html%00.png", "/api/../explore.js/../../README.md",
          "/..\\..\\README.md"}) {
        auto r = get(path);
        ASSERT_TRUE(r) << path;
        EXPECT_TRUE(r->status == 404 || r->status == 400) << path << " -> " << r->status;
        EXPECT_EQ(r->body.find("root:"), std::string::npos) << path;
    }
}

TEST_F(ExploreApi, CommandAndSceneReproduceTheView) {
    startServer(options());
    auto command = get("/api/command?render.width=64&fractal.formula=%22z%5E3%20%2B%20c%22");
    ASSERT_EQ(command->status, 200);
    EXPECT_EQ(command->body,
              "quaternia render --set 'fractal.formula=\"z^3 + c\"' --set 'render.width=64' -o "
              "quaternia.png\n");
    auto scene = get("/api/scene?camera.fov=30.5");
    ASSERT_EQ(scene->status, 200);
    EXPECT_EQ(parseScene(scene->body).camera.fovDegrees, 30.5);
}

TEST_F(ExploreApi, RequestRateIsLimitedPerAddress) {
    ExploreServerOptions o = options();
    o.requestsPerSecond = 0.5;
    o.requestBurst = 5;
    startServer(o);
    httplib::Client c = client();
    int ok = 0, limited = 0;
    for (int i = 0; i < 8; ++i) {
        auto r = c.Get("/api/parameters");
        ASSERT_TRUE(r);
        (r->status == 200 ? ok : limited) += r->status == 200 || r->status == 429;
    }
    EXPECT_EQ(ok, 5);
    EXPECT_EQ(limited, 3);
}

TEST_F(ExploreApi, ANewRequestCancelsTheClientsStaleRender) {
    ExploreServerOptions o = options();
    o.renderThreads = 1;
    startServer(o);
    // A slow render (1080p at 16 samples on one thread: several seconds; 640x360 took under
    // the 300 ms below once the lanes got faster), then a small one from the same client.
    std::atomic<int> slowStatus{0};
    std::thread slow([&] {
        auto r =
            get("/api/render?client=tab&render.width=1920&render.height=1080"
                "&render.samples=16");
        slowStatus = r ? r->status : -1;
    });
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    auto start = std::chrono::steady_clock::now();
    auto fast = get("/api/render?client=tab&render.width=16&render.height=16&render.samples=1");
    slow.join();
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_TRUE(fast);
    EXPECT_EQ(fast->status, 200);
    EXPECT_EQ(slowStatus, 204);
    EXPECT_LT(seconds, 2);  // the slow render alone takes longer
}

TEST(ExploreRequest, CommandListsOnlyChangedKeysInExactTomlSyntax) {
    Scene scene = defaultScene();
    EXPECT_EQ(renderCommandForScene(scene), "quaternia render -o quaternia.png");
    applyOverride(scene, "fractal.c=[0.1, 0.30000000000000004, 0, 0]");
    EXPECT_EQ(renderCommandForScene(scene),
              "quaternia render --set 'fractal.c=[0.1, 0.30000000000000004, 0.0, 0.0]' -o "
              "quaternia.png");
    // [animation] does not change a still: the command leaves it out.
    applyOverride(scene, "animation.fps=24");
    applyOverride(scene, "animation.keys=[{time = 0, \"camera.fov\" = 30}]");
    EXPECT_EQ(renderCommandForScene(scene),
              "quaternia render --set 'fractal.c=[0.1, 0.30000000000000004, 0.0, 0.0]' -o "
              "quaternia.png");
}

}  // namespace
}  // namespace quaternia::testing
