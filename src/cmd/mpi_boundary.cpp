#include "cmd/mpi_boundary.h"

#include <cstdio>
#include <exception>
#include <string>

#include "quaternia/util/error.h"

namespace quaternia {

std::optional<int> parseOnEveryRank(const MpiSession& mpi, CLI::App& app, int argc, char** argv) {
    int code = -1;
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (mpi.rank() != 0) {
            code = e.get_exit_code() == 0 ? 0 : 2;
        } else if (e.get_exit_code() == 0) {
            code = app.exit(e);  // --help, --version
        } else {
            std::fprintf(stderr, "quaternia: error: %s (see quaternia-mpi --help)\n", e.what());
            code = 2;
        }
    }
    if (code < 0) return std::nullopt;
    return code;
}

int setUpOnEveryRank(const MpiSession& mpi, const std::function<void()>& setUp) {
    int status = 0;
    std::string message;
    try {
        setUp();
    } catch (const UserError& e) {
        status = 2;
        message = std::string("quaternia: error: ") + e.what();
    } catch (const std::exception& e) {
        status = 1;
        message = std::string("quaternia: internal error: ") + e.what();
    }
    const int rankZeroStatus = mpi.broadcastFromRankZero(status);
    const int agreed = mpi.agree(status);
    if (status != 0 && (mpi.rank() == 0 || rankZeroStatus == 0)) {
        if (mpi.rank() == 0) {
            std::fprintf(stderr, "%s\n", message.c_str());
        } else {
            std::fprintf(stderr, "%s (rank %d)\n", message.c_str(), mpi.rank());
        }
    }
    return agreed;
}

int runOrAbort(const MpiSession& mpi, const std::function<int()>& work) {
    int code = 0;
    try {
        code = work();
    } catch (const UserError& e) {
        std::fprintf(stderr, "quaternia: error: %s\n", e.what());
        code = 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "quaternia: internal error: %s\n", e.what());
        code = 1;
    }
    if (code != 0) {
        std::fflush(stderr);
        mpi.abort(code);
    }
    return 0;
}

}  // namespace quaternia
