#include "server/explore_connections.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>

#include "server/explore_request.h"

namespace quaternia {

bool ConnectionAdmission::enter(const std::string& address) {
    std::lock_guard lock(mutex_);
    int& mine = perAddress_[address];
    if (mine >= limits_.perAddress || total_ >= limits_.total) {
        if (mine == 0) perAddress_.erase(address);
        return false;
    }
    ++mine;
    ++total_;
    return true;
}

void ConnectionAdmission::leave(const std::string& address) {
    std::lock_guard lock(mutex_);
    auto it = perAddress_.find(address);
    if (it != perAddress_.end() && --it->second == 0) perAddress_.erase(it);
    --total_;
}

namespace {

using Clock = std::chrono::steady_clock;

// A request line (8 KiB at most in cpp-httplib) and its headers, whose count cpp-httplib does
// not bound: reading stops here, as at the deadline.
constexpr std::size_t kMaxRequestBytes = 64 * 1024;

Clock::duration seconds(double s) {
    return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
}

// "1.2.3.4" or "::1" of a socket address; "" for another family.
std::string addressText(const sockaddr_storage& address, int& port) {
    char text[INET6_ADDRSTRLEN] = "";
    port = 0;
    if (address.ss_family == AF_INET) {
        const auto& a = reinterpret_cast<const sockaddr_in&>(address);
        ::inet_ntop(AF_INET, &a.sin_addr, text, sizeof text);
        port = ntohs(a.sin_port);
    } else if (address.ss_family == AF_INET6) {
        const auto& a = reinterpret_cast<const sockaddr_in6&>(address);
        ::inet_ntop(AF_INET6, &a.sin6_addr, text, sizeof text);
        port = ntohs(a.sin6_port);
    }
    return text;
}

std::string peerAddress(socket_t sock, int& port) {
    sockaddr_storage address{};
    socklen_t length = sizeof address;
    if (::getpeername(sock, reinterpret_cast<sockaddr*>(&address), &length) != 0) return "";
    return addressText(address, port);
}

// A connection's socket as cpp-httplib's Stream, whose reads fail past the current request's
// deadline or byte budget (the time-outs per read and write still apply), and which gives up
// soon after the server stops.
class DeadlineStream final : public httplib::Stream {
  public:
    struct Timeouts {
        Clock::duration read, write;
    };
    DeadlineStream(socket_t sock, std::string address, int port, Timeouts timeouts,
                   const std::atomic<socket_t>& listening)
        : sock_(sock),
          address_(std::move(address)),
          port_(port),
          timeouts_(timeouts),
          listening_(listening) {}

    // Waits up to `idle` for the first byte of the next request; false when none came, the
    // client closed, or the server stops.
    bool awaitRequest(Clock::duration idle) {
        return next_ < end_ || wait(POLLIN, Clock::now() + idle) > 0;
    }
    void startRequest(Clock::time_point deadline) {
        deadline_ = deadline;
        requestBytes_ = 0;
    }
    bool missedDeadline() const { return missedDeadline_; }
    bool overBudget() const { return requestBytes_ >= kMaxRequestBytes; }

    bool is_readable() const override {
        return next_ < end_ || wait(POLLIN, std::min(deadline_, Clock::now() + timeouts_.read)) > 0;
    }
    bool is_writable() const override { return wait(POLLOUT, Clock::now() + timeouts_.write) > 0; }

    ssize_t read(char* ptr, size_t size) override {
        if (requestBytes_ >= kMaxRequestBytes) return -1;
        if (next_ == end_) {
            if (!is_readable()) {
                missedDeadline_ = missedDeadline_ || Clock::now() >= deadline_;
                return -1;
            }
            ssize_t n = recvSome(buffer_, sizeof buffer_);
            if (n <= 0) return n;
            next_ = 0;
            end_ = std::size_t(n);
        }
        std::size_t n = std::min({size, end_ - next_, kMaxRequestBytes - requestBytes_});
        std::memcpy(ptr, buffer_ + next_, n);
        next_ += n;
        requestBytes_ += n;
        return ssize_t(n);
    }
    ssize_t write(const char* ptr, size_t size) override {
        if (!is_writable()) return -1;
        ssize_t n;
        do {
            n = ::send(sock_, ptr, size, MSG_NOSIGNAL);
        } while (n < 0 && errno == EINTR);
        return n;
    }
    void get_remote_ip_and_port(std::string& ip, int& port) const override {
        ip = address_;
        port = port_;
    }
    void get_local_ip_and_port(std::string& ip, int& port) const override {
        sockaddr_storage address{};
        socklen_t length = sizeof address;
        port = 0;
        ip.clear();
        if (::getsockname(sock_, reinterpret_cast<sockaddr*>(&address), &length) == 0)
            ip = addressText(address, port);
    }
    socket_t socket() const override { return sock_; }

