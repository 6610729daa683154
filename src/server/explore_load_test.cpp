// Load on loopback: 50 clients rendering small views at once, and 1,000 malformed requests
// (bad keys and values, traversal paths, oversized images, junk that is not HTTP), all answered
// within a bound, after which the server still answers. Every reply counted is checked: each
// render is the library's PNG of its view, each refusal its status and the key it names. The
// timings are printed for docs/benchmarks.md, The explorer.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <thread>
#include <vector>

#include "quaternia/image/png_io.h"
#include "quaternia/render/render.h"
#include "quaternia/scene/json.h"
#include "quaternia/scene/scene_file.h"
#include "server/explore_test_client.h"

namespace quaternia::testing {
namespace {

class ExploreLoad : public ExploreServerFixture {};

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct Refusal {
    std::string path;
    int status;
    std::string key;  // of the JSON body {"error": ..., "key": ...}
};

// The i-th malformed request: a path and query, and how it is refused.
const Refusal& malformed(int i) {
    static const std::vector<Refusal> refusals = {
        {"/api/render?render.width=-1", 400, "render.width"},
        {"/api/render?fractal.c=%5Bnan%2C0%2C0%2C0%5D", 400, "fractal.c"},
        {"/api/render?fractal.formula=((((((((z", 400, "fractal.formula"},
        // Each side is within the table's range before their product is checked.
        {"/api/render?render.width=100000&render.height=100000", 400, "render.height"},
        {"/api/render?no.such=key", 400, "no.such"},
        {"/api/render?fractal.c=%5B1e999%2C0%2C0%2C0%5D", 400, "fractal.c"},
        {"/api/render?render.samples=abc", 400, "render.samples"},
        {"/api/render?client=..%2F..%2F", 400, "client"},
        {"/api/render?camera.position=%5B0%2C0%2C0%5D", 400, "camera.look_at"},  // at look_at
        {"/api/mesh?mesh.resolution=4096", 400, "mesh.resolution"},
        // Not UTF-8: the JSON answer names the key with replacement characters.
        {"/api/scene?%ff%fe=%00", 400, "\xEF\xBF\xBD\xEF\xBF\xBD"},
        {"/../../etc/passwd", 404, "path"},
        {"/%2e%2e/%2e%2e/etc/passwd", 404, "path"},
        {"/api/render?" + std::string(3000, '%'), 400, std::string(3000, '%')},
    };
    return refusals[std::size_t(i) % refusals.size()];
}

// Raw bytes that are not a request the server serves, and the status line that answers each.
struct Junk {
    std::string bytes, statusLine, key;
};
const std::vector<Junk>& junk() {
    static const std::vector<Junk> all = {
        {"\x16\x03\x01\x02\x00garbage\r\n\r\n", "HTTP/1.1 400 Bad Request", ""},
        {"GET /api/render?render.width=1 HTTP/1.1\r\nHost:", "HTTP/1.1 400 Bad Request", ""},
        {"POST / HTTP/1.1\r\nContent-Length: 99999999\r\n\r\nxx", "HTTP/1.1 405 Method Not Allowed",
         "method"},
        {"GET /\x01\x02 HTTP/9.9\r\n\r\n", "HTTP/1.1 400 Bad Request", ""},
    };
    return all;
}

// Whether a raw reply is exactly one answer: `statusLine`, then a JSON body naming `key`.
bool isOneRefusal(const std::string& reply, const Junk& expected) {
    std::size_t bodyStart = reply.find("\r\n\r\n");
    if (reply.rfind(expected.statusLine + "\r\n", 0) != 0 || bodyStart == std::string::npos)
        return false;
    Json body = Json::parse(reply.substr(bodyStart + 4), nullptr, false);
    return !body.is_discarded() && body["key"] == expected.key && body["error"].is_string();
}

TEST_F(ExploreLoad, FiftyConcurrentClientsAndAThousandMalformedRequests) {
    startServer(options());
    const int port = server_->port();
    auto start = std::chrono::steady_clock::now();

    // 50 clients at once, each its own tab id and address (127.0.0.10 up: all of 127/8 is
    // loopback on Linux; one address would pass the limit of connections per address),
    // rendering three small views, each of which must come back as the library renders it.
    const std::string size = "render.width=32&render.height=18&render.samples=1";
    std::vector<std::string> views, pngs;
    for (int view = 0; view < 3; ++view) {
        views.push_back("slice.distance=" + std::to_string(0.01 * view));
        Scene scene = defaultScene();
        for (const char* assignment : {"render.width=32", "render.height=18", "render.samples=1"})
            applyOverride(scene, assignment);
        applyOverride(scene, views.back());
        auto png = encodePng(render(scene).image, 8);
        pngs.emplace_back(png.begin(), png.end());
    }
    std::atomic<int> rendered{0}, failed{0};
    std::vector<std::thread> clients;
    for (int i = 0; i < 50; ++i) {
        clients.emplace_back([&, i] {
            httplib::Client c = client();
            c.set_interface("127.0.0." + std::to_string(10 + i));  // an address is bound as is
            for (int view = 0; view < 3; ++view) {
                auto r = c.Get("/api/render?client=load" + std::to_string(i) + "&" + size + "&" +
                               views[std::size_t(view)]);
                bool right = r && r->status == 200 &&
                             r->get_header_value("Content-Type") == "image/png" &&
                             r->body == pngs[std::size_t(view)];
                (right ? rendered : failed) += 1;
            }
        });
    }
    for (auto& t : clients)
        t.join();
    double concurrentSeconds = secondsSince(start);
    EXPECT_EQ(rendered, 150);
    EXPECT_EQ(failed, 0);

    // 1,000 malformed requests from 10 threads: 960 over HTTP, 40 raw junk.
    start = std::chrono::steady_clock::now();
    std::atomic<int> refused{0}, wrong{0};
    std::vector<std::thread> attackers;
    for (int t = 0; t < 10; ++t) {
        attackers.emplace_back([&, t] {
            httplib::Client c = client();
            for (int i = 0; i < 96; ++i) {
                const Refusal& expected = malformed(t * 96 + i);
                auto r = c.Get(expected.path);
                bool right = r && r->status == expected.status &&
                             r->get_header_value("Content-Type") == "application/json";
                if (right) {
                    Json body = Json::parse(r->body, nullptr, false);
                    right = !body.is_discarded() && body["key"] == expected.key &&
                            body["error"].is_string();
                }
                (right ? refused : wrong) += 1;
            }
            for (const Junk& expected : junk())
                (isOneRefusal(sendRaw(port, expected.bytes), expected) ? refused : wrong) += 1;
        });
    }
    for (auto& t : attackers)
        t.join();
    double malformedSeconds = secondsSince(start);
    EXPECT_EQ(refused, 1000);
    EXPECT_EQ(wrong, 0);

    auto after = get("/api/render?" + size + "&" + views[0]);
    ASSERT_TRUE(after);
    EXPECT_EQ(after->status, 200);
    EXPECT_EQ(after->body, pngs[0]);
    std::printf("load: 50 clients x 3 renders in %.2f s; 1000 malformed requests in %.2f s\n",
                concurrentSeconds, malformedSeconds);
    EXPECT_LT(concurrentSeconds + malformedSeconds, 120);
}

}  // namespace
}  // namespace quaternia::testing
