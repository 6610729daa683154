// The ranks of a job as threads of one process: each rank's mailbox is a queue that the others
// append to, in the order sent. It runs the work scheduler without MPI (its tests), and can
// simulate what MPI cannot survive: a rank that dies in the middle of its work (lose()).
#pragma once

#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <vector>

#include "quaternia/distribute/channel.h"

namespace quaternia {

class InProcessNetwork;

// One rank's end of an InProcessNetwork; each is used from one thread at a time.
class InProcessChannel : public Channel {
  public:
    InProcessChannel(InProcessNetwork& network, int rank) : network_(network), rank_(rank) {}
    int rank() const override { return rank_; }
    int size() const override;
    void send(int destination, MessageTag tag, const std::vector<uint8_t>& bytes) override;
    std::optional<Message> poll(const std::atomic<bool>* cancel) override;
    std::optional<Message> wait(int source, MessageTag tag,
                                const std::atomic<bool>* cancel) override;

  private:
    InProcessNetwork& network_;
    int rank_;
};

class InProcessNetwork {
  public:
    explicit InProcessNetwork(int size);
    int size() const { return int(channels_.size()); }
    Channel& channel(int rank) { return *channels_.at(size_t(rank)); }

    // Rank `rank` dies now: what it sends from now on is dropped, what is sent to it too, its
    // polls and waits return nothing, and rank 0 gets a Lost message from it after every message
    // it sent before.
    void lose(int rank);
    bool isLost(int rank) const;

  private:
    friend class InProcessChannel;
    void deliver(int source, int destination, MessageTag tag, const std::vector<uint8_t>& bytes);
    // The first message of `rank`'s mailbox that `matches`; nothing when there is none and
    // `block` is false, else waits for one until `cancel` is set or the rank is lost.
    template <class Matches>
    std::optional<Message> take(int rank, Matches matches, bool block,
                                const std::atomic<bool>* cancel);

    mutable std::mutex mutex_;
    std::condition_variable arrived_;
    std::vector<std::deque<Message>> mailboxes_;  // by rank
    std::vector<bool> lost_;                      // by rank
    std::vector<std::unique_ptr<InProcessChannel>> channels_;
};

}  // namespace quaternia
