// The explorer's bounds on what a request may ask, each at its edge: 64 query parameters,
// render.max_steps, the rays of a download, two renders at once, a key given twice, and methods
// other than GET. A refusal is a status and one line of JSON naming the key.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "quaternia/scene/json.h"
#include "quaternia/scene/parameters.h"
#include "server/explore_test_client.h"

namespace quaternia::testing {
namespace {

using Clock = std::chrono::steady_clock;

class ExploreLimit : public ExploreServerFixture {};

// `status` with the one-line JSON {"error": message, "key": key}, the message naming `needle`.
void expectRefusal(const httplib::Result& result, int status, const std::string& key,
                   const std::string& needle) {
    ASSERT_TRUE(result) << "no answer";
    EXPECT_EQ(result->status, status) << result->body;
    EXPECT_EQ(result->get_header_value("Content-Type"), "application/json");
    EXPECT_EQ(std::count(result->body.begin(), result->body.end(), '\n'), 1) << result->body;
    Json body = Json::parse(result->body);
    EXPECT_EQ(body["key"], key) << result->body;
    EXPECT_NE(body["error"].get<std::string>().find(needle), std::string::npos) << result->body;
}

// The first `count` keys of the table at their default values.
std::string defaultKeys(std::size_t count) {
    httplib::Params params;
    const Scene defaults = defaultScene();
    for (const Parameter& p : parameterTable()) {
        if (params.size() == count) break;
        params.emplace(p.name(), formatValue(p.read(defaults)));
    }
    EXPECT_EQ(params.size(), count) << "the table has fewer keys";
    return httplib::detail::params_to_query_str(params);
}

TEST_F(ExploreLimit, AtMost64QueryParameters) {
    startServer(options());
    auto r = get("/api/command?" + defaultKeys(64));
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 200) << r->body;
    EXPECT_EQ(r->body, "quaternia render -o quaternia.png\n");
    expectRefusal(get("/api/command?" + defaultKeys(64) + "&client=tab"), 400, "query",
                  "too many query parameters (65; at most 64)");
}

TEST_F(ExploreLimit, RenderMaxStepsAtMost100000) {
    startServer(options());
    auto r = get("/api/command?render.max_steps=100000");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 200) << r->body;
    expectRefusal(get("/api/render?render.max_steps=100001"), 400, "render.max_steps",
                  "render.max_steps = 100001 is above the explorer's limit of 100000 steps");
}

TEST_F(ExploreLimit, RequestsBeyondTheMemoryBudgetAreRefused) {
    ExploreServerOptions o = options();
    o.memory = {4 << 20, "--memory-budget"};  // 2 MiB for each of the two renders at once
    startServer(o);
    // 640 x 480 in float RGBA alone is 4.7 MiB; 64 x 48 needs some 60 KiB.
    expectRefusal(get("/api/render?render.width=640&render.height=480&render.samples=1"), 400,
                  "render.width", "of memory, more than the 2.00 MiB available");
    expectRefusal(get("/api/mesh?mesh.resolution=256"), 400, "mesh.resolution",
                  "of memory, more than the 2.00 MiB available");
    auto r = get("/api/render?render.width=64&render.height=48&render.samples=1");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 200) << r->body;
}

TEST_F(ExploreLimit, DownloadRaysAreCapped) {
    ExploreServerOptions o = options();
    startServer(o);
    // 4096 x 4096 at 4 samples is the default cap; 5 samples is past it.
    expectRefusal(get("/api/download?render.width=4096&render.height=4096&render.samples=5"), 400,
                  "render.samples", "above the explorer's limit of 67108864 rays");
    server_->stop();
    // At its edge, with the cap lowered to a small image's rays.
    o.limits.downloadRays = 32 * 18 * 2;
    startServer(o);
    auto r = get("/api/download?render.width=32&render.height=18&render.samples=2");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 200) << r->body;
    EXPECT_EQ(r->get_header_value("Content-Type"), "image/png");
    EXPECT_EQ(r->get_header_value("Content-Disposition"), "attachment; filename=\"quaternia.png\"");
    expectRefusal(get("/api/download?render.width=32&render.height=18&render.samples=3"), 400,
                  "render.samples", "render.samples = 1728 is above the explorer's limit of 1152");
}

