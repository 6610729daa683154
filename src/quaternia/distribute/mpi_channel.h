// The few MPI calls quaternia-mpi makes, in one place: the session and its collectives, and the
// channel of binary messages (channel.h) over MPI. Compiled into quaternia-mpi alone, where MPI
// is installed; the rest of the library never needs it.
//
// OpenMPI's blocking receive polls on a core while it waits; here a rank sleeps between probes
// (kPollInterval), so that a rank waiting for work or for a result leaves the core to the
// renders beside it. The channel never reports a rank Lost: a rank that dies ends the whole job
// (MPI does that), and rank 0 takes the SIGTERM that follows like Ctrl-C.
#pragma once

#include <atomic>
#include <cstdint>
#include <optional>
#include <vector>

#include "quaternia/distribute/channel.h"

namespace quaternia {

// MPI_Init_thread (funnelled: only the main thread calls MPI) and MPI_Finalize.
class MpiSession {
  public:
    MpiSession(int& argc, char**& argv);
    ~MpiSession();
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;
    int rank() const { return rank_; }
    int size() const { return size_; }
    // Every rank's `status` agreed: the largest (collective: every rank calls it).
    int agree(int status) const;
    // Rank 0's `value` on every rank (collective).
    int broadcastFromRankZero(int value) const;
    // Rank 0's `values` on every rank, resized to rank 0's size (collective).
    void broadcastFromRankZero(std::vector<int64_t>& values) const;
    // Ends the whole job now (MPI_Abort) with `code`.
    [[noreturn]] void abort(int code) const;

  private:
    int rank_ = 0, size_ = 1;
};

// Point-to-point messages between the session's ranks (MPI_COMM_WORLD). Main thread only.
class MpiChannel : public Channel {
  public:
    explicit MpiChannel(const MpiSession& session) : rank_(session.rank()), size_(session.size()) {}
    int rank() const override { return rank_; }
    int size() const override { return size_; }
    void send(int destination, MessageTag tag, const std::vector<uint8_t>& bytes) override;
    std::optional<Message> poll(const std::atomic<bool>* cancel) override;
    std::optional<Message> wait(int source, MessageTag tag,
                                const std::atomic<bool>* cancel) override;

  private:
    int rank_, size_;
};

}  // namespace quaternia