  private:
    // poll() in short slices until `until`, so that a stopping server is noticed: 1 when ready,
    // 0 at `until` or when the server stops, -1 on an error.
    int wait(short events, Clock::time_point until) const {
        for (;;) {
            if (listening_ == INVALID_SOCKET) return 0;
            // Rounded up, so that a 0 returned for `until` means it has passed.
            auto left = std::chrono::ceil<std::chrono::milliseconds>(until - Clock::now());
            if (left.count() <= 0) return 0;
            pollfd p{sock_, events, 0};
            int r = ::poll(&p, 1, int(std::min<int64_t>(left.count(), 100)));
            if (r > 0) return 1;
            if (r < 0 && errno != EINTR) return -1;
        }
    }
    ssize_t recvSome(char* ptr, std::size_t size) {
        ssize_t n;
        do {
            n = ::recv(sock_, ptr, size, 0);
        } while (n < 0 && errno == EINTR);
        return n;
    }

    socket_t sock_;
    std::string address_;
    int port_;
    Timeouts timeouts_;
    const std::atomic<socket_t>& listening_;
    Clock::time_point deadline_ = Clock::time_point::max();
    std::size_t requestBytes_ = 0;
    bool missedDeadline_ = false;
    char buffer_[4096];
    std::size_t next_ = 0, end_ = 0;
};

Clock::duration timeout(time_t sec, time_t usec) {
    return std::chrono::seconds(sec) + std::chrono::microseconds(usec);
}

}  // namespace

GuardedHttpServer::GuardedHttpServer(const ExploreConnectionLimits& limits)
    : limits_(limits), admission_(limits) {
    int threads = poolThreads(limits);
    // Only the answers' Keep-Alive header reads these; serve() keeps to the limits themselves.
    set_keep_alive_timeout(time_t(std::ceil(limits.idleSeconds)));
    set_keep_alive_max_count(std::size_t(limits.requestsPerConnection));
    new_task_queue = [threads] { return new httplib::ThreadPool(std::size_t(threads)); };
}

void GuardedHttpServer::widenBacklog() {
    // Linux lets listen() change the backlog of a socket already listening.
    if (svr_sock_ != INVALID_SOCKET) ::listen(svr_sock_, SOMAXCONN);
}

ExploreConnectionStats GuardedHttpServer::stats() const {
    return {refused_.load(), timedOut_.load()};
}

bool GuardedHttpServer::process_and_close_socket(socket_t sock) {
    int port = 0;
    std::string address = peerAddress(sock, port);
    bool served = false;
    if (address.empty()) {
        // The client has gone already: nothing to serve.
    } else if (admission_.enter(address)) {
        served = serve(sock, address, port);
        admission_.leave(address);
    } else {
        refuse(sock);
    }
    ::shutdown(sock, SHUT_RDWR);
    ::close(sock);
    return served;
}

// cpp-httplib's own connection loop (detail::process_server_socket), with the deadline of each
// request starting at its first byte.
bool GuardedHttpServer::serve(socket_t sock, const std::string& address, int port) {
    DeadlineStream stream(sock, address, port,
                          {timeout(read_timeout_sec_, read_timeout_usec_),
                           timeout(write_timeout_sec_, write_timeout_usec_)},
                          svr_sock_);
    bool ok = false;
    for (int left = limits_.requestsPerConnection; left > 0 && !stopping(); --left) {
        if (!stream.awaitRequest(seconds(limits_.idleSeconds))) break;
        stream.startRequest(Clock::now() + seconds(limits_.requestSeconds));
        bool closed = false, parsed = false, bodyUnread = false;
        ok = process_request(stream, left == 1, closed, [&](httplib::Request& request) {
            parsed = true;  // called only for a request line and header that parse
            // A body is never read (explore_server.cpp answers 405 before it): what follows
            // the header cannot be the next request, so the connection ends with this one.
            if (request.method != "GET" && request.method != "HEAD") {
                bodyUnread = true;
                request.headers.erase("Connection");
                request.set_header("Connection", "close");
            }
        });
        if (stream.missedDeadline()) {
            ++timedOut_;
            break;
        }
        // After a request that did not parse, what follows is no request either.
        if (!ok || closed || !parsed || bodyUnread || stream.overBudget()) break;
    }
    return ok;
}

// A short 503 sent without waiting, then the caller closes the connection.
void GuardedHttpServer::refuse(socket_t sock) {
    ++refused_;
    static const std::string answer = [] {
        std::string body = errorJson("", "too many connections; try again later");
        return "HTTP/1.1 503 Service Unavailable\r\nContent-Type: application/json\r\n"
               "Content-Length: " +
               std::to_string(body.size()) + "\r\nConnection: close\r\nRetry-After: 1\r\n\r\n" +
               body;
    }();
    (void)!::send(sock, answer.data(), answer.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
    // What the client has sent is read, so that closing does not reset the connection (which
    // could discard the 503 before the client reads it).
    ::shutdown(sock, SHUT_WR);
    char discard[4096];
    while (::recv(sock, discard, sizeof discard, MSG_DONTWAIT) > 0) {
    }
}

}  // namespace quaternia
