// An in-process explorer server on a free loopback port and an HTTP client for it, shared by
// the server tests and the load test.
#pragma once

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <httplib.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <memory>
#include <string>

#include "quaternia/scene/parameters.h"
#include "server/explore_server.h"

namespace quaternia::testing {

// Writes `bytes` on a raw loopback connection to `port` (then, with `endWriting`, shuts its
// writing side) and returns what the server answers until it closes the connection or 5 s
// pass.
inline std::string sendRaw(int port, const std::string& bytes, bool endWriting = true) {
    std::string reply;
    int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    if (fd < 0) return reply;
    timeval timeout{5, 0};
    ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(uint16_t(port));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0) {
        (void)!::send(fd, bytes.data(), bytes.size(), MSG_NOSIGNAL);
        if (endWriting) ::shutdown(fd, SHUT_WR);
        char buffer[4096];
        for (ssize_t n; (n = ::recv(fd, buffer, sizeof buffer, 0)) > 0;)
            reply.append(buffer, std::size_t(n));
    }
    ::close(fd);
    return reply;
}

class ExploreServerFixture : public ::testing::Test {
  protected:
    // Tests change options (limits, rates) before the first request.
    ExploreServerOptions options() {
        ExploreServerOptions o;
        o.port = 0;
        o.startScene = defaultScene();
        o.renderThreads = 2;
        o.requestsPerSecond = 1e6;  // rate limiting has its own test
        o.requestBurst = 1e6;
        return o;
    }
    void startServer(ExploreServerOptions o) {
        server_ = std::make_unique<ExploreServer>(std::move(o));
        server_->start();
    }
    void TearDown() override {
        if (server_) server_->stop();
    }
    httplib::Client client() const {
        httplib::Client c("127.0.0.1", server_->port());
        c.set_connection_timeout(5, 0);
        c.set_read_timeout(30, 0);
        return c;
    }
    httplib::Result get(const std::string& path) const { return client().Get(path); }

    std::unique_ptr<ExploreServer> server_;
};

}  // namespace quaternia::testing
