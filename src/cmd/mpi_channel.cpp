#include "cmd/mpi_channel.h"

#include <mpi.h>

#include <climits>
#include <thread>

namespace quaternia {

MpiSession::MpiSession(int& argc, char**& argv) {
    int provided = 0;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() {
    MPI_Finalize();
}

int MpiSession::agree(int status) const {
    int agreed = status;
    MPI_Allreduce(&status, &agreed, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    return agreed;
}

void MpiSession::abort(int code) const {
    MPI_Abort(MPI_COMM_WORLD, code);
    std::abort();  // MPI_Abort does not return; this tells the compiler so
}

void sendMessage(int destination, MessageTag tag, const std::vector<uint8_t>& bytes) {
    if (bytes.size() > size_t(INT_MAX)) throw std::length_error("MPI message over 2 GiB");
    MPI_Send(bytes.data(), int(bytes.size()), MPI_BYTE, destination, int(tag), MPI_COMM_WORLD);
}

namespace {

std::optional<Message> receiveIfReady(int source, int tag) {
    int ready = 0;
    MPI_Status status;
    MPI_Iprobe(source, tag, MPI_COMM_WORLD, &ready, &status);
    if (!ready) return std::nullopt;
    int count = 0;
    MPI_Get_count(&status, MPI_BYTE, &count);
    Message message;
    message.source = status.MPI_SOURCE;
    message.tag = MessageTag(status.MPI_TAG);
    message.bytes.resize(size_t(count));
    MPI_Recv(message.bytes.data(), count, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG,
             MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    return message;
}

}  // namespace

std::optional<Message> pollMessage() {
    return receiveIfReady(MPI_ANY_SOURCE, MPI_ANY_TAG);
}

std::optional<Message> waitMessage(int source, MessageTag tag, const std::atomic<bool>* cancel) {
    for (;;) {
        if (auto message = receiveIfReady(source, int(tag))) return message;
        if (cancel != nullptr && cancel->load()) return std::nullopt;
        std::this_thread::sleep_for(kPollInterval);
    }
}

}  // namespace quaternia
