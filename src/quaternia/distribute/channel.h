// How the ranks of a distributed job talk: binary messages, by tag, between numbered ranks
// (0 .. size() - 1). The work scheduler (work_scheduler.h) is written against this interface;
// the MPI channel (mpi_channel.h, only in quaternia-mpi) and the in-process channel (threads of
// one process, in_process_channel.h, for tests) implement it.
//
// Messages carry plain structs as bytes (MessageWriter, MessageReader): the ranks of one job run
// the same binary on machines of one architecture, as MPI jobs do.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace quaternia {

// How long a rank with nothing to do sleeps before it looks for a message again: a rank waiting
// for work or for a result leaves its core to the renders beside it.
inline constexpr std::chrono::microseconds kPollInterval{200};

// The messages of the work scheduler, by tag.
enum class MessageTag : int {
    Ready = 1,  // worker -> 0: free for work (the first time; a result says it after that)
    Result,     // worker -> 0: a unit or frame done, and free for the next
    Assign,     // 0 -> worker: the next unit or frame, or kNoMoreWork
    Summary,    // worker -> 0: what it did, after kNoMoreWork
    Lost,       // the channel -> 0: the source rank is gone; nothing more comes from it
};
inline constexpr int64_t kNoMoreWork = -1;

struct Message {
    int source = 0;
    MessageTag tag = MessageTag::Ready;
    std::vector<uint8_t> bytes;
};

class Channel {
  public:
    virtual ~Channel() = default;
    virtual int rank() const = 0;
    virtual int size() const = 0;
    virtual void send(int destination, MessageTag tag, const std::vector<uint8_t>& bytes) = 0;
    // The next message from any rank with any tag if one has arrived, else nothing; nothing too
    // if `cancel` is set while its bytes are still coming (their sender may have died). A
    // channel that can tell a rank has gone delivers a Lost message from it, after every
    // message that rank sent.
    virtual std::optional<Message> poll(const std::atomic<bool>* cancel) = 0;
    // Waits (without spinning) for a message from `source` with `tag`; nothing if `cancel` is
    // set first, or if this rank itself has been lost.
    virtual std::optional<Message> wait(int source, MessageTag tag,
                                        const std::atomic<bool>* cancel) = 0;
};

// Plain values appended as bytes, and read back in the same order.
class MessageWriter {
  public:
    template <class T>
    MessageWriter& put(const T& value) {
        static_assert(std::is_trivially_copyable_v<T>);
        const size_t at = bytes_.size();
        bytes_.resize(at + sizeof(T));
        std::memcpy(bytes_.data() + at, &value, sizeof(T));
        return *this;
    }
    MessageWriter& putBytes(const std::vector<uint8_t>& bytes) {
        put(uint64_t(bytes.size()));
        bytes_.insert(bytes_.end(), bytes.begin(), bytes.end());
        return *this;
    }
    const std::vector<uint8_t>& bytes() const { return bytes_; }

  private:
    std::vector<uint8_t> bytes_;
};

class MessageReader {
  public:
    explicit MessageReader(const std::vector<uint8_t>& bytes) : bytes_(bytes) {}
    template <class T>
    T get() {
        static_assert(std::is_trivially_copyable_v<T>);
        need(sizeof(T));
        T value;
        std::memcpy(&value, bytes_.data() + at_, sizeof(T));
        at_ += sizeof(T);
        return value;
    }
    std::vector<uint8_t> getBytes() {
        const auto size = get<uint64_t>();
        need(size);
        std::vector<uint8_t> out(bytes_.begin() + std::ptrdiff_t(at_),
                                 bytes_.begin() + std::ptrdiff_t(at_ + size));
        at_ += size;
        return out;
    }

  private:
    void need(size_t size) const {
        if (size > bytes_.size() - at_) throw std::runtime_error("truncated message between ranks");
    }
    const std::vector<uint8_t>& bytes_;
    size_t at_ = 0;
};

}  // namespace quaternia
