// The explorer's server under hostile clients (explore_connections.h): 200 connections from one
// address that each send half a request header and then a byte now and then do not keep a
// well-behaved client from the page; those beyond the per-address limit are refused at once
// with a 503, the admitted ones are cut off at the request deadline, and the limit in all and
// the byte budget of a request hold.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <thread>
#include <vector>

#include "server/explore_static.h"
#include "server/explore_test_client.h"

namespace quaternia::testing {
namespace {

using Clock = std::chrono::steady_clock;

class ExploreConnections : public ExploreServerFixture {};

double secondsBetween(Clock::time_point from, Clock::time_point to) {
    return std::chrono::duration<double>(to - from).count();
}

// A connection to the server from `source`, an address of 127/8 (all loopback on Linux), so
// that the server sees a remote address of its own; -1 when it fails.
int connectFrom(const char* source, int port) {
    int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in local{};
    local.sin_family = AF_INET;
    ::inet_pton(AF_INET, source, &local.sin_addr);
    sockaddr_in server{};
    server.sin_family = AF_INET;
    server.sin_port = htons(uint16_t(port));
    server.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (fd < 0 || ::bind(fd, reinterpret_cast<sockaddr*>(&local), sizeof local) != 0 ||
        ::connect(fd, reinterpret_cast<sockaddr*>(&server), sizeof server) != 0) {
        if (fd >= 0) ::close(fd);
        return -1;
    }
    return fd;
}

bool sendAll(int fd, const std::string& bytes) {
    return ::send(fd, bytes.data(), bytes.size(), MSG_NOSIGNAL) == ssize_t(bytes.size());
}

// Reads what has arrived without waiting; false once the server has closed the connection.
bool readWhatArrived(int fd, std::string& received) {
    char buffer[4096];
    for (;;) {
        ssize_t n = ::recv(fd, buffer, sizeof buffer, MSG_DONTWAIT);
        if (n > 0)
            received.append(buffer, std::size_t(n));
        else
            return n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK);
    }
}

// Reads until the server closes the connection or `seconds` pass.
std::string readUntilClosed(int fd, double seconds) {
    std::string received;
    auto end = Clock::now() + std::chrono::duration<double>(seconds);
    while (Clock::now() < end) {
        pollfd p{fd, POLLIN, 0};
        if (::poll(&p, 1, 20) > 0 && !readWhatArrived(fd, received)) break;
    }
    return received;
}

bool startsWith(const std::string& text, const std::string& prefix) {
    return text.compare(0, prefix.size(), prefix) == 0;
}

struct SlowClient {
    int fd = -1;
    bool open = true;
    Clock::time_point closedAt;  // when the server closed the connection
    std::string received;
};

TEST_F(ExploreConnections, TwoHundredSlowClientsDoNotBlockTheWellBehavedOne) {
    ExploreServerOptions o = options();
    o.connections.perAddress = 8;
    o.connections.total = 32;
    o.connections.requestSeconds = 1;
    startServer(o);
    const int port = server_->port();

    // 200 connections from 127.0.0.2, each with half a header; then, every 100 ms, a byte more
    // on each that is still open (cpp-httplib's own time-out per read would never expire).
    std::vector<SlowClient> slow(200);
    const Clock::time_point start = Clock::now();
    for (SlowClient& c : slow) {
        c.fd = connectFrom("127.0.0.2", port);
        ASSERT_GE(c.fd, 0) << "connect: " << std::strerror(errno);
        ASSERT_TRUE(sendAll(c.fd, "GET / HTTP/1.1\r\nHost: quaternia\r\nX-Slow: "));
    }
    std::thread trickle([&] {
        while (Clock::now() < start + std::chrono::seconds(4)) {
            bool anyOpen = false;
            for (SlowClient& c : slow) {
                if (!c.open) continue;
                if (!readWhatArrived(c.fd, c.received)) {
                    c.open = false;
                    c.closedAt = Clock::now();
                    continue;
                }
                anyOpen = true;
                (void)!::send(c.fd, "a", 1, MSG_NOSIGNAL | MSG_DONTWAIT);
            }
            if (!anyOpen) break;
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
        }
    });

    // The page from 127.0.0.1 meanwhile, whole, and before any slow client was cut off.
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    const Clock::time_point asked = Clock::now();
    auto page = get("/");
    const Clock::time_point answered = Clock::now();
    trickle.join();

    ASSERT_TRUE(page) << "no answer: " << httplib::to_string(page.error());
    EXPECT_EQ(page->status, 200);
    EXPECT_EQ(page->body, exploreStaticFiles().at("/").body);
    const double pageSeconds = secondsBetween(asked, answered);
    EXPECT_LT(pageSeconds, 0.8) << "the deadline is 1 s";

    int refused = 0, cutOff = 0;
    double lastClose = 0;
    Clock::time_point firstCut = Clock::time_point::max();
    for (SlowClient& c : slow) {
        EXPECT_FALSE(c.open) << "still open after 4 s";
        double closed = secondsBetween(start, c.closedAt);
        lastClose = std::max(lastClose, closed);
        if (startsWith(c.received, "HTTP/1.1 503")) {
            ++refused;
            EXPECT_LT(closed, 0.5) << "refused at once";
            EXPECT_NE(c.received.find("too many connections"), std::string::npos) << c.received;
        } else {
            ++cutOff;
            firstCut = std::min(firstCut, c.closedAt);
            // cpp-httplib answers a header cut short with a 400.
            EXPECT_TRUE(startsWith(c.received, "HTTP/1.1 400")) << c.received;
            EXPECT_GE(closed, 0.9) << "held until the deadline";
            EXPECT_LT(closed, 2.0) << "cut off at the deadline";
        }
        ::close(c.fd);
    }
    EXPECT_EQ(refused, 192);
    EXPECT_EQ(cutOff, 8);
    EXPECT_LT(answered, firstCut) << "the page came while the admitted slow clients held on";
    ExploreConnectionStats stats = server_->connectionStats();
    EXPECT_EQ(stats.refused, 192u);
    EXPECT_EQ(stats.timedOut, 8u);
    std::printf(
        "slow clients: page in %.3f s while 200 trickled; 192 refused, 8 cut off by %.2f s\n",
        pageSeconds, lastClose);
}

TEST_F(ExploreConnections, TheLimitInAllRefusesEveryAddress) {
    ExploreServerOptions o = options();
    o.connections.total = 4;
    startServer(o);
    const int port = server_->port();
    std::vector<int> held;
    for (const char* source : {"127.0.0.3", "127.0.0.3", "127.0.0.4", "127.0.0.5"}) {
        held.push_back(connectFrom(source, port));
        ASSERT_GE(held.back(), 0);
        ASSERT_TRUE(sendAll(held.back(), "GET / HTTP/1.1\r\n"));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));  // all four admitted
    auto refused = get("/");
    ASSERT_TRUE(refused);
    EXPECT_EQ(refused->status, 503);
    EXPECT_EQ(refused->get_header_value("Retry-After"), "1");
    for (int fd : held)
        ::close(fd);
    std::this_thread::sleep_for(std::chrono::milliseconds(300));  // their places freed
    auto page = get("/");
    ASSERT_TRUE(page);
    EXPECT_EQ(page->status, 200);
    EXPECT_EQ(server_->connectionStats().refused, 1u);
}

TEST_F(ExploreConnections, AHeaderBeyond64KiBIsRefused) {
    startServer(options());
    int fd = connectFrom("127.0.0.1", server_->port());
    ASSERT_GE(fd, 0);
    std::string header = "GET / HTTP/1.1\r\nHost: quaternia\r\n";
    while (header.size() < 70 * 1024)
        header += "X-Filler: " + std::string(60, 'f') + "\r\n";
    sendAll(fd, header + "\r\n");  // may fail part-way once the server has answered
    std::string reply = readUntilClosed(fd, 5);
    ::close(fd);
    EXPECT_TRUE(startsWith(reply, "HTTP/1.1 400")) << reply;
    auto page = get("/");
    ASSERT_TRUE(page);
    EXPECT_EQ(page->status, 200);
}

}  // namespace
}  // namespace quaternia::testing
