// Load on loopback: 50 clients rendering small views at once, and 1,000 malformed requests
// (bad keys and values, traversal paths, oversized images, junk that is not HTTP), all answered
// within a bound, after which the server still answers. The timings are printed for the README.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <thread>
#include <vector>

#include "server/explore_test_client.h"

namespace quaternia::testing {
namespace {

class ExploreLoad : public ExploreServerFixture {};

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Writes `bytes` on a raw connection and reads until the server closes it or 5 s pass.
void sendRaw(int port, const std::string& bytes) {
    int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    ASSERT_GE(fd, 0);
    timeval timeout{5, 0};
    ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(uint16_t(port));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0) {
        (void)!::send(fd, bytes.data(), bytes.size(), MSG_NOSIGNAL);
        ::shutdown(fd, SHUT_WR);
        char buffer[4096];
        while (::recv(fd, buffer, sizeof buffer, 0) > 0) {
        }
    }
    ::close(fd);
}

// The i-th malformed request: a path and query that must be refused.
std::string malformedPath(int i) {
    static const std::vector<std::string> paths = {
        "/api/render?render.width=-1",
        "/api/render?fractal.c=%5Bnan%2C0%2C0%2C0%5D",
        "/api/render?fractal.formula=((((((((z",
        "/api/render?render.width=100000&render.height=100000",
        "/api/render?no.such=key",
        "/api/render?fractal.c=%5B1e999%2C0%2C0%2C0%5D",
        "/api/render?render.samples=abc",
        "/api/render?client=..%2F..%2F",
        "/api/render?camera.position=%5B0%2C0%2C0%5D",  // at look_at
        "/api/mesh?mesh.resolution=4096",
        "/api/scene?%ff%fe=%00",
        "/../../etc/passwd",
        "/%2e%2e/%2e%2e/etc/passwd",
        "/api/render?" + std::string(3000, '%'),
    };
    return paths[std::size_t(i) % paths.size()];
}

TEST_F(ExploreLoad, FiftyConcurrentClientsAndAThousandMalformedRequests) {
    startServer(options());
    const int port = server_->port();
    auto start = std::chrono::steady_clock::now();

    // 50 clients at once, each its own tab id and address (127.0.0.10 up: all of 127/8 is
    // loopback on Linux; one address would pass the limit of connections per address),
    // rendering three small views.
    std::atomic<int> rendered{0}, superseded{0}, failed{0};
    std::vector<std::thread> clients;
    for (int i = 0; i < 50; ++i) {
        clients.emplace_back([&, i] {
            httplib::Client c = client();
            c.set_interface("127.0.0." + std::to_string(10 + i));  // an address is bound as is
            for (int view = 0; view < 3; ++view) {
                std::string path = "/api/render?client=load" + std::to_string(i) +
                                   "&render.width=32&render.height=18&render.samples=1"
                                   "&slice.distance=" +
                                   std::to_string(0.01 * view);
                auto r = c.Get(path);
                if (r && r->status == 200 && r->body.size() > 8)
                    ++rendered;
                else if (r && r->status == 204)
                    ++superseded;
                else
                    ++failed;
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
                auto r = c.Get(malformedPath(t * 96 + i));
                bool ok = r && r->status >= 400 && r->status < 500;
                (ok ? refused : wrong) += 1;
            }
            for (int i = 0; i < 4; ++i) {
                const char* junk[] = {"\x16\x03\x01\x02\x00garbage\r\n\r\n",
                                      "GET /api/render?render.width=1 HTTP/1.1\r\nHost:",
                                      "POST / HTTP/1.1\r\nContent-Length: 99999999\r\n\r\nxx",
                                      "GET /\x01\x02 HTTP/9.9\r\n\r\n"};
                sendRaw(port, junk[i]);
                ++refused;
            }
        });
    }
    for (auto& t : attackers)
        t.join();
    double malformedSeconds = secondsSince(start);
    EXPECT_EQ(refused, 1000);
    EXPECT_EQ(wrong, 0);

    auto after = get("/api/render?render.width=8&render.height=8&render.samples=1");
    ASSERT_TRUE(after);
    EXPECT_EQ(after->status, 200);
    std::printf("load: 50 clients x 3 renders in %.2f s; 1000 malformed requests in %.2f s\n",
                concurrentSeconds, malformedSeconds);
    EXPECT_LT(concurrentSeconds + malformedSeconds, 120);
}

}  // namespace
}  // namespace quaternia::testing
