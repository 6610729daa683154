// `quaternia explore` as a user meets it: a port in use or an address not of this machine is
// one line and exit code 2 (not a server that never starts), bad limits are refused by the
// parser, and the connection limits given reach the server (quaternia-explore, into which
// quaternia turns).
#include <arpa/inet.h>
#include <netinet/in.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "cmd/cli_fixture.h"

extern char** environ;

namespace quaternia {
namespace {

using testing::CommandResult;

class ExploreCli : public testing::CliFixture {
  protected:
    // `quaternia explore ARGUMENTS` as run() runs a command, but stopped by `timeout` (exit
    // code 124) should it serve after all.
    CommandResult explore(const std::string& arguments) {
        std::string command = "timeout 20 " + std::string(QUATERNIA_BINARY) + " explore " +
                              arguments + " >" + (dir_ / "stdout").string() + " 2>" +
                              (dir_ / "stderr").string() + " </dev/null";
        int status = std::system(command.c_str());
        return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, testing::readFile(dir_ / "stdout"),
                testing::readFile(dir_ / "stderr")};
    }
};

// A socket listening on a free loopback port, closed at the end of the test.
struct Listener {
    int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    int port = 0;
    Listener() {
        sockaddr_in address{};
        address.sin_family = AF_INET;
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        socklen_t length = sizeof address;
        if (::bind(fd, reinterpret_cast<sockaddr*>(&address), length) == 0 &&
            ::listen(fd, 1) == 0 &&
            ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length) == 0)
            port = ntohs(address.sin_port);
    }
    ~Listener() { ::close(fd); }
};

TEST_F(ExploreCli, APortInUseIsOneLineAndExitCode2) {
    Listener taken;
    ASSERT_GT(taken.port, 0);
    const std::string port = std::to_string(taken.port);
    CommandResult r = explore("--port " + port);
    expectUserError(r, "cannot listen on 127.0.0.1 port " + port);
    EXPECT_TRUE(r.out.empty()) << r.out;
}

TEST_F(ExploreCli, AnAddressNotOfThisMachineIsOneLineAndExitCode2) {
    // 192.0.2.1 is TEST-NET-1 (RFC 5737): never an address of this machine.
    CommandResult r = explore("--port 0 --bind 192.0.2.1");
    expectUserError(r, "cannot listen on 192.0.2.1 port 0");
    EXPECT_TRUE(r.out.empty()) << r.out;
}

TEST_F(ExploreCli, LimitsOutOfRangeAreRefused) {
    expectUserError(explore("--port 0 --connections 0"), "--connections");
    expectUserError(explore("--port 0 --connections-per-address 5000"),
                    "--connections-per-address");
    expectUserError(explore("--port 0 --request-timeout 0"), "--request-timeout");
}

// `quaternia explore ARGUMENTS` running, with the port it printed; stopped at the end.
class RunningExplorer {
  public:
    explicit RunningExplorer(const std::vector<std::string>& arguments) {
        int out[2];
        if (::pipe(out) != 0) return;
        std::vector<std::string> all = {QUATERNIA_BINARY, "explore"};
        all.insert(all.end(), arguments.begin(), arguments.end());
        std::vector<char*> argv;
        for (std::string& argument : all)
            argv.push_back(argument.data());
        argv.push_back(nullptr);
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
        posix_spawn_file_actions_addclose(&actions, out[0]);
        if (posix_spawn(&pid_, argv[0], &actions, nullptr, argv.data(), environ) != 0) pid_ = -1;
        posix_spawn_file_actions_destroy(&actions);
        ::close(out[1]);
        output_ = ::fdopen(out[0], "r");
        char line[256];
        if (pid_ > 0 && std::fgets(line, sizeof line, output_)) {
            std::string text = line;
            auto colon = text.rfind(':');
            if (colon != std::string::npos) port_ = std::atoi(text.c_str() + colon + 1);
        }
    }
    ~RunningExplorer() {
        if (pid_ > 0) {
            ::kill(pid_, SIGTERM);
            int status;
            ::waitpid(pid_, &status, 0);
        }
        if (output_) std::fclose(output_);
    }
    int port() const { return port_; }

  private:
    pid_t pid_ = -1;
    FILE* output_ = nullptr;
    int port_ = 0;
};

// A raw connection with half a request header sent; -1 when it fails.
int halfRequest(int port) {
    int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(uint16_t(port));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    timeval timeout{5, 0};
    ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
    const std::string half = "GET / HTTP/1.1\r\nHost: q\r\n";
    if (::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 ||
        ::send(fd, half.data(), half.size(), MSG_NOSIGNAL) != ssize_t(half.size())) {
        ::close(fd);
        return -1;
    }
    return fd;
}

// Reads until the server closes the connection (or 5 s pass).
std::string readAll(int fd) {
    std::string reply;
    char buffer[4096];
    for (ssize_t n; (n = ::recv(fd, buffer, sizeof buffer, 0)) > 0;)
        reply.append(buffer, std::size_t(n));
    return reply;
}

TEST_F(ExploreCli, TheConnectionLimitsReachTheServer) {
    RunningExplorer server({"--port", "0", "--connections", "1", "--request-timeout", "0.3"});
    ASSERT_GT(server.port(), 0) << "the server did not print its URL";
    auto start = std::chrono::steady_clock::now();
    int held = halfRequest(server.port());
    ASSERT_GE(held, 0);
    ::usleep(100 * 1000);  // admitted
    int refused = halfRequest(server.port());
    ASSERT_GE(refused, 0);
    std::string refusal = readAll(refused);
    ::close(refused);
    EXPECT_EQ(refusal.rfind("HTTP/1.1 503 ", 0), 0u) << "--connections 1: " << refusal;
    std::string cut = readAll(held);
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ::close(held);
    EXPECT_EQ(cut.rfind("HTTP/1.1 400 ", 0), 0u) << cut;
    EXPECT_GT(seconds, 0.25);
    EXPECT_LT(seconds, 2) << "--request-timeout 0.3";
}

}  // namespace
}  // namespace quaternia
