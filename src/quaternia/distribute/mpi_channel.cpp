#include "quaternia/distribute/mpi_channel.h"

#include <mpi.h>

#include <climits>
#include <cstdlib>
#include <stdexcept>
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

int MpiSession::broadcastFromRankZero(int value) const {
    MPI_Bcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD);
    return value;
}

void MpiSession::broadcastFromRankZero(std::vector<int64_t>& values) const {
    uint64_t count = values.size();
    MPI_Bcast(&count, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
    values.resize(count);
    if (count > 0) MPI_Bcast(values.data(), int(count), MPI_INT64_T, 0, MPI_COMM_WORLD);
}

void MpiSession::abort(int code) const {
    MPI_Abort(MPI_COMM_WORLD, code);
    std::abort();  // MPI_Abort does not return; this tells the compiler so
}

void MpiChannel::send(int destination, MessageTag tag, const std::vector<uint8_t>& bytes) {
    if (bytes.size() > size_t(INT_MAX)) throw std::length_error("MPI message over 2 GiB");
    MPI_Send(bytes.data(), int(bytes.size()), MPI_BYTE, destination, int(tag), MPI_COMM_WORLD);
}

namespace {

// The message's envelope may arrive before its bytes (a large one goes by rendezvous), and a
// sender killed in between never sends them: a blocking MPI_Recv would then wait for ever, deaf to
// the interruption that ends the job (mpirun's SIGTERM), until mpirun's SIGKILL ended the rank
// before it removed its outputs' temporaries (Mpi.KilledRankLeavesNoPng, one run in a few).
// So the bytes are received by polling, and an interruption gives up on them.
std::optional<Message> receiveIfReady(int source, int tag, const std::atomic<bool>* cancel) {
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
    MPI_Request request;
    MPI_Irecv(message.bytes.data(), count, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG,
              MPI_COMM_WORLD, &request);
    for (;;) {
        int received = 0;
        MPI_Test(&request, &received, MPI_STATUS_IGNORE);
        if (received) return message;
        if (cancel != nullptr && cancel->load()) return std::nullopt;  // the job is ending
        std::this_thread::yield();  // MPI_Test moves the transfer on: no sleeping in it
    }
}

}  // namespace

std::optional<Message> MpiChannel::poll(const std::atomic<bool>* cancel) {
    return receiveIfReady(MPI_ANY_SOURCE, MPI_ANY_TAG, cancel);
}

std::optional<Message> MpiChannel::wait(int source, MessageTag tag,
                                        const std::atomic<bool>* cancel) {
    for (;;) {
        if (auto message = receiveIfReady(source, int(tag), cancel)) return message;
        if (cancel != nullptr && cancel->load()) return std::nullopt;
        std::this_thread::sleep_for(kPollInterval);
    }
}

}  // namespace quaternia
