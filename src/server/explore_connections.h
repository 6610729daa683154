// The explorer's HTTP server under hostile clients: cpp-httplib's Server with each connection
// admitted against a per-address and a total limit (refused at once beyond them, with a short
// 503), and each request read against a deadline, so that clients which open many connections
// or trickle their bytes cannot hold the threads a well-behaved client needs.
//
// cpp-httplib reads a request with a time-out per read, which a byte now and then resets, and
// serves connections on a fixed pool: 64 half-sent headers held every thread. Here its private
// virtual process_and_close_socket is overridden; the requests themselves are still parsed and
// routed by its process_request.
#pragma once

#include <httplib.h>

#include <atomic>
#include <map>
#include <mutex>
#include <string>

#include "server/explore_server.h"

namespace quaternia {

// Connections being served, per remote address and in all.
class ConnectionAdmission {
  public:
    explicit ConnectionAdmission(const ExploreConnectionLimits& limits) : limits_(limits) {}
    // Takes a place for `address`; false (nothing taken) when either limit is reached.
    bool enter(const std::string& address);
    void leave(const std::string& address);

  private:
    ExploreConnectionLimits limits_;
    std::mutex mutex_;
    std::map<std::string, int> perAddress_;
    int total_ = 0;
};

class GuardedHttpServer : public httplib::Server {
  public:
    explicit GuardedHttpServer(const ExploreConnectionLimits& limits);

    // Threads of the connection pool: every admitted connection and a few more, which answer
    // the refusals and the accept loop's queue while the admitted ones are all slow.
    static int poolThreads(const ExploreConnectionLimits& limits) { return limits.total + 8; }
    // After bind: a listen backlog that holds a burst of connections (cpp-httplib listens with
    // 5, beyond which Linux drops a SYN and the client waits a second to send it again).
    void widenBacklog();
    ExploreConnectionStats stats() const;

  private:
    bool process_and_close_socket(socket_t sock) override;
    bool serve(socket_t sock, const std::string& address, int port);
    void refuse(socket_t sock);
    bool stopping() const { return svr_sock_ == INVALID_SOCKET; }

    ExploreConnectionLimits limits_;
    ConnectionAdmission admission_;
    std::atomic<uint64_t> refused_{0}, timedOut_{0};
};

}  // namespace quaternia
