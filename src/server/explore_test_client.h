// An in-process explorer server on a free loopback port and an HTTP client for it, shared by
// the server tests and the load test.
#pragma once

#include <gtest/gtest.h>
#include <httplib.h>

#include <memory>
#include <string>

#include "quaternia/scene/parameters.h"
#include "server/explore_server.h"

namespace quaternia::testing {

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
