#include "quaternia/distribute/in_process_channel.h"

#include <stdexcept>
#include <string>

namespace quaternia {

InProcessNetwork::InProcessNetwork(int size) : mailboxes_(size_t(size)), lost_(size_t(size)) {
    if (size < 1) throw std::invalid_argument("a network has at least one rank");
    for (int rank = 0; rank < size; ++rank)
        channels_.push_back(std::make_unique<InProcessChannel>(*this, rank));
}

void InProcessNetwork::lose(int rank) {
    {
        std::lock_guard lock(mutex_);
        if (lost_.at(size_t(rank))) return;
        lost_[size_t(rank)] = true;
        mailboxes_[size_t(rank)].clear();
        // Behind everything the rank sent: a message it sent before dying still counts.
        if (rank != 0 && !lost_[0]) mailboxes_[0].push_back(Message{rank, MessageTag::Lost, {}});
    }
    arrived_.notify_all();
}

bool InProcessNetwork::isLost(int rank) const {
    std::lock_guard lock(mutex_);
    return lost_.at(size_t(rank));
}

void InProcessNetwork::deliver(int source, int destination, MessageTag tag,
                               const std::vector<uint8_t>& bytes) {
    if (destination < 0 || destination >= size())
        throw std::out_of_range("no rank " + std::to_string(destination));
    {
        std::lock_guard lock(mutex_);
        if (lost_[size_t(source)] || lost_[size_t(destination)]) return;  // the dead hear nothing
        mailboxes_[size_t(destination)].push_back(Message{source, tag, bytes});
    }
    arrived_.notify_all();
}

template <class Matches>
std::optional<Message> InProcessNetwork::take(int rank, Matches matches, bool block,
                                              const std::atomic<bool>* cancel) {
    std::unique_lock lock(mutex_);
    for (;;) {
        if (lost_[size_t(rank)]) return std::nullopt;
        std::deque<Message>& mailbox = mailboxes_[size_t(rank)];
        for (auto at = mailbox.begin(); at != mailbox.end(); ++at) {
            if (!matches(*at)) continue;
            Message message = std::move(*at);
            mailbox.erase(at);
            return message;
        }
        if (!block || (cancel != nullptr && cancel->load())) return std::nullopt;
        // The cancel flag is set without the mutex: look at it again every poll interval.
        arrived_.wait_for(lock, kPollInterval);
    }
}

int InProcessChannel::size() const {
    return network_.size();
}

void InProcessChannel::send(int destination, MessageTag tag, const std::vector<uint8_t>& bytes) {
    network_.deliver(rank_, destination, tag, bytes);
}

std::optional<Message> InProcessChannel::poll(const std::atomic<bool>* cancel) {
    return network_.take(
        rank_, [](const Message&) { return true; }, false, cancel);
}

std::optional<Message> InProcessChannel::wait(int source, MessageTag tag,
                                              const std::atomic<bool>* cancel) {
    return network_.take(
        rank_, [&](const Message& m) { return m.source == source && m.tag == tag; }, true, cancel);
}

}  // namespace quaternia