TEST_F(ExploreLimit, TwoRendersRunAtOnce) {
    ExploreServerOptions o = options();  // concurrentRenders as by default: 2
    o.renderThreads = 1;
    startServer(o);
    // Two slow renders of their own tabs (each about half a second on one thread), then a tiny
    // one of a third tab: it waits for a place until one of them has rendered. (It may still
    // answer first: a slow one encodes its PNG after leaving the gate.)
    double slowMs[2] = {0, 0};
    std::thread slow[2];
    for (int i = 0; i < 2; ++i) {
        slow[i] = std::thread([&, i] {
            auto r = get("/api/render?client=slow" + std::to_string(i) +
                         "&render.width=1280&render.height=720&render.samples=4");
            if (r && r->status == 200) slowMs[i] = std::stod(r->get_header_value("X-Render-Ms"));
        });
    }
    // Until both hold a place (under the sanitizers reading their queries alone takes a while).
    const Clock::time_point started = Clock::now();
    while (server_->rendersRunning() < 2 && Clock::now() - started < std::chrono::seconds(20))
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    ASSERT_EQ(server_->rendersRunning(), 2);
    Clock::time_point asked = Clock::now();
    auto tiny = get("/api/render?client=tiny&render.width=8&render.height=8&render.samples=1");
    double tinyMs = std::chrono::duration<double, std::milli>(Clock::now() - asked).count();
    for (auto& t : slow)
        t.join();
    ASSERT_TRUE(tiny);
    EXPECT_EQ(tiny->status, 200);
    ASSERT_GT(slowMs[0], 0);
    ASSERT_GT(slowMs[1], 0);
    // Without the gate the tiny render takes a millisecond or so.
    const double waited = std::chrono::duration<double, std::milli>(asked - started).count();
    EXPECT_GT(tinyMs, 0.5 * (std::min(slowMs[0], slowMs[1]) - waited))
        << "a third render ran at once";
    std::printf(
        "gate: the third render answered after %.0f ms; the two before it rendered in "
        "%.0f and %.0f ms\n",
        tinyMs, slowMs[0], slowMs[1]);
}

TEST_F(ExploreLimit, AKeyGivenTwiceIsRefused) {
    startServer(options());
    expectRefusal(get("/api/render?render.width=10&render.width=20"), 400, "render.width",
                  "render.width is given more than once");
    expectRefusal(get("/api/command?client=a&camera.fov=30&client=b"), 400, "client",
                  "client is given more than once");
}

TEST_F(ExploreLimit, OnlyGetAndHeadAreServed) {
    startServer(options());
    httplib::Client c = client();
    const std::string path = "/api/render?render.width=8&render.height=8";
    std::vector<httplib::Result> results;
    results.push_back(c.Post(path, "x", "text/plain"));
    results.push_back(c.Put(path, "x", "text/plain"));
    results.push_back(c.Patch(path, "x", "text/plain"));
    results.push_back(c.Delete(path));
    results.push_back(c.Options(path));
    for (const httplib::Result& result : results) {
        expectRefusal(result, 405, "method", "is not allowed; the explorer answers GET");
        EXPECT_EQ(result->get_header_value("Allow"), "GET, HEAD");
    }
    auto head = c.Head("/");
    ASSERT_TRUE(head);
    EXPECT_EQ(head->status, 200);
    EXPECT_TRUE(head->body.empty());
    // The body is not read, so nothing after it is taken for a request: one answer, then the
    // connection closes (the client's keep-alive notwithstanding).
    std::string reply = sendRaw(server_->port(),
                                "POST /api/render HTTP/1.1\r\nHost: q\r\nContent-Length: 18\r\n"
                                "Connection: keep-alive\r\n\r\nGET / HTTP/1.1\r\n\r\n",
                                false);
    EXPECT_EQ(reply.rfind("HTTP/1.1 405 Method Not Allowed\r\n", 0), 0u) << reply;
    EXPECT_NE(reply.find("Connection: close\r\n"), std::string::npos) << reply;
    EXPECT_EQ(reply.find("HTTP/1.1", 1), std::string::npos) << "a second answer: " << reply;
}

}  // namespace
}  // namespace quaternia::testing
